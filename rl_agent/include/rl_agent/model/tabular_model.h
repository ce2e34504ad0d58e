/**
 * TabularModel: a maximum-likelihood table of transitions, rewards and terminations per exact
 * state-action (the original's RMaxModel, ORIGINAL.md §6.4), with optional R-MAX optimism.
 *
 * For a state-action seen n times, t of them terminal:
 *   P(s' | s,a) = count(s,a,s') / (n − t)   (over non-terminal outcomes),
 *   R(s,a) = mean observed reward,  termProb = t / n,  known = n >= max(m, 1).
 * Never-seen state-actions predict a self-transition with reward −0.001 and known = false (the
 * paper's "initialized to predict self-transitions for state-actions that have not been
 * visited"). With `optimistic` on (R-MAX, Brafman & Tennenholtz, "R-MAX - a general
 * polynomial time algorithm for near-optimal reinforcement learning", JMLR 3, 2002), a
 * state-action seen fewer than m times instead predicts reward `rmax` (the value bound
 * Rmax/(1−γ)) and termination, so that its value is exactly the bound; and, as in R-MAX and the
 * original, counting stops once a state-action is known (its estimate uses its first m
 * samples). Without optimism every sample is counted.
 *
 * Inputs are the exact query vectors (state, plus history features if any); next states have
 * the task's d features. view() is cheap: rows are immutable and shared (copy-on-write), a
 * view copies only the table of row pointers, and only when the table changed.
 */
#pragma once

#include <atomic>
#include <memory>
#include <unordered_map>
#include <vector>

#include "rl_agent/learning_defaults.h"
#include "rl_agent/planner/state_hash.h"
#include "rl_common/mdp_model.h"

namespace rl_agent {

class TabularModel : public rl_common::MDPModel {
 public:
  struct Config {
    int numActions = 0;
    int numFeatures = 0;             ///< d: features of a next state
    int m = defaults::kKnownVisits;  ///< visits before a state-action is known
    bool optimistic = false;         ///< R-MAX optimism for unknown state-actions
    float rmax = 1.0f;               ///< reward predicted for unknown state-actions when optimistic
  };

  /// Counts for one state-action.
  struct Entry {
    int visits = 0;
    int terminations = 0;
    double rewardSum = 0.0;
    std::vector<std::pair<rl_common::State, int>> next;  ///< non-terminal successors
  };
  using Row = std::vector<Entry>;  ///< one entry per action
  using Table = std::unordered_map<rl_common::State, std::shared_ptr<const Row>, StateHash>;

  class View : public rl_common::ModelView {
   public:
    rl_common::StateActionInfo query(const rl_common::State& input, int action) const override;
    /// Visits of (input, action) as counted (capped at m when optimistic).
    int visits(const rl_common::State& input, int action) const;
    std::size_t numStates() const { return table_->size(); }

   private:
    friend class TabularModel;
    std::shared_ptr<const Table> table_;
    Config config_;
    bool optimistic_ = false;
  };

  /// Throws std::invalid_argument for a bad configuration.
  explicit TabularModel(const Config& config);

  /// Counts each experience. Throws std::invalid_argument for an action out of range or a
  /// next state with the wrong number of features.
  bool update(const std::vector<rl_common::Experience>& experiences) override;
  std::shared_ptr<const rl_common::ModelView> view() const override { return tabularView(); }
  std::shared_ptr<const View> tabularView() const;

  /// Turns the R-MAX optimism on or off for views taken from now on (a no-op when the model
  /// was built without it).
  void setOptimistic(bool on) { optimisticOn_ = on; }
  const Config& config() const { return config_; }

 private:
  Config config_;
  Table rows_;
  std::atomic<bool> optimisticOn_{true};
  mutable std::shared_ptr<const Table> snapshot_;  // null: rows_ changed since the last view
};

}  // namespace rl_agent
