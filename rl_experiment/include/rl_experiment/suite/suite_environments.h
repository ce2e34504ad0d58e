/**
 * The suite's composition of environments: rl_env's built-ins plus nao_interface's simulated
 * Nao arm (naoarm and its --task). The runner, its benchmark and the optimal agent node offer
 * this catalog; rl_env and rl_agent know nothing of the robot.
 */
#pragma once

#include "rl_env/env/environment_registry.h"

namespace rl_experiment {

/// Built once per process.
const rl_env::EnvironmentCatalog& suiteEnvironments();

}  // namespace rl_experiment
