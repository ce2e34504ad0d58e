/**
 * StateSpacePlanner: the shared machinery of the dynamic-programming planners (value
 * iteration, policy iteration, prioritized sweeping; the original's ValueIteration,
 * PolicyIteration and PrioritizedSweeping, ORIGINAL.md §7.3).
 *
 * The planner keeps a table of states: every root it was asked to plan from (and any added
 * with addStates), plus every state the model predicts within `maxSteps` transitions of a root
 * (the original's MAX_STEPS). For each table state within that distance it caches the model's
 * prediction for every action, for the current model version (setModel() makes them stale;
 * they are re-queried on the next plan()). Values follow the Bellman equation of the model:
 *
 *   Q(s,a) = R(s,a) + γ (1 − T(s,a)) Σ_s' P(s'|s,a) max_a' Q(s',a')
 *
 * where R includes any intrinsic bonus the model view adds and T is its termination
 * probability. Successors outside the declared feature ranges count as staying put (a
 * learned model's relative predictions can leave them). States at the distance limit (or beyond
 * `maxStates`) are not expanded: their Q stays at its initial 0. Subclasses decide how the equation
 * is solved (solve()). Values are warm-started from the previous model version. A budget's
 * `rollouts` caps the solver's iterations (sweeps, policy iterations or single backups); its
 * deadline is honoured between iterations; an empty budget (no rollouts, no deadline) solves to
 * convergence within the solver's own cap. Deterministic; not thread-safe.
 */
#pragma once

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "rl_agent/planner/state_grid.h"
#include "rl_agent/planner/state_hash.h"
#include "rl_common/planner.h"
#include "rl_common/random.h"

namespace rl_agent {

class StateSpacePlanner : public rl_common::Planner {
 public:
  struct Config {
    int numActions = 0;
    double gamma = 0.99;              ///< discount, in [0, 1)
    double tolerance = 1e-4;          ///< convergence threshold on value changes (MIN_ERROR)
    int maxSteps = 100;               ///< expand states within this many model steps of a root
    std::size_t maxStates = 1000000;  ///< table size limit
    long maxIterations = 100000;      ///< solver's own cap per plan()
    /// A factored prediction's joint outcomes below this probability are dropped (the rest
    /// renormalised; rl_common::expandTransitions). Higher values keep a learned forest's
    /// product of per-feature guesses from flooding the table with hallucinated states.
    double minTransitionProbability = 1e-6;
    /// Bins per feature for continuous models: empty, or one count for every feature, or one
    /// per feature (0: that feature is used as it is). States (roots and predicted successors)
    /// are binned as the original's discretisation: factor = (max − min)/n,
    /// bin = int((s ± factor/2)/factor) (+ for s > 0), s = factor · bin.
    std::vector<int> statesPerDim;
    /// Declared feature ranges (needed with statesPerDim). When given, a predicted successor
    /// outside them is not real (the original's planners' validity check, as UctPlanner):
    /// its probability stays in the state it was predicted from.
    std::vector<float> featMin, featMax;
    /// Features that tell table states apart (empty: all). With a subset the table aggregates
    /// states: those equal on these features share one entry, whose model queries use the
    /// first full state met for it (its representative; a root's is the root itself). A
    /// learned factored model whose per-feature guesses never close up (e.g. LightWorld's
    /// light sensors) otherwise reaches a new state at almost every imagined step.
    std::vector<int> keyFeatures;
    /// With keyFeatures: a factored prediction's outcomes are the joint values of the key
    /// features only, every other feature at its most likely value. An entry is then reached
    /// with the probability the model gives its key, not that of one full state: a door that
    /// opens (one key feature) and turns four door sensors on (four non-key features, each a
    /// separate guess) is otherwise a product below minTransitionProbability, and dropped.
    bool keyMarginal = false;
  };

  /// Throws std::invalid_argument for a bad configuration.
  StateSpacePlanner(const Config& config, std::uint64_t seed);

  void setModel(std::shared_ptr<const rl_common::ModelView> model) override;
  /// Adds `s` as a root, brings predictions up to date, expands, then solves within `budget`.
  /// Returns the solver's iterations. Throws std::runtime_error without a model.
  long plan(const rl_common::State& s, const rl_common::PlanningBudget& budget) override;
  /// Greedy action in `s` (ties within 1e-4 at random); a random action for an unknown state.
  /// With statesPerDim, every state argument is binned first.
  int bestAction(const rl_common::State& s) override;

  /// States new to the table from now on start from `previous`'s values for their key (if it
  /// has them) instead of 0: a table rebuilt on a changed model converges in fewer sweeps.
  /// `previous` must outlive this planner's next plan() calls; null stops warm starts.
  void warmStartFrom(const StateSpacePlanner* previous) { warm_ = previous; }
  /// Makes every state in `states` a root (e.g. all reachable states of a known model).
  void addStates(const std::vector<rl_common::State>& states);
  /// Q(s, ·); empty if `s` is not in the table.
  std::vector<double> qValues(const rl_common::State& s) const override;
  /// max_a Q(s, a); 0 for a state not in the table.
  double value(const rl_common::State& s) const;
  std::size_t numStates() const { return states_.size(); }
  /// Every state whose predictions are cached, in table order.
  /// (Their table keys: only the keyFeatures' values when those are given.)
  std::vector<rl_common::State> expandedStates() const;
  /// States whose predictions are cached (within maxSteps of a root).
  std::size_t numExpanded() const;
  const Config& config() const { return config_; }

  static constexpr double kTieTolerance = 1e-4;

 protected:
  struct Successor {
    int state;  ///< index into states_
    double p;
  };
  struct Node {
    rl_common::State key;
    rl_common::State rep;  ///< the full state the model is queried at (== key without keyFeatures)
    std::vector<double> q;
    int depth = 0;          ///< model steps from the nearest root
    bool expanded = false;  ///< predictions below are valid for the current version
    std::vector<std::vector<Successor>> next;  ///< per action
    std::vector<double> reward;                ///< per action
    std::vector<double> continueProb;          ///< per action: 1 − termProb
  };

  /// Solves the Bellman equation on the expanded states within `budget`; returns the
  /// iterations done. `changed` lists the states whose predictions were (re)queried by this
  /// plan() call.
  virtual long solve(const rl_common::PlanningBudget& budget, const std::vector<int>& changed) = 0;

  /// R + γ(1−T) Σ P max Q' for (s, a).
  double backup(int s, int a) const;
  double maxQ(int s) const;
  /// R + γ(1−T) Σ P value(s') for (s, a), with value(j) the value of table state j.
  template <class Value>
  double backupWith(int s, int a, const Value& value) const {
    const Node& n = states_[static_cast<std::size_t>(s)];
    const auto ai = static_cast<std::size_t>(a);
    double future = 0.0;
    for (const auto& succ : n.next[ai]) future += succ.p * value(succ.state);
    return n.reward[ai] + config_.gamma * n.continueProb[ai] * future;
  }
  /// True if the budget allows another iteration after `done` ones.
  bool allows(const rl_common::PlanningBudget& budget, long done) const;

  std::vector<Node> states_;
  Config config_;

 private:
  int indexOf(const rl_common::State& s);
  bool inRange(const rl_common::State& s) const;
  rl_common::State binned(const rl_common::State& s) const;
  /// The table key of a (binned) state: its keyFeatures, or all of it.
  rl_common::State keyOf(const rl_common::State& binnedState) const;
  std::vector<int> refresh();
  /// The outcomes planned for one prediction (keyMarginal: over the key features only).
  std::vector<std::pair<rl_common::State, double>> outcomes(
      const rl_common::StateActionInfo& info) const;

  rl_common::Random rng_;
  std::shared_ptr<const rl_common::ModelView> model_;
  std::uint64_t version_ = 0;
  std::uint64_t refreshedVersion_ = 0;
  std::unordered_map<rl_common::State, int, StateHash> index_;
  std::vector<int> roots_;
  std::vector<char> isRoot_;
  bool newRoots_ = false;
  bool solved_ = false;  // solved without a budget limit and nothing changed since
  StateGrid grid_;
  const StateSpacePlanner* warm_ = nullptr;
  std::vector<char> isKey_;  // per feature, for keyMarginal (empty: no key features)
};

}  // namespace rl_agent
