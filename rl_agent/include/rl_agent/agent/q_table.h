/**
 * QTable: a table of action values Q(s, a) keyed by the exact state vector, with the greedy and
 * epsilon-greedy choices the model-free agents (Sarsa, Dyna) share. Unseen states start at the
 * initial value; greedy ties (values within 1e-4 of the best) are broken at random, as in the
 * original package.
 */
#pragma once

#include <map>
#include <string>
#include <vector>

#include "rl_common/experience.h"
#include "rl_common/random.h"

namespace rl_agent {

class QTable {
 public:
  /// Throws std::invalid_argument if numActions < 1.
  QTable(int numActions, float initialValue);

  /// The row of `s`, created at the initial value if new.
  std::vector<float>& row(const rl_common::State& s);
  /// Q(s, a) without creating a row.
  float value(const rl_common::State& s, int action) const;
  /// max_a Q(s, a) (creates the row).
  float maxValue(const rl_common::State& s);
  /// Greedy action with random tie-break.
  int greedyAction(const rl_common::State& s, rl_common::Random& rng);
  /// A uniformly random action with probability epsilon, the greedy one otherwise.
  int epsilonGreedyAction(const rl_common::State& s, float epsilon, rl_common::Random& rng);
  /// Writes the table in the original's policy-file format (PolicyFile).
  void save(const std::string& filename) const;

  int numActions() const { return numActions_; }
  const std::map<rl_common::State, std::vector<float>>& rows() const { return q_; }

  static constexpr float kTieEpsilon = 1e-4f;

 private:
  int numActions_;
  float initialValue_;
  std::map<rl_common::State, std::vector<float>> q_;
};

}  // namespace rl_agent
