/**
 * TrueModel: an environment's exact dynamics, for evaluation and reference planning.
 *
 * Small discrete environments (LightWorld, taxi, tworooms, fourrooms) offer every outcome of a
 * (state, action) with its probability, the set of reachable states, and a way to put the
 * environment in a given state. The model-accuracy evaluation compares a learned model's
 * predicted next-state distribution with transitions(); the `optimal` agent plans on it.
 */
#pragma once

#include <vector>

#include "rl_common/experience.h"
#include "rl_common/random.h"

namespace rl_common {

/// One possible result of an action.
struct Outcome {
  State next;
  float reward = 0.0f;
  bool terminal = false;
  double probability = 0.0;
};

class TrueModel {
 public:
  virtual ~TrueModel() = default;

  /// Every distinct outcome of taking `action` in `s`, with probabilities summing to 1.
  /// Outcomes with the same next state, reward and terminal flag are merged. Throws
  /// std::invalid_argument if `s` is not a valid state or `action` is out of range.
  virtual std::vector<Outcome> transitions(const State& s, int action) const = 0;

  /// Every state reachable from the start states (each once, in a fixed order). Non-terminal
  /// and terminal states alike.
  virtual std::vector<State> reachableStates() const = 0;

  /// A state drawn uniformly from reachableStates().
  virtual State sampleReachableState(Random& rng) const {
    const std::vector<State> all = reachableStates();
    return all.at(static_cast<std::size_t>(rng.uniformInt(0, static_cast<int>(all.size()) - 1)));
  }

  /// Puts the environment in state `s` (as if it had just arrived there). Throws
  /// std::invalid_argument if `s` is not a valid state.
  virtual void setState(const State& s) = 0;
};

}  // namespace rl_common
