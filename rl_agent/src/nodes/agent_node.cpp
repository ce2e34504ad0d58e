// The agent node: `rosrun rl_agent agent --agent texplore --v 1 --n 3`. Options also come from
// ~private parameters (the command line wins); see AgentNode for the protocol. The optimal
// agent, which plans on its own copy of the environment, is rl_experiment's optimal_agent node.
#include <ros/ros.h>

#include "rl_agent/agent/agent_options.h"
#include "rl_agent/ros/agent_node_main.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "RLAgent", ros::init_options::NoSigintHandler);
  return rl_agent::runAgentNodeMain(argc, argv, nullptr, "agent", rl_agent::AgentOptions().agent);
}
