// The Nao arm bridge: `rosrun nao_interface nao_arm_bridge --task explore [options]`: the
// environment side of the rl_msgs protocol on top of a Nao driver (see NaoArmBridge). Options
// also come from ~private parameters (the command line wins).
#include <ros/ros.h>

#include <iostream>
#include <memory>

#include "nao_interface/ros/nao_arm_bridge.h"
#include "rl_common/ros/param_loader.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "nao_arm_bridge");
  nao_interface::NaoArmBridgeOptions options;
  rl_common::OptionParser parser("nao_arm_bridge", "[--task explore|pink|button|mic] [options]");
  nao_interface::addBridgeOptions(parser, &options);
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
    std::cerr << "nao_arm_bridge: " << e.what() << "\n";
    return 2;
  }
  std::string values;
  for (const auto& [name, value] : parser.currentValues()) values += " " + name + "=" + value;
  ROS_INFO_STREAM_NAMED("nao_arm_bridge", "configuration:" << values);
  try {
    nao_interface::NaoArmBridge bridge(ros::NodeHandle(), options);
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM_NAMED("nao_arm_bridge", e.what());
    return 1;
  }
  return 0;
}
