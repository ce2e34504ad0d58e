/**
 * NaoArmSimNode: serves a NaoArmSimulation with the topics and types of the real Nao driver
 * (naoqi_driver, shared/spec/NAO.md §2.1), so the bridge cannot tell it from a robot:
 *   publishes  /joint_states (sensor_msgs/JointState, --joint-state-rate Hz),
 *              /<driver-ns>/camera/front/image_raw (rgb8, through cv_bridge) and camera_info
 *              (--camera-rate Hz, frame CameraTop_optical_frame),
 *              /<driver-ns>/bumper (naoqi_bridge_msgs/Bumper, on press and release only),
 *              /<driver-ns>/audio (naoqi_bridge_msgs/AudioBuffer, 48 kHz, 4 channels)
 *   subscribes /joint_angles (naoqi_bridge_msgs/JointAnglesWithSpeed, absolute or relative)
 * The simulation advances with the wall clock (a timer at 100 Hz). A malformed command
 * (sizes differ, unknown joint, speed outside (0, 1], not finite) is logged and dropped.
 */
#pragma once

#include <naoqi_bridge_msgs/JointAnglesWithSpeed.h>
#include <ros/ros.h>

#include <memory>
#include <string>

#include "nao_interface/sim/nao_arm_simulation.h"

namespace nao_interface {

struct NaoArmSimNodeOptions {
  std::uint64_t seed = 1;
  double jointStateRate = 50.0;  ///< Hz, as naoqi_driver's boot_config.json
  double cameraRate = 10.0;      ///< Hz
  std::string driverNs = "naoqi_driver";
};

class NaoArmSimNode {
 public:
  NaoArmSimNode(ros::NodeHandle nh, const NaoArmSimConfig& config,
                const NaoArmSimNodeOptions& options);

  void onJointAngles(const naoqi_bridge_msgs::JointAnglesWithSpeed::ConstPtr& msg);
  /// Advances the simulation to `now` and publishes what is due.
  void tick(const ros::WallTime& now);

  const NaoArmSimulation& simulation() const { return sim_; }

 private:
  void publishJointStates(const ros::Time& stamp);
  void publishCamera(const ros::Time& stamp);

  NaoArmSimNodeOptions options_;
  NaoArmSimulation sim_;
  ros::NodeHandle nh_;
  ros::Publisher jointPub_, imagePub_, infoPub_, bumperPub_, audioPub_;
  ros::Subscriber commandSub_;
  ros::WallTimer timer_;
  ros::WallTime last_, nextJoints_, nextCamera_;
  ros::Time audioStart_;
};

}  // namespace nao_interface
