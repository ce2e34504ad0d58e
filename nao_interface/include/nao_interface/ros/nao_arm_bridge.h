/**
 * NaoArmBridge: the environment side of the rl_msgs protocol (shared/spec/ORIGINAL.md §2.2)
 * for the paper's Nao arm task (Hester & Stone, TEXPLORE-VANIR, §5.2), built only from the
 * Nao driver's topics, so it drives a real Nao (naoqi_driver) as well as nao_arm_sim.
 *
 *   publishes  rl_env/rl_env_description (latched: 8 features, 5 actions, the task's reward
 *              range, non-episodic), rl_env/rl_seed (no seeds), rl_env/rl_state_reward
 *              (latched), /joint_angles (absolute shoulder targets), ~mic_energy
 *              (naoqi_bridge_msgs/FloatStamped, per step), and for rviz, only while someone
 *              subscribes: ~pink_mask (sensor_msgs/Image mono8, 255 = pink: the detector's
 *              mask of each camera image, with the image's header) and ~markers
 *              (visualization_msgs/MarkerArray at 10 Hz: the foot bumper, red while pressed,
 *              and the cymbal, flashing on a hit heard by the microphone; nao_arm_markers.h)
 *   subscribes rl_agent/rl_action, rl_agent/rl_experiment_info (moves the arm back to the
 *              start pose, as the original env resets), /joint_states,
 *              /<driver-ns>/camera/front/image_raw, /<driver-ns>/bumper, /<driver-ns>/audio
 *   service    rl_env/reset (rl_msgs/Reset): arm back to the start pose
 *
 * One step: an action moves the shoulder targets by ±8° (clamped to the URDF limits) and
 * sends them; the state and reward go out 1 / --rate seconds after the previous state (3 Hz by
 * default; at least 40 % of a period after the action), built by DriverSensorState from the
 * latest sensor data. If a sensor is missing or older than
 * --max-age the bridge logs what and waits. Malformed messages and out-of-range actions are
 * logged and dropped.
 */
#pragma once

#include <naoqi_bridge_msgs/AudioBuffer.h>
#include <naoqi_bridge_msgs/Bumper.h>
#include <rl_msgs/RLAction.h>
#include <rl_msgs/RLExperimentInfo.h>
#include <rl_msgs/Reset.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/JointState.h>

#include <string>

#include "nao_interface/camera/pink_detector.h"
#include "nao_interface/env/cymbal_hit_detector.h"
#include "nao_interface/env/driver_sensor_state.h"
#include "nao_interface/env/nao_arm_task.h"
#include "nao_interface/kinematics/nao_body.h"
#include "nao_interface/sim/nao_arm_simulation.h"
#include "rl_common/option_parser.h"

namespace nao_interface {

struct NaoArmBridgeOptions {
  std::string task = "explore";  ///< explore, pink, button or mic
  double rate = 3.0;             ///< actions per second (the paper's 3 Hz)
  double speed = 0.1;            ///< fraction of the joints' velocity limit for commands
  double maxAge = 1.0;           ///< seconds after which sensor data counts as stale
  double resetTime = 3.0;        ///< seconds allowed for the arm to return to the start pose
  bool needAudio = true;         ///< wait for audio (a real driver on NAOqi >= 2.9 has none)
  std::string driverNs = "naoqi_driver";
  CymbalHitOptions cymbal;  ///< when the microphone's energy counts as a cymbal hit (rviz)
  NaoArmSimConfig robot;    ///< URDF, start pose and seated posture (only those fields are used)
};

/// Declares the bridge's options (--task, --rate, --speed, --max-age, ...).
void addBridgeOptions(rl_common::OptionParser& parser, NaoArmBridgeOptions* options);

class NaoArmBridge {
 public:
  NaoArmBridge(ros::NodeHandle nh, const NaoArmBridgeOptions& options);

  void onAction(const rl_msgs::RLAction::ConstPtr& msg);
  void onExperimentInfo(const rl_msgs::RLExperimentInfo::ConstPtr& msg);
  bool onReset(rl_msgs::Reset::Request& req, rl_msgs::Reset::Response& res);
  void onJointStates(const sensor_msgs::JointState::ConstPtr& msg);
  void onImage(const sensor_msgs::Image::ConstPtr& msg);
  void onBumper(const naoqi_bridge_msgs::Bumper::ConstPtr& msg);
  void onAudio(const naoqi_bridge_msgs::AudioBuffer::ConstPtr& msg);
  /// Publishes the first state or a pending step's state when due and the sensors are fresh.
  void poll();

  long steps() const { return steps_; }

 private:
  void sendTargets();
  void startReset();
  void publishMarkers();

  NaoArmBridgeOptions options_;
  NaoArmTask task_;
  NaoBody body_;
  PinkDetector detector_;
  DriverSensorState sensors_;
  CymbalHitDetector cymbal_;
  ros::NodeHandle nh_;
  ros::Publisher descriptionPub_, seedPub_, statePub_, commandPub_, micPub_, maskPub_, markerPub_;
  ros::Subscriber actionSub_, infoSub_, jointSub_, imageSub_, bumperSub_, audioSub_;
  ros::ServiceServer resetSrv_;
  ros::WallTimer timer_, markerTimer_;
  Eigen::Vector2d targets_ = Eigen::Vector2d::Zero();
  bool started_ = false;    ///< the first state went out
  bool pending_ = false;    ///< a step (or reset) waits for its state
  bool resetting_ = false;  ///< the pending state ends a move to the start pose
  ros::WallTime due_, lastState_;
  long steps_ = 0;
};

}  // namespace nao_interface
