/**
 * The whole program of an env node over a catalog: options from the command line and ~private
 * parameters (the command line wins), --help without a master, then an EnvironmentNode until
 * shutdown. rl_env's `env` node runs it over rl_env's built-in environments; a package that
 * registers its own (nao_interface's nao_arm_env) runs it over its catalog.
 */
#pragma once

#include <string>

#include "rl_env/env/environment_registry.h"

namespace rl_env {

/// Runs the node named `program` in messages, whose --env is `defaultEnv` unless given;
/// returns main()'s exit code: 0 after shutdown or --help, 2 for a bad option, 1 if serving
/// failed. Call ros::init first.
int runEnvironmentNodeMain(int argc, char** argv, const EnvironmentCatalog& catalog,
                           const std::string& program,
                           const std::string& defaultEnv = EnvironmentOptions().env);

}  // namespace rl_env
