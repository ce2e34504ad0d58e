/**
 * Options shared by every environment: the original env node's options (§3.2 of
 * shared/spec/ORIGINAL.md), one default each, and their command-line declaration. Options that
 * only another package's environments read (nao_interface's --task) are not here: that package
 * declares them with its registration (ExtraOption), and their values travel in `extra`.
 */
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "rl_common/option_parser.h"

namespace rl_env {

class EnvironmentCatalog;

struct EnvironmentOptions {
  std::string env = "lightworld";  ///< registry name (--env)
  std::uint64_t seed = 1;          ///< seed of the environment's own random source (--seed)
  bool stochastic = true;          ///< noisy dynamics (--stochastic / --deterministic)
  int delay = 0;                   ///< action/observation delay in steps (mcar, tworooms)
  int nsectors = 3;                ///< stocks: number of sectors
  int nstocks = 3;                 ///< stocks: stocks per sector
  bool lag = false;                ///< car*: second-order brake dynamics (--lag / --nolag)
  bool highvar = false;            ///< fuelworld: high-variance fuel costs
  /// Values of the catalog's extra options by name (e.g. "task" -> "pink"); an absent name
  /// stands for that option's default.
  std::map<std::string, std::string> extra;

  /// extra's value of `name`, or `fallback` if it has none.
  std::string extraValue(const std::string& name, const std::string& fallback) const;
};

/// A choice option that only some environments of a catalog read, declared by the package
/// that registers them (the entries that read it name it in their registry options).
struct ExtraOption {
  std::string name;                  ///< option name without dashes, e.g. "task"
  std::vector<std::string> choices;  ///< valid values
  std::string defaultValue;          ///< one of choices
  std::string help;
};

/// Declares --env, --seed and every option of addEnvironmentVariantOptions on `parser`,
/// writing into `options`.
void addEnvironmentOptions(rl_common::OptionParser& parser, EnvironmentOptions* options,
                           const EnvironmentCatalog& catalog);

/// Declares the options that choose an environment's variant: --stochastic, --deterministic,
/// --delay, --nsectors, --nstocks, --lag, --nolag, --highvar and the catalog's extra options
/// (the optimal agent node uses them to build its own copy of the env node's environment).
void addEnvironmentVariantOptions(rl_common::OptionParser& parser, EnvironmentOptions* options,
                                  const EnvironmentCatalog& catalog);

/// Rejects an unknown --env and options given for an environment that does not read them (as
/// the original did), e.g. --delay with taxi: each registry entry names the options it reads.
/// Throws rl_common::OptionError naming the option and the environments it applies to.
void checkEnvironmentOptions(const rl_common::OptionParser& parser,
                             const EnvironmentOptions& options, const EnvironmentCatalog& catalog);

}  // namespace rl_env
