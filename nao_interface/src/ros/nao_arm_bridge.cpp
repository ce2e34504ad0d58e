#include "nao_interface/ros/nao_arm_bridge.h"

#include <cv_bridge/cv_bridge.h>
#include <naoqi_bridge_msgs/FloatStamped.h>
#include <naoqi_bridge_msgs/JointAnglesWithSpeed.h>
#include <rl_msgs/RLEnvDescription.h>
#include <rl_msgs/RLEnvSeedExperience.h>
#include <rl_msgs/RLStateReward.h>
#include <sensor_msgs/image_encodings.h>

#include <algorithm>
#include <cmath>

#include "nao_interface/ros/nao_arm_markers.h"

namespace nao_interface {

namespace {
double wallNow() { return ros::WallTime::now().toSec(); }
}  // namespace

void addBridgeOptions(rl_common::OptionParser& parser, NaoArmBridgeOptions* o) {
  parser.choice("task", &o->task, naoArmTaskNames(),
                "reward: none (explore), pink pixels, +200 while the foot button is pressed, "
                "microphone energy");
  parser.value("rate", &o->rate, "actions per second", rl_common::greaterThan(0.0));
  parser.value("speed", &o->speed, "fraction of the joint velocity limit for commands",
               rl_common::inRange(0.001, 1.0));
  parser.value("max-age", &o->maxAge, "seconds after which sensor data is stale",
               rl_common::greaterThan(0.0));
  parser.value("reset-time", &o->resetTime, "seconds for the arm to return to the start pose",
               rl_common::greaterThan(0.0));
  parser.flag("no-audio", &o->needAudio, false, "do not wait for audio (NAOqi >= 2.9)");
  parser.value("driver-ns", &o->driverNs, "namespace of the driver's topics");
  parser.value("cymbal-threshold", &o->cymbal.threshold,
               "microphone energy above which a sound is a cymbal hit (rviz markers)",
               rl_common::atLeast(0.0));
  parser.value("urdf", &o->robot.urdf, "URDF of the seated Nao (for the hand position)");
  parser.value("start-pitch", &o->robot.startPitch, "RShoulderPitch of the start pose (rad)");
  parser.value("start-roll", &o->robot.startRoll, "RShoulderRoll of the start pose (rad)");
}

NaoArmBridge::NaoArmBridge(ros::NodeHandle nh, const NaoArmBridgeOptions& options)
    : options_(options),
      task_(parseNaoArmTask(options.task)),
      body_(NaoBody::fromUrdfFile(options.robot.urdf)),
      sensors_(seatedPosture(options.robot)),
      cymbal_(options.cymbal),
      nh_(nh) {
  rl_msgs::RLEnvDescription d;
  std::vector<float> mn, mx;
  naoArmFeatureRanges(&mn, &mx);
  float rmin = 0, rmax = 0;
  naoArmRewardRange(task_, &rmin, &rmax);
  d.num_actions = naoarm::kNumActions;
  d.num_states = naoarm::kNumFeatures;
  d.min_state_range = mn;
  d.max_state_range = mx;
  d.max_reward = rmax;
  d.reward_range = rmax - rmin;
  d.stochastic = true;
  d.episodic = false;
  d.title = "Environment: NaoArm\n";

  ros::NodeHandle driver(nh_, options_.driverNs);
  ros::NodeHandle pnh("~");
  const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
  descriptionPub_ = nh_.advertise<rl_msgs::RLEnvDescription>("rl_env/rl_env_description", 1, true);
  seedPub_ = nh_.advertise<rl_msgs::RLEnvSeedExperience>("rl_env/rl_seed", 1);
  statePub_ = nh_.advertise<rl_msgs::RLStateReward>("rl_env/rl_state_reward", 1, true);
  commandPub_ = nh_.advertise<naoqi_bridge_msgs::JointAnglesWithSpeed>("joint_angles", 10);
  micPub_ = pnh.advertise<naoqi_bridge_msgs::FloatStamped>("mic_energy", 10);
  maskPub_ = pnh.advertise<sensor_msgs::Image>("pink_mask", 1);
  markerPub_ = pnh.advertise<visualization_msgs::MarkerArray>("markers", 1);
  actionSub_ = nh_.subscribe("rl_agent/rl_action", 1, &NaoArmBridge::onAction, this, hints);
  infoSub_ =
      nh_.subscribe("rl_agent/rl_experiment_info", 1, &NaoArmBridge::onExperimentInfo, this, hints);
  jointSub_ = nh_.subscribe("joint_states", 5, &NaoArmBridge::onJointStates, this, hints);
  imageSub_ = driver.subscribe("camera/front/image_raw", 1, &NaoArmBridge::onImage, this, hints);
  bumperSub_ = driver.subscribe("bumper", 10, &NaoArmBridge::onBumper, this, hints);
  audioSub_ = driver.subscribe("audio", 50, &NaoArmBridge::onAudio, this, hints);
  resetSrv_ = nh_.advertiseService("rl_env/reset", &NaoArmBridge::onReset, this);
  descriptionPub_.publish(d);
  timer_ =
      nh_.createWallTimer(ros::WallDuration(0.01), [this](const ros::WallTimerEvent&) { poll(); });
  markerTimer_ = nh_.createWallTimer(ros::WallDuration(0.1),
                                     [this](const ros::WallTimerEvent&) { publishMarkers(); });
  ROS_INFO_STREAM_NAMED("nao_arm_bridge", "Nao arm task '"
                                              << options_.task << "' at " << options_.rate
                                              << " Hz; waiting for the driver and an agent");
}

void NaoArmBridge::onJointStates(const sensor_msgs::JointState::ConstPtr& msg) {
  try {
    sensors_.onJointStates(msg->name, msg->position, wallNow());
  } catch (const std::invalid_argument& e) {
    ROS_WARN_STREAM_THROTTLE_NAMED(5.0, "nao_arm_bridge", "dropping /joint_states: " << e.what());
  }
}

void NaoArmBridge::onImage(const sensor_msgs::Image::ConstPtr& msg) {
  try {
    const cv_bridge::CvImageConstPtr bgr =
        cv_bridge::toCvShare(msg, sensor_msgs::image_encodings::BGR8);
    if (maskPub_.getNumSubscribers() == 0) {
      sensors_.onPinkCount(detector_.count(bgr->image), wallNow());
      return;
    }
    // Someone watches the mask (rviz): count the pixels of the very mask it shows.
    cv_bridge::CvImage mask(msg->header, sensor_msgs::image_encodings::MONO8,
                            detector_.mask(bgr->image));
    sensors_.onPinkCount(cv::countNonZero(mask.image), wallNow());
    maskPub_.publish(mask.toImageMsg());
  } catch (const std::exception& e) {
    ROS_WARN_STREAM_THROTTLE_NAMED(5.0, "nao_arm_bridge",
                                   "dropping camera image (" << msg->encoding << "): " << e.what());
  }
}

void NaoArmBridge::onBumper(const naoqi_bridge_msgs::Bumper::ConstPtr& msg) {
  if (msg->state > naoqi_bridge_msgs::Bumper::statePressed) {
    ROS_WARN_STREAM_NAMED("nao_arm_bridge", "dropping bumper event with state " << int{msg->state});
    return;
  }
  sensors_.onBumper(msg->bumper == naoqi_bridge_msgs::Bumper::right,
                    msg->state == naoqi_bridge_msgs::Bumper::statePressed, wallNow());
}

void NaoArmBridge::onAudio(const naoqi_bridge_msgs::AudioBuffer::ConstPtr& msg) {
  try {
    const double now = wallNow();
    sensors_.onAudio(msg->channelMap, msg->data, now);
    if (cymbal_.onEnergy(sensors_.lastAudioEnergy(), now)) {
      ROS_DEBUG_STREAM_NAMED("nao_arm_bridge",
                             "cymbal hit (microphone energy " << sensors_.lastAudioEnergy() << ")");
    }
  } catch (const std::invalid_argument& e) {
    ROS_WARN_STREAM_THROTTLE_NAMED(5.0, "nao_arm_bridge", "dropping audio buffer: " << e.what());
  }
}

void NaoArmBridge::publishMarkers() {
  if (markerPub_.getNumSubscribers() == 0) return;
  NaoArmMarkerState state;
  state.bumperPressed = sensors_.bumperPressed();
  state.cymbalFlash = cymbal_.flash(wallNow());
  state.cymbalHits = cymbal_.hits();
  state.cymbalRadius = options_.robot.cymbalRadius;
  markerPub_.publish(naoArmMarkers(state));
}

void NaoArmBridge::sendTargets() {
  naoqi_bridge_msgs::JointAnglesWithSpeed cmd;
  cmd.header.stamp = ros::Time::now();
  cmd.joint_names = {"RShoulderPitch", "RShoulderRoll"};
  cmd.joint_angles = {static_cast<float>(targets_[0]), static_cast<float>(targets_[1])};
  cmd.speed = static_cast<float>(options_.speed);
  cmd.relative = 0;
  commandPub_.publish(cmd);
}

void NaoArmBridge::onAction(const rl_msgs::RLAction::ConstPtr& msg) {
  if (!started_) {
    ROS_WARN_NAMED("nao_arm_bridge", "dropping an action sent before the first state");
    return;
  }
  if (pending_) {
    ROS_WARN_STREAM_NAMED("nao_arm_bridge",
                          "dropping action " << msg->action << ": the previous step is running");
    return;
  }
  if (msg->action < 0 || msg->action >= naoarm::kNumActions) {
    ROS_WARN_STREAM_NAMED("nao_arm_bridge", "dropping action " << msg->action
                                                               << ": valid actions are 0.."
                                                               << naoarm::kNumActions - 1);
    return;
  }
  targets_ = applyNaoArmAction(msg->action, targets_, body_);
  sendTargets();
  pending_ = true;
  // A fixed pace: the next state is due one period after the previous one (the agent's
  // thinking time included), but the arm gets at least 40 % of a period to move.
  const ros::WallTime now = ros::WallTime::now();
  const ros::WallDuration period(1.0 / options_.rate);
  due_ = std::max(lastState_ + period, now + period * 0.4);
}

void NaoArmBridge::startReset() {
  targets_ = Eigen::Vector2d(body_.clamp("RShoulderPitch", options_.robot.startPitch),
                             body_.clamp("RShoulderRoll", options_.robot.startRoll));
  sendTargets();
  pending_ = true;
  resetting_ = true;
  due_ = ros::WallTime::now() + ros::WallDuration(options_.resetTime);
}

void NaoArmBridge::onExperimentInfo(const rl_msgs::RLExperimentInfo::ConstPtr& msg) {
  ROS_INFO_STREAM_NAMED("nao_arm_bridge", "episode " << msg->episode_number
                                                     << " ended; moving the arm to the start pose");
  if (started_) startReset();
}

bool NaoArmBridge::onReset(rl_msgs::Reset::Request& /*req*/, rl_msgs::Reset::Response& res) {
  steps_ = 0;
  res.success = true;
  if (!started_) {
    res.message = "the first state goes out once the driver and an agent are up";
    return true;
  }
  startReset();
  res.message = "moving the arm to the start pose";
  ROS_INFO_STREAM_NAMED("nao_arm_bridge", res.message);
  return true;
}

void NaoArmBridge::poll() {
  const ros::WallTime now = ros::WallTime::now();
  if (started_ && (!pending_ || now < due_)) return;
  if (!started_ && statePub_.getNumSubscribers() == 0) return;
  const std::string problems = sensors_.ready(now.toSec(), options_.maxAge, options_.needAudio);
  if (!problems.empty()) {
    ROS_WARN_STREAM_THROTTLE_NAMED(2.0, "nao_arm_bridge", "waiting for the driver: " << problems);
    return;
  }
  const NaoArmObservation o = sensors_.observe(body_);
  rl_msgs::RLStateReward m;
  m.state = toState(o);
  m.reward = started_ && pending_ && !resetting_ ? taskReward(task_, o) : 0.0f;
  m.terminal = false;
  if (!started_) {
    // Start from where the arm is.
    targets_ = Eigen::Vector2d(o.shoulderPitch, o.shoulderRoll);
    started_ = true;
    ROS_INFO_NAMED("nao_arm_bridge", "driver and agent connected; publishing the first state");
  } else if (!resetting_) {
    ++steps_;
  }
  pending_ = false;
  resetting_ = false;
  lastState_ = now;
  statePub_.publish(m);
  naoqi_bridge_msgs::FloatStamped e;
  e.header.stamp = ros::Time::now();
  e.data = static_cast<float>(std::min<double>(o.micEnergy, naoarm::kMicCap));
  micPub_.publish(e);
}

}  // namespace nao_interface
