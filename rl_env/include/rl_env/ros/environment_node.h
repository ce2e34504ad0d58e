/**
 * EnvironmentNode: serves an rl_common::Environment over the original rl_msgs protocol
 * (shared/spec/ORIGINAL.md §2.2-2.3), so an original agent node or ours can drive it.
 *
 * Topics (relative, so `/rl_env/...` and `/rl_agent/...` without a namespace):
 *   publishes  rl_env/rl_env_description (latched), rl_env/rl_seed, rl_env/rl_state_reward
 *   subscribes rl_agent/rl_action, rl_agent/rl_experiment_info
 *   service    rl_env/reset (rl_msgs/Reset, new): reseed if asked, reset, publish the start
 *   publishes  rl_env/image (sensor_msgs/Image, rgb8, new; only with `render` and a Renderable
 *              environment): the environment drawn after every state it publishes, naming the
 *              action that led there; drawn only while someone subscribes, and once for
 *              each new subscriber (the current state)
 *
 * Beyond the original: the description is latched and re-sent to every new subscriber; the
 * seed experiences are sent to every new subscriber of rl_seed (from a queue that holds them
 * all); the first state is published only once an agent listens on rl_state_reward and
 * rl_seed, and the state topic is latched so a late agent gets the current state. A bad action
 * or message is logged and dropped; the node keeps serving.
 */
#pragma once

#include <rl_msgs/RLAction.h>
#include <rl_msgs/RLEnvDescription.h>
#include <rl_msgs/RLEnvSeedExperience.h>
#include <rl_msgs/RLExperimentInfo.h>
#include <rl_msgs/RLStateReward.h>
#include <rl_msgs/Reset.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>

#include <functional>
#include <memory>

#include "rl_common/environment.h"
#include "rl_common/rate_limited_log.h"
#include "rl_env/render/rgb_image.h"

namespace rl_env {

/// Converts to the original messages.
rl_msgs::RLEnvDescription toMessage(const rl_common::EnvironmentDescription& d);
rl_msgs::RLEnvSeedExperience toMessage(const rl_common::Experience& e);
/// An image as sensor_msgs/Image, encoding rgb8.
sensor_msgs::Image toMessage(const RgbImage& image);

class EnvironmentNode {
 public:
  /// Builds a fresh environment from a seed (used at start and by the reset service).
  using Factory = std::function<std::unique_ptr<rl_common::Environment>(std::uint64_t seed)>;

  /// `nh` resolves the topics; `seed` is the seed of the first environment. With `render`
  /// the environment must be Renderable (throws std::invalid_argument otherwise).
  EnvironmentNode(ros::NodeHandle nh, Factory factory, std::uint64_t seed, bool prints,
                  bool render = false);

  /// Publishes the first state once an agent listens (call from a timer or the spin loop).
  void publishFirstStateWhenReady();

  void onAction(const rl_msgs::RLAction::ConstPtr& msg);
  void onExperimentInfo(const rl_msgs::RLExperimentInfo::ConstPtr& msg);
  bool onReset(rl_msgs::Reset::Request& req, rl_msgs::Reset::Response& res);

  long steps() const { return steps_; }

 private:
  void publishState(float reward);
  void publishImage();
  sensor_msgs::Image imageMessage();
  void sendSeeds(const ros::SingleSubscriberPublisher& pub);

  ros::NodeHandle nh_;
  Factory factory_;
  std::unique_ptr<rl_common::Environment> env_;
  bool prints_;
  bool render_;
  int lastAction_ = -1;  // the action that led to the current state (-1 after a reset)
  std::uint32_t imageSeq_ = 0;
  bool firstStateSent_ = false;
  bool seedsSent_ = false;    // the connect callback has sent the seeds to an agent
  ros::WallTime readySince_;  // since when a client hears states and publishes actions
  long steps_ = 0;
  ros::Publisher descriptionPub_, seedPub_, statePub_, imagePub_;
  ros::Subscriber actionSub_, infoSub_;
  ros::ServiceServer resetSrv_;
  ros::WallTimer readyTimer_;
  /// Malformed actions: one warning each, at most 10 a second (a burst is counted, not logged).
  rl_common::RateLimitedLog dropLog_;
};

}  // namespace rl_env
