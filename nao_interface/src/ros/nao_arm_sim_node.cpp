#include "nao_interface/ros/nao_arm_sim_node.h"

#include <cv_bridge/cv_bridge.h>
#include <naoqi_bridge_msgs/AudioBuffer.h>
#include <naoqi_bridge_msgs/Bumper.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/JointState.h>
#include <sensor_msgs/image_encodings.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace nao_interface {

NaoArmSimNode::NaoArmSimNode(ros::NodeHandle nh, const NaoArmSimConfig& config,
                             const NaoArmSimNodeOptions& options)
    : options_(options), sim_(config, options.seed), nh_(nh) {
  ros::NodeHandle driver(nh_, options_.driverNs);
  jointPub_ = nh_.advertise<sensor_msgs::JointState>("joint_states", 10);
  imagePub_ = driver.advertise<sensor_msgs::Image>("camera/front/image_raw", 2);
  infoPub_ = driver.advertise<sensor_msgs::CameraInfo>("camera/front/camera_info", 2);
  bumperPub_ = driver.advertise<naoqi_bridge_msgs::Bumper>("bumper", 10);
  audioPub_ = driver.advertise<naoqi_bridge_msgs::AudioBuffer>("audio", 50);
  commandSub_ = nh_.subscribe("joint_angles", 10, &NaoArmSimNode::onJointAngles, this,
                              ros::TransportHints().tcpNoDelay());
  last_ = nextJoints_ = nextCamera_ = ros::WallTime::now();
  audioStart_ = ros::Time::now();
  timer_ = nh_.createWallTimer(ros::WallDuration(0.01),
                               [this](const ros::WallTimerEvent& e) { tick(e.current_real); });
  ROS_INFO_STREAM_NAMED("nao_arm_sim", "simulated Nao ready: URDF "
                                           << config.urdf
                                           << ", topics /joint_states, /joint_angles, /"
                                           << options_.driverNs << "/{camera/front,bumper,audio}");
}

void NaoArmSimNode::onJointAngles(const naoqi_bridge_msgs::JointAnglesWithSpeed::ConstPtr& msg) {
  if (msg->joint_names.size() != msg->joint_angles.size() || msg->joint_names.empty()) {
    ROS_WARN_STREAM_NAMED("nao_arm_sim",
                          "dropping /joint_angles: " << msg->joint_names.size() << " names, "
                                                     << msg->joint_angles.size() << " angles");
    return;
  }
  if (!(msg->speed > 0.0f && msg->speed <= 1.0f)) {
    ROS_WARN_STREAM_NAMED("nao_arm_sim",
                          "dropping /joint_angles: speed " << msg->speed << " outside (0, 1]");
    return;
  }
  for (std::size_t i = 0; i < msg->joint_names.size(); ++i) {
    const std::string& name = msg->joint_names[i];
    if (!std::isfinite(msg->joint_angles[i]) || sim_.angles().count(name) == 0) {
      ROS_WARN_STREAM_NAMED("nao_arm_sim", "dropping /joint_angles: unknown joint '"
                                               << name << "' or angle not finite");
      return;
    }
  }
  for (std::size_t i = 0; i < msg->joint_names.size(); ++i) {
    if (msg->relative != 0) {
      sim_.changeTarget(msg->joint_names[i], msg->joint_angles[i], msg->speed);
    } else {
      sim_.setTarget(msg->joint_names[i], msg->joint_angles[i], msg->speed);
    }
  }
}

void NaoArmSimNode::tick(const ros::WallTime& now) {
  const double dt = std::min(0.5, std::max(0.0, (now - last_).toSec()));
  last_ = now;
  sim_.advance(dt);
  const ros::Time stamp = ros::Time::now();
  for (const BumperEdge& e : sim_.takeBumperEdges()) {
    naoqi_bridge_msgs::Bumper b;
    b.bumper = naoqi_bridge_msgs::Bumper::right;
    b.state = e.pressed ? naoqi_bridge_msgs::Bumper::statePressed
                        : naoqi_bridge_msgs::Bumper::stateReleased;
    bumperPub_.publish(b);
    ROS_DEBUG_STREAM_NAMED("nao_arm_sim",
                           "right foot bumper " << (e.pressed ? "pressed" : "released"));
  }
  while (auto data = sim_.nextAudioBuffer()) {
    naoqi_bridge_msgs::AudioBuffer a;
    a.header.stamp = stamp;
    a.frequency = static_cast<std::uint16_t>(sim_.config().microphone.sampleRate);
    a.channelMap = MicrophoneModel::channelMap();
    a.data = std::move(*data);
    audioPub_.publish(a);
  }
  // Fixed rates: the next message is due one period after the previous one was due.
  if (now >= nextJoints_) {
    nextJoints_ = std::max(nextJoints_ + ros::WallDuration(1.0 / options_.jointStateRate), now);
    publishJointStates(stamp);
  }
  if (now >= nextCamera_) {
    nextCamera_ = std::max(nextCamera_ + ros::WallDuration(1.0 / options_.cameraRate), now);
    publishCamera(stamp);
  }
}

void NaoArmSimNode::publishJointStates(const ros::Time& stamp) {
  sensor_msgs::JointState js;
  js.header.stamp = stamp;
  for (const auto& [name, q] : sim_.measuredAngles()) {
    js.name.push_back(name);
    js.position.push_back(q);
  }
  jointPub_.publish(js);
}

void NaoArmSimNode::publishCamera(const ros::Time& stamp) {
  if (imagePub_.getNumSubscribers() == 0 && infoPub_.getNumSubscribers() == 0) return;
  cv::Mat rgb;
  cv::cvtColor(sim_.renderCamera(), rgb, cv::COLOR_BGR2RGB);
  std_msgs::Header header;
  header.stamp = stamp;
  header.frame_id = "CameraTop_optical_frame";
  imagePub_.publish(
      cv_bridge::CvImage(header, sensor_msgs::image_encodings::RGB8, rgb).toImageMsg());
  const PinholeCamera& c = sim_.camera();
  sensor_msgs::CameraInfo info;
  info.header = header;
  info.width = c.width;
  info.height = c.height;
  info.distortion_model = "plumb_bob";
  info.D = {0.0, 0.0, 0.0, 0.0, 0.0};
  info.K = {c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1};
  info.R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  info.P = {c.fx, 0, c.cx, 0, 0, c.fy, c.cy, 0, 0, 0, 1, 0};
  infoPub_.publish(info);
}

}  // namespace nao_interface
