// The env node: `rosrun rl_env env --env lightworld [options]`. Options also come from
// ~private parameters (the command line wins); see EnvironmentNode for the protocol.
#include <ros/ros.h>

#include <iostream>
#include <memory>

#include "rl_common/ros/param_loader.h"
#include "rl_env/env/environment_registry.h"
#include "rl_env/ros/environment_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "RLEnvironment");
  rl_env::EnvironmentOptions options;
  bool prints = false;
  rl_common::OptionParser parser("env", "--env <type> [options]");
  rl_env::addEnvironmentOptions(parser, &options);
  parser.flag("prints", &prints, true, "log every action, the first two features and reward");
  // Kept until main() returns: when the last node handle goes, the node shuts down, and a
  // handle local to the block below silenced every later ROS_* line.
  std::unique_ptr<ros::NodeHandle> pnh;
  try {
    // --help must work without a master: look at argv before touching the parameter server.
    if (!parser.parse(argc, argv)) {
      std::cout << parser.help() << "\nValid environments: "
                << rl_common::joinNames(rl_env::environmentRegistry().names()) << "\n";
      return 0;
    }
    pnh = std::make_unique<ros::NodeHandle>("~");
    rl_common::loadPrivateParams(parser, *pnh);
    parser.parse(argc, argv);  // the command line wins over parameters
    rl_env::checkEnvironmentOptions(parser, options);
    rl_env::environmentRegistry().canonical(options.env);  // validate before building
  } catch (const std::exception& e) {
    std::cerr << "env: " << e.what() << "\n";
    return 2;
  }
  std::string config;
  for (const auto& [name, value] : parser.currentValues()) config += " " + name + "=" + value;
  ROS_INFO_STREAM_NAMED("env", "configuration:" << config);
  try {
    ros::NodeHandle nh;
    rl_env::EnvironmentNode node(
        nh,
        [options](std::uint64_t seed) {
          rl_env::EnvironmentOptions o = options;
          o.seed = seed;
          return rl_env::makeEnvironment(o);
        },
        options.seed, prints);
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM_NAMED("env", e.what());
    return 1;
  }
  return 0;
}
