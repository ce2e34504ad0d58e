// The Nao arm bridge: `rosrun nao_interface nao_arm_bridge --task explore [options]`: the
// environment side of the rl_msgs protocol on top of a Nao driver (see NaoArmBridge). Options
// also come from ~private parameters (the command line wins).
#include <ros/ros.h>

#include "nao_interface/ros/nao_arm_bridge.h"
#include "rl_common/ros/param_loader.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "nao_arm_bridge");
  nao_interface::NaoArmBridgeOptions options;
  rl_common::OptionParser parser("nao_arm_bridge", "[--task explore|pink|button|mic] [options]");
  nao_interface::addBridgeOptions(parser, &options);
  const rl_common::NodeStart start = rl_common::startNode(parser, argc, argv, "nao_arm_bridge");
  if (!start) return start.exitCode;
  try {
    nao_interface::NaoArmBridge bridge(ros::NodeHandle(), options);
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM_NAMED("nao_arm_bridge", e.what());
    return 1;
  }
  return 0;
}
