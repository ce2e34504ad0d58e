/**
 * QLearner: tabular Q-learning with epsilon-greedy action selection.
 *
 * Watkins & Dayan, "Q-learning", Machine Learning 8:279-292, 1992. After each step,
 *   Q(s,a) <- Q(s,a) + alpha * (r + gamma * max_a' Q(s',a') - Q(s,a)),
 * with the bootstrap term dropped when s' is terminal. The values live in a QTable (shared with
 * Sarsa and Dyna): states keyed by their exact feature vector, unseen state-actions at
 * `initialValue`, greedy ties within 1e-4 of the best broken at random, as in the original.
 */
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rl_agent/agent/q_table.h"
#include "rl_agent/learning_defaults.h"
#include "rl_common/agent.h"
#include "rl_common/random.h"

namespace rl_agent {

class QLearner : public rl_common::Agent {
 public:
  struct Config {
    int numActions = 0;
    float gamma = defaults::kGamma;
    float initialValue = defaults::kInitialValue;
    float alpha = defaults::kAlpha;
    float epsilon = defaults::kEpsilon;
  };

  /// Throws std::invalid_argument if numActions < 1 or a rate is outside [0, 1].
  QLearner(const Config& config, std::uint64_t seed);

  int firstAction(const rl_common::State& s) override;
  int nextAction(float reward, const rl_common::State& s) override;
  void lastAction(float reward) override;
  /// Applies one Q-update per seed transition (terminal-aware).
  void seedExperiences(const std::vector<rl_common::Experience>& seeds) override;
  /// Writes Q in the original's policy-file format (PolicyFile).
  void savePolicy(const std::string& filename) override;

  /// Q(s, a); `initialValue` for unseen pairs.
  float q(const rl_common::State& s, int action) const;
  /// The greedy action in `s` (random tie-break).
  int greedyAction(const rl_common::State& s);

 private:
  void update(const rl_common::State& s, int a, float r, const rl_common::State* next);

  Config config_;
  rl_common::Random rng_;
  QTable q_;
  rl_common::State lastState_;
  int lastAction_ = -1;
};

}  // namespace rl_agent
