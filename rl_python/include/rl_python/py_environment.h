/**
 * PyEnvironment: one environment of a catalog, built by registry name with the env node's
 * option names, behind the Gymnasium-style protocol the Python module offers.
 *
 *   reset(seed)  seed given: the environment is built anew with that seed, so its start state
 *                and every later step are those of the C++ environment constructed with it;
 *                no seed: a new episode from the environment's own random source, except right
 *                after construction (or a seeded reset), when the start state it was built in
 *                is returned as it is.
 *   step(a)      apply(a): the next state, the reward, terminated (the state is terminal),
 *                truncated (always false: environments have no time limit; cutting episodes
 *                is the caller's, as the runner's --maxsteps). Stepping a terminated episode
 *                is an error until reset().
 *   run(as)      the same steps in C++ (reset on termination), as a baseline that crosses the
 *                Python boundary once.
 *
 * The options are validated as on the env node's command line (addEnvironmentOptions,
 * checkEnvironmentOptions): unknown names, bad values and options the chosen environment does
 * not read throw rl_common::OptionError.
 */
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rl_common/environment.h"
#include "rl_common/true_model.h"
#include "rl_env/env/environment_options.h"
#include "rl_env/env/environment_registry.h"
#include "rl_python/option_values.h"

namespace rl_python {

class PyEnvironment {
 public:
  /// What step() returns.
  struct Step {
    rl_common::State observation;
    float reward = 0.0f;
    bool terminated = false;
    bool truncated = false;
  };

  /// Builds `name` from `catalog` (which must outlive this object) with `options` (any option
  /// of the env node's but --env, e.g. ("deterministic", "true"), ("seed", "3")). Throws
  /// rl_common::OptionError for an unknown environment or option, or a bad value.
  PyEnvironment(const rl_env::EnvironmentCatalog& catalog, const std::string& name,
                const OptionValues& options);

  /// Starts an episode (see the class comment); returns its first state.
  const rl_common::State& reset(std::optional<std::uint64_t> seed);
  /// Applies `action`. Throws std::out_of_range for an action outside [0, numActions) and
  /// std::logic_error if the episode has terminated.
  Step step(int action);
  /// Applies every action in C++, resetting (as reset() without a seed) whenever a state is
  /// terminal, exactly as a Python loop of step() and reset(); returns the rewards' sum.
  double run(const std::vector<int>& actions);

  /// The current state.
  const rl_common::State& observation() const { return env_->sensation(); }
  bool terminated() const { return env_->terminal(); }
  /// Steps since the episode began.
  long episodeSteps() const { return episodeSteps_; }

  /// Registry name (canonical), e.g. "lightworld".
  const std::string& name() const { return options_.env; }
  rl_common::EnvironmentDescription description() const { return env_->describe(); }
  std::vector<rl_common::Experience> seedExperiences() const { return env_->seedExperiences(); }
  /// The environment's exact dynamics, or null if it has none (registry fact "true-model").
  rl_common::TrueModel* trueModel();
  /// Puts the environment in state `s` (TrueModel::setState); the next reset() without a seed
  /// starts a new episode. Throws std::logic_error without a true model, and
  /// std::invalid_argument if `s` cannot occur.
  void setState(const rl_common::State& s);
  /// The options the environment was built with (the seed of the last seeded reset).
  const rl_env::EnvironmentOptions& options() const { return options_; }
  /// Every option's effective value, as the env node logs them.
  const OptionValues& effectiveOptions() const { return effective_; }
  const rl_env::EnvironmentCatalog& catalog() const { return *catalog_; }
  /// Another environment built like this one (same name, options and seed), e.g. the copy an
  /// agent that plans on the true model keeps.
  std::unique_ptr<rl_common::Environment> makeCopy() const { return catalog_->make(options_); }

 private:
  const rl_env::EnvironmentCatalog* catalog_;
  rl_env::EnvironmentOptions options_;
  OptionValues effective_;
  std::unique_ptr<rl_common::Environment> env_;
  bool fresh_ = true;  ///< in the start state it was built in, no step taken
  long episodeSteps_ = 0;
};

}  // namespace rl_python
