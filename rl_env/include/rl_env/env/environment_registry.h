/**
 * The environment registry: every environment of the suite under the original's --env names.
 */
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "rl_common/environment.h"
#include "rl_common/registry.h"
#include "rl_env/env/environment_options.h"

namespace rl_env {

/// Factories take the options and the seed of the environment's own random source.
using EnvironmentRegistry =
    rl_common::Registry<rl_common::Environment, const EnvironmentOptions&, std::uint64_t>;

/// The fact of the environments that are an rl_common::TrueModel (every outcome of every
/// state-action, as `--agent optimal` and the model-accuracy measurement need).
inline constexpr const char* kTrueModelFact = "true-model";

/// The registry: taxi, tworooms, fourrooms, energy, fuelworld, mcar, cartpole, car2to7,
/// car7to2, carrandom, stocks, lightworld, naoarm.
const EnvironmentRegistry& environmentRegistry();

/// The environments with a true model, "a, b, c" (for messages and help texts).
std::string trueModelEnvironments();

/// Builds `options.env` seeded with `options.seed`. Throws std::invalid_argument listing the
/// valid names if the name is unknown.
std::unique_ptr<rl_common::Environment> makeEnvironment(const EnvironmentOptions& options);

}  // namespace rl_env
