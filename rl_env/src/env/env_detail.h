// Helpers shared by the environment sources (private to rl_env_core, not installed).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "rl_common/experience.h"
#include "rl_common/random.h"
#include "rl_common/true_model.h"
#include "rl_env/env/gridworld.h"

namespace rl_env {
namespace detail {

/// Throws std::out_of_range "<where>: action A out of range [0, n-1]" for a bad action.
inline void checkAction(int action, int numActions, const char* where) {
  if (action < 0 || action >= numActions) {
    throw std::out_of_range(std::string(where) + ": action " + std::to_string(action) +
                            " out of range [0, " + std::to_string(numActions - 1) + "]");
  }
}

/// Throws std::invalid_argument "<where>: state has N features, expected M".
inline void checkStateSize(const rl_common::State& s, std::size_t expected, const char* where) {
  if (s.size() != expected) {
    throw std::invalid_argument(std::string(where) + ": state has " + std::to_string(s.size()) +
                                " features, expected " + std::to_string(expected));
  }
}

/// The integer value of feature `i` of `s`; throws std::invalid_argument unless it is an
/// integer in [lo, hi].
inline int integerFeature(const rl_common::State& s, std::size_t i, int lo, int hi,
                          const char* where) {
  const float v = s.at(i);
  if (!(v == std::floor(v)) || v < static_cast<float>(lo) || v > static_cast<float>(hi)) {
    throw std::invalid_argument(std::string(where) + ": feature " + std::to_string(i) + " = " +
                                std::to_string(v) + " is not an integer in [" + std::to_string(lo) +
                                ", " + std::to_string(hi) + "]");
  }
  return static_cast<int>(v);
}

/// Adds an outcome, merging it into an existing one with the same next state, reward and
/// terminal flag. Outcomes of probability 0 are dropped.
inline void addOutcome(std::vector<rl_common::Outcome>* outcomes, rl_common::State next,
                       float reward, bool terminal, double probability) {
  if (probability <= 0.0) return;
  for (rl_common::Outcome& o : *outcomes) {
    if (o.next == next && o.reward == reward && o.terminal == terminal) {
      o.probability += probability;
      return;
    }
  }
  rl_common::Outcome o;
  o.next = std::move(next);
  o.reward = reward;
  o.terminal = terminal;
  o.probability = probability;
  outcomes->push_back(std::move(o));
}

/// The directions a grid move in `intended` can end up taking, with their probabilities:
/// `pIntended` as intended, the rest split evenly between the two perpendicular directions.
/// Deterministic moves (stochastic == false) go as intended.
inline std::vector<std::pair<Gridworld::Direction, double>> moveDistribution(
    Gridworld::Direction intended, bool stochastic, double pIntended) {
  if (!stochastic) return {{intended, 1.0}};
  const auto [a, b] = Gridworld::perpendicular(intended);
  const double slip = 0.5 * (1.0 - pIntended);
  return {{intended, pIntended}, {a, slip}, {b, slip}};
}

/// Samples the direction actually taken for an intended grid move (one uniform draw):
/// intended with probability `pIntended`, else either perpendicular direction evenly.
inline Gridworld::Direction sampleMove(rl_common::Random& rng, Gridworld::Direction intended,
                                       bool stochastic, double pIntended) {
  if (!stochastic) return intended;
  const double u = rng.uniform();
  if (u < pIntended) return intended;
  const auto [a, b] = Gridworld::perpendicular(intended);
  return u < pIntended + 0.5 * (1.0 - pIntended) ? a : b;
}

}  // namespace detail
}  // namespace rl_env
