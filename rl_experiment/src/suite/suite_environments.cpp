#include "rl_experiment/suite/suite_environments.h"

#include "nao_interface/env/nao_arm_registration.h"

namespace rl_experiment {

const rl_env::EnvironmentCatalog& suiteEnvironments() {
  static const rl_env::EnvironmentCatalog catalog = [] {
    rl_env::EnvironmentCatalog c;
    rl_env::addBuiltinEnvironments(c);
    nao_interface::addNaoArmEnvironment(c);
    return c;
  }();
  return catalog;
}

}  // namespace rl_experiment
