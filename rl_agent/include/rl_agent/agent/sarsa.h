/**
 * Sarsa: tabular Sarsa(λ) with replacing eligibility traces and epsilon-greedy actions.
 *
 * Rummery & Niranjan, "On-line Q-learning using connectionist systems", CUED/F-INFENG/TR 166,
 * 1994; Sutton & Barto, "Reinforcement Learning: An Introduction", 2nd ed. 2018, §12.7.
 * After each step (s, a, r, s') and the next action a' chosen epsilon-greedily in s':
 *
 *   δ = r + γ Q(s',a') − Q(s,a)        (δ = r − Q(s,a) when s' is terminal)
 *   e(s,a) = 1                         (replacing traces)
 *   for every traced pair: Q(x,b) += α δ e(x,b);  e(x,b) *= γλ
 *
 * Traces below 1e-3 are dropped and all traces are cleared at the start of each episode. This
 * is the standard update: the original package decayed traces by λ instead of γλ and applied
 * a per-pair TD error (ORIGINAL.md §1.3, §10.3 item 11); we do not copy that.
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

class Sarsa : public rl_common::Agent {
 public:
  struct Config {
    int numActions = 0;
    float gamma = defaults::kGamma;
    float initialValue = defaults::kInitialValue;
    float alpha = defaults::kAlpha;
    float epsilon = defaults::kEpsilon;
    float lambda = defaults::kLambda;
  };

  /// Throws std::invalid_argument if numActions < 1 or a rate is outside [0, 1].
  Sarsa(const Config& config, std::uint64_t seed);

  int firstAction(const rl_common::State& s) override;
  int nextAction(float reward, const rl_common::State& s) override;
  void lastAction(float reward) override;
  /// One Sarsa(0)-style update per seed transition, bootstrapping on the greedy value (a
  /// seed has no next action).
  void seedExperiences(const std::vector<rl_common::Experience>& seeds) override;
  void savePolicy(const std::string& filename) override { q_.save(filename); }

  /// Q(s, a); the initial value for unseen pairs.
  float q(const rl_common::State& s, int action) const { return q_.value(s, action); }
  /// Number of traced state-actions.
  std::size_t numTraces() const { return traces_.size(); }

  static constexpr float kMinTrace = 1e-3f;

 private:
  struct Trace {
    rl_common::State s;
    int action;
    float e;
  };
  void update(float delta);

  Config config_;
  rl_common::Random rng_;
  QTable q_;
  std::vector<Trace> traces_;
  rl_common::State lastState_;
  int lastAction_ = -1;
};

}  // namespace rl_agent
