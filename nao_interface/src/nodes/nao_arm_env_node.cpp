// The simulated Nao arm as an env node on the rl_msgs protocol, no driver and no bridge:
// `rosrun nao_interface nao_arm_env --task pink [--seed S] [--deterministic]`. The same
// program as rl_env's env node (options, ~private parameters, reset service) over a catalog
// holding `naoarm` alone, which is its default --env.
#include <ros/ros.h>

#include "nao_interface/env/nao_arm_registration.h"
#include "rl_env/ros/env_node_main.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "NaoArmEnvironment");
  rl_env::EnvironmentCatalog catalog;
  nao_interface::addNaoArmEnvironment(catalog);
  return rl_env::runEnvironmentNodeMain(argc, argv, catalog, "nao_arm_env", "naoarm");
}
