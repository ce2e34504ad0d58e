/**
 * Dyna: Dyna-Q, Q-learning plus planning by replaying remembered experience.
 *
 * Sutton, "Integrated architectures for learning, planning, and reacting based on
 * approximating dynamic programming", ICML 1990; Sutton & Barto 2018, §8.2. Each real step
 * (s, a, r, s') gets the Q-learning update
 *
 *   Q(s,a) <- Q(s,a) + α (r + γ max_a' Q(s',a') − Q(s,a))      (no bootstrap if terminal)
 *
 * and is stored; then, before each action, k more such updates are made on experiences drawn
 * uniformly from everything stored so far (the original's Dyna, ORIGINAL.md §1.3: sampling
 * stored transitions is a sample model of a stochastic environment). Actions are
 * epsilon-greedy on Q.
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

class Dyna : public rl_common::Agent {
 public:
  struct Config {
    int numActions = 0;
    float gamma = defaults::kGamma;
    float initialValue = defaults::kInitialValue;
    float alpha = defaults::kAlpha;
    float epsilon = defaults::kEpsilon;
    int k = 1000;  ///< replayed updates per step
  };

  /// Throws std::invalid_argument if numActions < 1, k < 0 or a rate is outside [0, 1].
  Dyna(const Config& config, std::uint64_t seed);

  int firstAction(const rl_common::State& s) override;
  int nextAction(float reward, const rl_common::State& s) override;
  void lastAction(float reward) override;
  /// Learns from and stores each seed transition.
  void seedExperiences(const std::vector<rl_common::Experience>& seeds) override;
  void savePolicy(const std::string& filename) override { q_.save(filename); }

  float q(const rl_common::State& s, int action) const { return q_.value(s, action); }
  std::size_t numStored() const { return memory_.size(); }

 private:
  void learn(const rl_common::Experience& e);
  void replay();
  int act(const rl_common::State& s);

  Config config_;
  rl_common::Random rng_;
  QTable q_;
  std::vector<rl_common::Experience> memory_;
  rl_common::State lastState_;
  int lastAction_ = -1;
};

}  // namespace rl_agent
