// The simulated Nao: `rosrun nao_interface nao_arm_sim [options]`, standing in for the robot's
// driver (see NaoArmSimNode). Options also come from ~private parameters (command line wins).
#include <ros/ros.h>

#include "nao_interface/ros/nao_arm_sim_node.h"
#include "rl_common/ros/param_loader.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "nao_arm_sim");
  nao_interface::NaoArmSimConfig config;
  nao_interface::NaoArmSimNodeOptions options;
  rl_common::OptionParser parser("nao_arm_sim", "[options]");
  nao_interface::addSimOptions(parser, &config);
  parser.value("seed", &options.seed, "seed of the simulation's random sources");
  parser.value("joint-state-rate", &options.jointStateRate, "Hz of /joint_states",
               rl_common::greaterThan(0.0));
  parser.value("camera-rate", &options.cameraRate, "Hz of the camera images",
               rl_common::greaterThan(0.0));
  parser.value("driver-ns", &options.driverNs, "namespace of the driver's topics");
  const rl_common::NodeStart start = rl_common::startNode(parser, argc, argv, "nao_arm_sim");
  if (!start) return start.exitCode;
  try {
    nao_interface::NaoArmSimNode node(ros::NodeHandle(), config, options);
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM_NAMED("nao_arm_sim", e.what());
    return 1;
  }
  return 0;
}
