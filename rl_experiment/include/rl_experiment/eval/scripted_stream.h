/**
 * Scripted LightWorld experience streams: what the model-distance measure (the TEXPLORE-VANIR
 * paper's Fig. 4) gives for data no explorer chose, to bound what exploration can buy
 * (docs/science/lightworld-curiosity.md §2.1).
 *
 * Every stream takes uniformly random actions; they differ in where the actions are taken:
 * - walk: from LightWorld's start state on, like `--explore random`;
 * - iid: each from a state drawn uniformly from the reachable states, the measure's own
 *   distribution (no walk can do better than this on average);
 * - teleport: a walk restarted from a uniformly drawn reachable state every `period` steps;
 * - keep-key: a walk whose PICKUP on the key becomes a uniformly random move for its first
 *   `period` steps, so the key stays on the floor (only then do the key sensors read anything).
 */
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rl_common/experience.h"

namespace rl_experiment {

struct ScriptedStreamConfig {
  std::string stream = "walk";  ///< walk, iid, teleport, keep-key
  long steps = 1000;
  long period = 100;  ///< teleport: steps between restarts; keep-key: steps without pickup
};

/// The valid stream names.
const std::vector<std::string>& scriptedStreamNames();

/// `config.steps` LightWorld experiences (stochastic dynamics), from an environment and an
/// action source seeded by `seed`. Throws std::invalid_argument for an unknown stream, steps < 1
/// or period < 1.
std::vector<rl_common::Experience> scriptedLightWorldStream(const ScriptedStreamConfig& config,
                                                            std::uint64_t seed);

/// One scripted trial, measured.
struct ScriptedStreamResult {
  double distance = 0.0;  ///< the model's mean variational distance (ModelAccuracy)
  long keyOnFloor = 0;    ///< experiences that start with the key on the floor
};

/// Feeds scriptedLightWorldStream(config, streamSeed) one experience at a time to the model of
/// `--agent texplore --explore random` (seeded with `modelSeed`), then measures it over
/// `samples` state-actions drawn with `evalSeed`.
ScriptedStreamResult measureScriptedStream(const ScriptedStreamConfig& config,
                                           std::uint64_t streamSeed, std::uint64_t modelSeed,
                                           std::uint64_t evalSeed, int samples);

}  // namespace rl_experiment
