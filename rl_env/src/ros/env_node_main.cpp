#include "rl_env/ros/env_node_main.h"

#include <ros/ros.h>

#include "rl_common/ros/param_loader.h"
#include "rl_env/ros/environment_node.h"

namespace rl_env {

int runEnvironmentNodeMain(int argc, char** argv, const EnvironmentCatalog& catalog,
                           const std::string& program, const std::string& defaultEnv) {
  EnvironmentOptions options;
  options.env = defaultEnv;
  bool prints = false;
  rl_common::OptionParser parser(program, "--env <type> [options]");
  addEnvironmentOptions(parser, &options, catalog);
  parser.flag("prints", &prints, true, "log every action, the first two features and reward");
  const rl_common::NodeStart start = rl_common::startNode(
      parser, argc, argv, program,
      [&] { checkEnvironmentOptions(parser, options, catalog); },  // validates --env too
      "\nValid environments: " + rl_common::joinNames(catalog.registry().names()) + "\n");
  if (!start) return start.exitCode;
  try {
    ros::NodeHandle nh;
    EnvironmentNode node(
        nh,
        [options, &catalog](std::uint64_t seed) {
          EnvironmentOptions o = options;
          o.seed = seed;
          return catalog.make(o);
        },
        options.seed, prints);
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM_NAMED(program, e.what());
    return 1;
  }
  return 0;
}

}  // namespace rl_env
