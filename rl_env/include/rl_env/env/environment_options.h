/**
 * Options shared by every environment: the original env node's options (§3.2 of
 * shared/spec/ORIGINAL.md), one default each, and their command-line declaration.
 */
#pragma once

#include <cstdint>
#include <string>

#include "rl_common/option_parser.h"

namespace rl_env {

struct EnvironmentOptions {
  std::string env = "lightworld";  ///< registry name (--env)
  std::uint64_t seed = 1;          ///< seed of the environment's own random source (--seed)
  bool stochastic = true;          ///< noisy dynamics (--stochastic / --deterministic)
  int delay = 0;                   ///< action/observation delay in steps (mcar, tworooms)
  int nsectors = 3;                ///< stocks: number of sectors
  int nstocks = 3;                 ///< stocks: stocks per sector
  bool lag = false;                ///< car*: second-order brake dynamics (--lag / --nolag)
  bool highvar = false;            ///< fuelworld: high-variance fuel costs
  std::string task = "explore";    ///< naoarm: explore, pink, button or mic (--task)
};

/// Declares --env, --seed, --stochastic, --deterministic, --delay, --nsectors, --nstocks,
/// --lag, --nolag, --highvar and --task on `parser`, writing into `options`.
void addEnvironmentOptions(rl_common::OptionParser& parser, EnvironmentOptions* options);

/// Declares the options that choose an environment's variant, every option of
/// addEnvironmentOptions but --env and --seed (the agent node uses them to build its own copy
/// of the env node's environment as the `optimal` agent's true model).
void addEnvironmentVariantOptions(rl_common::OptionParser& parser, EnvironmentOptions* options);

/// Rejects options given for an environment that does not use them (as the original did),
/// e.g. --delay with taxi. Throws rl_common::OptionError naming the option and the
/// environments it applies to.
void checkEnvironmentOptions(const rl_common::OptionParser& parser,
                             const EnvironmentOptions& options);

}  // namespace rl_env
