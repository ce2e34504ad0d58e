// The env node: `rosrun rl_env env --env lightworld [options]`, rl_env's built-in environments.
// Options also come from ~private parameters (the command line wins); see EnvironmentNode for
// the protocol. The simulated Nao arm has its own node (nao_interface's nao_arm_env).
#include <ros/ros.h>

#include "rl_env/ros/env_node_main.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "RLEnvironment");
  return rl_env::runEnvironmentNodeMain(argc, argv, rl_env::builtinEnvironments(), "env");
}
