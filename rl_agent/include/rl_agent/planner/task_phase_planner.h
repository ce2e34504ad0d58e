/**
 * TaskPhasePlanner (`--taskplanner vi`): plans the paper's task phase by value iteration on
 * the learned model, afresh at every step, instead of UCT.
 *
 * The table is the states the model's likely outcomes reach within `maxSteps` steps of the
 * current one (at most `maxStates`), told apart by the key features when given, the last
 * `recent` observed states serving as their entries' representatives. UCT's rollouts from one
 * state rarely reach a reward three subgoals away (key, lock, door on LightWorld); a sweep over
 * the imagined states does (docs/science/lightworld-curiosity.md §5).
 */
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <vector>

#include "rl_agent/planner/value_iteration.h"
#include "rl_common/mdp_model.h"

namespace rl_agent {

class TaskPhasePlanner {
 public:
  struct Config {
    StateSpacePlanner::Config table;  ///< each step's table (depth, size, outcomes, key features)
    long sweeps = 0;                  ///< sweeps a step; 0: to convergence
    int recent = 0;                   ///< observed states kept as representatives
    std::uint64_t seed = 0;           ///< each step's planner seed derives from it
  };

  explicit TaskPhasePlanner(const Config& config) : config_(config) {}

  /// A state just observed (kept while it is among the last `recent`).
  void observe(const rl_common::State& s);
  /// Plans at `s` on `model` (the learned model, no bonuses) and returns the greedy action.
  int plan(const rl_common::State& s, std::shared_ptr<const rl_common::ModelView> model);
  /// Sweeps of the last plan().
  long lastIterations() const { return lastIterations_; }
  /// Q(s, ·) of the last plan's table; empty before the first plan or for a state not in it.
  std::vector<double> qValues(const rl_common::State& s) const;
  /// True once a step was planned since the last reset().
  bool planned() const { return last_ != nullptr; }
  /// Forgets the last table (the model changed: a new phase plans afresh).
  void reset() { last_.reset(); }

 private:
  Config config_;
  std::unique_ptr<ValueIteration> last_;  ///< kept for its values (warm start, Q-values)
  std::uint64_t steps_ = 0;               ///< steps planned so far
  std::deque<rl_common::State> recent_;
  long lastIterations_ = 0;
};

}  // namespace rl_agent
