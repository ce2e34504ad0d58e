#include "rl_env/ros/environment_node.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "rl_env/render/renderable.h"

namespace rl_env {

rl_msgs::RLEnvDescription toMessage(const rl_common::EnvironmentDescription& d) {
  rl_msgs::RLEnvDescription m;
  m.num_actions = static_cast<float>(d.numActions);
  m.num_states = static_cast<float>(d.numFeatures());
  m.min_state_range = d.minFeatures;
  m.max_state_range = d.maxFeatures;
  m.max_reward = d.maxReward;
  m.reward_range = d.rewardRange();
  m.stochastic = d.stochastic;
  m.episodic = d.episodic;
  m.title = d.title;
  return m;
}

rl_msgs::RLEnvSeedExperience toMessage(const rl_common::Experience& e) {
  rl_msgs::RLEnvSeedExperience m;
  m.from_state = e.s;
  m.action = e.action;
  m.to_state = e.next;
  m.reward = e.reward;
  m.terminal = e.terminal;
  return m;
}

sensor_msgs::Image toMessage(const RgbImage& image) {
  sensor_msgs::Image m;
  m.height = static_cast<uint32_t>(image.height());
  m.width = static_cast<uint32_t>(image.width());
  m.encoding = "rgb8";
  m.is_bigendian = 0;
  m.step = static_cast<uint32_t>(image.rowBytes());
  m.data = image.bytes();
  return m;
}

EnvironmentNode::EnvironmentNode(ros::NodeHandle nh, Factory factory, std::uint64_t seed,
                                 bool prints, bool render)
    : nh_(nh),
      factory_(std::move(factory)),
      env_(factory_(seed)),
      prints_(prints),
      render_(render) {
  if (render_ && dynamic_cast<const Renderable*>(env_.get()) == nullptr) {
    throw std::invalid_argument("render: " + env_->name() + " has no rendered view");
  }
  const auto description = toMessage(env_->describe());
  const std::size_t nseeds = env_->seedExperiences().size();
  descriptionPub_ = nh_.advertise<rl_msgs::RLEnvDescription>("rl_env/rl_env_description", 1,
                                                             /*latch=*/true);
  // Every new subscriber gets all seeds, from a queue large enough to hold them.
  seedPub_ = nh_.advertise<rl_msgs::RLEnvSeedExperience>(
      "rl_env/rl_seed", static_cast<uint32_t>(std::max<std::size_t>(20, nseeds + 1)),
      [this](const ros::SingleSubscriberPublisher& pub) { sendSeeds(pub); },
      ros::SubscriberStatusCallback(), ros::VoidConstPtr(), /*latch=*/false);
  statePub_ = nh_.advertise<rl_msgs::RLStateReward>("rl_env/rl_state_reward", 1, /*latch=*/true);
  const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
  // Deeper than the original's 1: a second publisher's action must not push the agent's out
  // (a lost action stalls the pair, which waits on each other).
  constexpr uint32_t kQueue = 10;
  actionSub_ = nh_.subscribe("rl_agent/rl_action", kQueue, &EnvironmentNode::onAction, this, hints);
  infoSub_ = nh_.subscribe("rl_agent/rl_experiment_info", kQueue,
                           &EnvironmentNode::onExperimentInfo, this, hints);
  resetSrv_ = nh_.advertiseService("rl_env/reset", &EnvironmentNode::onReset, this);
  // A viewer that connects gets the current state drawn at once (and then every step).
  if (render_) {
    imagePub_ = nh_.advertise<sensor_msgs::Image>(
        "rl_env/image", 2,
        [this](const ros::SingleSubscriberPublisher& pub) { pub.publish(imageMessage()); });
  }
  descriptionPub_.publish(description);
  ROS_INFO_STREAM_NAMED(
      "env", "serving " << description.title.substr(0, description.title.size() - 1) << ": "
                        << description.num_states << " features, " << description.num_actions
                        << " actions, " << nseeds << " seed experiences; waiting for an agent");
  readyTimer_ = nh_.createWallTimer(ros::WallDuration(0.05), [this](const ros::WallTimerEvent&) {
    publishFirstStateWhenReady();
  });
}

void EnvironmentNode::sendSeeds(const ros::SingleSubscriberPublisher& pub) {
  const auto seeds = env_->seedExperiences();
  for (const auto& e : seeds) pub.publish(toMessage(e));
  seedsSent_ = true;
  ROS_INFO_STREAM_NAMED(
      "env", "sent " << seeds.size() << " seed experiences to " << pub.getSubscriberName());
}

void EnvironmentNode::publishFirstStateWhenReady() {
  if (firstStateSent_) return;
  // An agent can act once it hears states and its actions reach this node. Seeds are optional
  // in the protocol (an agent written to rl_msgs may not subscribe to them), but one that does
  // gets them first: its subscriptions come up together, so wait a moment for the others, and
  // then for the seeds to have been sent (roscpp counts a subscriber before it runs the connect
  // callback, queued on this node's spinner behind this timer).
  const ros::WallTime now = ros::WallTime::now();
  if (statePub_.getNumSubscribers() == 0 || actionSub_.getNumPublishers() == 0) {
    readySince_ = ros::WallTime();
    return;
  }
  if (readySince_.isZero()) readySince_ = now;
  if (now - readySince_ < ros::WallDuration(0.5)) return;
  if (seedPub_.getNumSubscribers() > 0 && !seedsSent_) return;
  firstStateSent_ = true;
  readyTimer_.stop();
  // Let the seeds sent on connection reach the agent before the first state.
  if (seedsSent_) ros::WallDuration(0.2).sleep();
  ROS_INFO_NAMED("env", "agent connected; publishing the first state");
  publishState(0.0f);
}

void EnvironmentNode::publishState(float reward) {
  rl_msgs::RLStateReward m;
  m.state = env_->sensation();
  m.reward = reward;
  m.terminal = env_->terminal();
  statePub_.publish(m);
  publishImage();
}

sensor_msgs::Image EnvironmentNode::imageMessage() {
  const auto& view = dynamic_cast<const Renderable&>(*env_);  // checked in the constructor
  sensor_msgs::Image m = toMessage(view.render(lastAction_));
  m.header.seq = imageSeq_++;
  m.header.stamp = ros::Time::now();
  m.header.frame_id = "rl_env";
  return m;
}

void EnvironmentNode::publishImage() {
  // Drawing costs more than a step of most environments: only for a listener.
  if (render_ && imagePub_.getNumSubscribers() > 0) imagePub_.publish(imageMessage());
}

void EnvironmentNode::onAction(const rl_msgs::RLAction::ConstPtr& msg) {
  const int a = msg->action;
  if (a < 0 || a >= env_->numActions()) {
    const std::string line = "dropping action " + std::to_string(a) + ": valid actions are 0.." +
                             std::to_string(env_->numActions() - 1);
    if (auto l = dropLog_.admit(line)) ROS_WARN_STREAM_NAMED("env", *l);
    return;
  }
  const float r = env_->apply(a);
  lastAction_ = a;
  ++steps_;
  if (prints_) {
    const auto& s = env_->sensation();
    ROS_INFO_STREAM_NAMED("env", "action " << a << " state " << (s.empty() ? 0.0f : s[0]) << ","
                                           << (s.size() > 1 ? s[1] : 0.0f) << " reward " << r);
  }
  publishState(r);
}

void EnvironmentNode::onExperimentInfo(const rl_msgs::RLExperimentInfo::ConstPtr& msg) {
  // The original treats any episode report as "reset".
  ROS_INFO_STREAM_NAMED("env", "episode " << msg->episode_number << " ended with reward "
                                          << msg->episode_reward << " after " << msg->number_actions
                                          << " actions; resetting");
  env_->reset();
  lastAction_ = -1;
  publishState(0.0f);
}

bool EnvironmentNode::onReset(rl_msgs::Reset::Request& req, rl_msgs::Reset::Response& res) {
  try {
    if (req.use_seed) {
      env_ = factory_(req.seed);
    } else {
      env_->reset();
    }
  } catch (const std::exception& e) {
    res.success = false;
    res.message = e.what();
    return true;
  }
  steps_ = 0;
  lastAction_ = -1;
  res.success = true;
  res.message = req.use_seed ? "reset with seed " + std::to_string(req.seed) : "reset";
  ROS_INFO_STREAM_NAMED("env", res.message);
  publishState(0.0f);
  return true;
}

}  // namespace rl_env
