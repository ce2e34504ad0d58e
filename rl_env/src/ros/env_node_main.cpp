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
  bool render = false;
  rl_common::OptionParser parser(program, "--env <type> [options]");
  addEnvironmentOptions(parser, &options, catalog);
  parser.flag("prints", &prints, true, "log every action, the first two features and reward");
  parser.flag("render", &render, true,
              "publish rl_env/image, the environment drawn after every step (environments: " +
                  catalog.renderNames() + ")");
  const rl_common::NodeStart start = rl_common::startNode(
      parser, argc, argv, program,
      [&] {
        checkEnvironmentOptions(parser, options, catalog);  // validates --env too
        if (render && !catalog.registry().hasFact(options.env, kRenderFact)) {
          throw rl_common::OptionError(
              "--render: " + options.env +
              " has no rendered view; environments with one: " + catalog.renderNames());
        }
      },
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
        options.seed, prints, render);
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM_NAMED(program, e.what());
    return 1;
  }
  return 0;
}

}  // namespace rl_env
