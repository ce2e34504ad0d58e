/**
 * Registers the paper's simulated Nao arm in an environment catalog: `naoarm` and the option
 * only it reads, --task (explore, pink, button, mic; nao_arm_task.h). The runner and the
 * nao_arm_env node compose it with rl_env's built-in environments; rl_env knows no robot.
 */
#pragma once

#include "rl_env/env/environment_registry.h"

namespace nao_interface {

/// The --task every Nao arm program starts with.
inline constexpr const char* kDefaultNaoArmTask = "explore";

/// Adds `naoarm` and --task to `catalog`. Throws std::invalid_argument if either is there.
void addNaoArmEnvironment(rl_env::EnvironmentCatalog& catalog);

}  // namespace nao_interface
