// The optimal agent as a node: `rosrun rl_experiment optimal_agent --env lightworld [--seed S]
// [the env node's options]`. rl_agent's agent node program with the suite's environments, so
// that `optimal` can build its own copy of the env node's environment as the true model it
// plans on (value iteration) and check it against the received description; every other agent
// works here as in rl_agent's node. Lives here because rl_agent knows no environment.
#include <ros/ros.h>

#include "rl_agent/ros/agent_node_main.h"
#include "rl_experiment/suite/suite_environments.h"
#include "rl_experiment/suite/suite_true_model_source.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "RLAgent", ros::init_options::NoSigintHandler);
  rl_experiment::SuiteTrueModelSource source(rl_experiment::suiteEnvironments());
  return rl_agent::runAgentNodeMain(argc, argv, &source, "optimal_agent", "optimal");
}
