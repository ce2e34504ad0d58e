// The agent node: `rosrun rl_agent agent --agent texplore --v 1 --n 3`. Options also come from
// ~private parameters (the command line wins); see AgentNode for the protocol.
#include <ros/ros.h>

#include <iostream>

#include "rl_agent/agent/agent_registry.h"
#include "rl_agent/ros/agent_node.h"
#include "rl_common/ros/param_loader.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "RLAgent");
  rl_agent::AgentOptions options;
  rl_common::OptionParser parser("agent", "--agent <type> [options]");
  rl_agent::addAgentOptions(parser, &options);
  parser.value("seed", &options.seed, "seed of the agent's random source");
  try {
    // --help must work without a master: look at argv before the parameter server.
    if (!parser.parse(argc, argv)) {
      std::cout << parser.help()
                << "\nValid agents: " << rl_common::joinNames(rl_agent::agentRegistry().names())
                << "\n";
      return 0;
    }
    rl_common::loadPrivateParams(parser, ros::NodeHandle("~"));
    parser.parse(argc, argv);  // the command line wins over parameters
    rl_agent::agentRegistry().canonical(options.agent);
    rl_agent::applyAgentDefaults(parser, &options);
    rl_agent::checkAgentOptions(parser, options);
  } catch (const std::exception& e) {
    std::cerr << "agent: " << e.what() << "\n";
    return 2;
  }
  std::string config;
  for (const auto& [name, value] : parser.currentValues()) config += " " + name + "=" + value;
  ROS_INFO_STREAM_NAMED("agent", "configuration:" << config);
  rl_agent::AgentNode node(ros::NodeHandle(), options);
  ros::spin();
  return 0;
}
