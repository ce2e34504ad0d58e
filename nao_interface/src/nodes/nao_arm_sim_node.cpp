// The simulated Nao: `rosrun nao_interface nao_arm_sim [options]`, standing in for the robot's
// driver (see NaoArmSimNode). Options also come from ~private parameters (command line wins).
#include <ros/ros.h>

#include <iostream>
#include <memory>

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
  // Kept until main() returns: when the last node handle goes, the node shuts down, and a
  // handle local to the block below silenced every later ROS_* line.
  std::unique_ptr<ros::NodeHandle> pnh;
  try {
    if (!parser.parse(argc, argv)) {
      std::cout << parser.help();
      return 0;
    }
    pnh = std::make_unique<ros::NodeHandle>("~");
    rl_common::loadPrivateParams(parser, *pnh);
    parser.parse(argc, argv);  // the command line wins over parameters
  } catch (const std::exception& e) {
    std::cerr << "nao_arm_sim: " << e.what() << "\n";
    return 2;
  }
  std::string values;
  for (const auto& [name, value] : parser.currentValues()) values += " " + name + "=" + value;
  ROS_INFO_STREAM_NAMED("nao_arm_sim", "configuration:" << values);
  try {
    nao_interface::NaoArmSimNode node(ros::NodeHandle(), config, options);
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM_NAMED("nao_arm_sim", e.what());
    return 1;
  }
  return 0;
}
