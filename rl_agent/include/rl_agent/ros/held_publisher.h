/**
 * HeldPublisher: a publisher whose latest message answers one node (the sender of the state
 * it responds to) and is not lost when that node is not connected yet.
 *
 * A message published before the environment is connected is lost, and the pair then waits on
 * each other for good: an agent restarted beside a running env acts on its latched state at
 * once, and ends an episode as soon as the env's reply is terminal, while the env's
 * subscriptions to the agent's topics come up one by one; an observer connected first (rosbag,
 * a test) does not make the env hear it. Such a message is held for the node it answers and
 * sent to it alone when it connects. roscpp opens a connection (which hears every publish)
 * before it runs the connection's callback, so the callbacks still pending when a message goes
 * out are counted: those connections heard it, and get no second copy.
 *
 * All calls on the node's callback thread (the connection callbacks run there too).
 */
#pragma once

#include <ros/ros.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <set>
#include <string>

namespace rl_agent {

template <class Msg>
class HeldPublisher {
 public:
  /// Advertises `topic`; `what` names the message in the log ("action", "episode end").
  void advertise(ros::NodeHandle& nh, const std::string& topic, std::uint32_t queue,
                 std::string what) {
    what_ = std::move(what);
    pub_ = nh.advertise<Msg>(
        topic, queue, [this](const ros::SingleSubscriberPublisher& p) { onConnect(p); },
        [this](const ros::SingleSubscriberPublisher& p) {
          subscribers_.erase(p.getSubscriberName());
        });
  }

  /// Publishes `m` to everyone connected; if `answering` (may be empty: nobody in particular)
  /// is not connected yet, holds `m` for it, replacing any message held before. Returns true
  /// if it holds `m`.
  bool publish(const Msg& m, const std::string& answering) {
    // Counted before the publish: a connection counted here certainly hears it.
    const int connections = static_cast<int>(pub_.getNumSubscribers());
    unannounced_ = std::max(0, connections - static_cast<int>(subscribers_.size()));
    pub_.publish(m);
    held_.reset();
    if (answering.empty() || subscribers_.count(answering) > 0) return false;
    held_ = m;
    heldFor_ = answering;
    return true;
  }

 private:
  void onConnect(const ros::SingleSubscriberPublisher& p) {
    const std::string name = p.getSubscriberName();
    subscribers_.insert(name);
    const bool heardIt = unannounced_ > 0;
    if (heardIt) --unannounced_;
    if (!held_ || name != heldFor_) return;
    if (!heardIt) {
      p.publish(*held_);
      ROS_INFO_STREAM_NAMED("agent", "sent the held " << what_ << " to " << name);
    }
    held_.reset();
  }

  ros::Publisher pub_;
  std::string what_;
  /// The subscribers whose connection callback has run, and how many of the connections open
  /// when the last message went out had not run theirs yet (those heard it).
  std::set<std::string> subscribers_;
  int unannounced_ = 0;
  std::optional<Msg> held_;
  std::string heldFor_;
};

}  // namespace rl_agent
