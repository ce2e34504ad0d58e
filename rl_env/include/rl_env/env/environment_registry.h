/**
 * The environment registry and the catalog a program offers: rl_env's built-in environments
 * under the original's --env names, plus whatever the program's composition adds (the runner
 * adds nao_interface's naoarm; rl_env itself knows no robot).
 */
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rl_common/environment.h"
#include "rl_common/registry.h"
#include "rl_env/env/environment_options.h"
#include "rl_env/render/renderable.h"

namespace rl_env {

/// Factories take the options and the seed of the environment's own random source.
using EnvironmentRegistry =
    rl_common::Registry<rl_common::Environment, const EnvironmentOptions&, std::uint64_t>;

/// The fact of the environments that are an rl_common::TrueModel (every outcome of every
/// state-action, as `--agent optimal` and the model-accuracy measurement need).
inline constexpr const char* kTrueModelFact = "true-model";

/// The environments one program offers and the extra options some of them read.
class EnvironmentCatalog {
 public:
  EnvironmentRegistry& registry() { return registry_; }
  const EnvironmentRegistry& registry() const { return registry_; }

  /// Declares an option for environments registered with it in their entry's options. Throws
  /// std::invalid_argument if the name is declared already or the default is not a choice.
  void addOption(ExtraOption option);
  const std::vector<ExtraOption>& extraOptions() const { return extraOptions_; }

  /// Builds `options.env` seeded with `options.seed`. Throws std::invalid_argument listing the
  /// valid names if the name is unknown.
  std::unique_ptr<rl_common::Environment> make(const EnvironmentOptions& options) const;

  /// The environments with a true model, "a, b, c" (for messages and help texts).
  std::string trueModelNames() const;
  /// The environments with a rendered view (kRenderFact), "a, b, c".
  std::string renderNames() const;

 private:
  EnvironmentRegistry registry_{"environment"};
  std::vector<ExtraOption> extraOptions_;
};

/// Adds rl_env's environments: taxi, tworooms, fourrooms, energy, fuelworld, mcar, cartpole,
/// car2to7, car7to2, carrandom, stocks, lightworld.
void addBuiltinEnvironments(EnvironmentCatalog& catalog);

/// A catalog of rl_env's built-in environments alone (what rl_env's env node offers).
const EnvironmentCatalog& builtinEnvironments();

}  // namespace rl_env
