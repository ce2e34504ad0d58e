/**
 * FactoredModel: TEXPLORE's learned model of the environment (Hester & Stone
 * 2013; the TEXPLORE-VANIR paper §4.1, Algorithm 1; shared/spec/ORIGINAL.md
 * §6.1).
 *
 * One random forest per state feature predicts that feature's change s'_j - s_j
 * (or s'_j with absolute transitions); a reward forest predicts the reward and,
 * in episodic tasks, a terminal forest predicts termination. Every forest's
 * input is the state (plus any history features) followed by the action
 * one-hot: x = [s, onehot(a)]. Feature forests learn only from non-terminal
 * transitions; reward and terminal forests from all.
 *
 * A query returns the per-feature distributions (StateActionInfo::factored) whose independent
 * product is the distribution over absolute next states:
 *   P(s' | s, a) = prod_j P_j(s'_j - s_j | x)
 * (rl_common::expandTransitions() lists it when needed); reward = E[reward forest];
 * termProb = E[clip(terminal forest, 0, 1)] (0 if non-episodic). Before any data the model
 * predicts a self-transition with reward -0.001 and known = false, as the original.
 *
 * The model's variance (VANIR's D(s,a), ORIGINAL.md §5.2) is the forests'
 * disagreement averaged over the outputs {features, reward, terminal}, where
 * the terminal output counts 0 in non-episodic tasks: D = (sum_j D_j + D_reward
 * + D_terminal) / (d + 2).
 *
 * view() is cheap: it copies the forests' snapshots (shared, immutable trees).
 *
 * Each forest carries a revision, drawn from one process-wide counter whenever the forest's
 * predictions may have changed (a tree rebuilt; with the weighted and best combinations, any
 * instance, since the trees' accuracies move). A view's refresh() re-reads only the forests
 * whose revision differs from the prediction's stamp: the trees rebuild on a minority of the
 * instances, so from one step to the next a planner's cached prediction is mostly still right.
 * The result is bit for bit what query() returns (the same arithmetic in the same order).
 *
 * All forests see the same input x, so they share one input table: each x is stored once,
 * the trees keep only row ids into it (the instance storage dominates the agent's memory).
 */
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "rl_agent/model/random_forest.h"
#include "rl_common/mdp_model.h"

namespace rl_agent {

class FactoredModel : public rl_common::MDPModel {
 public:
  struct Config {
    int numActions = 0;
    std::vector<float> featMin;  ///< declared feature ranges (define d)
    std::vector<float> featMax;
    int extraInputs = 0;              ///< history features appended to states (not predicted)
    bool relativeTransitions = true;  ///< predict s'-s (--reltrans) or s' (--abstrans)
    bool episodic = true;             ///< learn a terminal forest
    RandomForest::Config forest;      ///< every forest's settings (m, w, f, combination)
  };

  /// Immutable view: thread-safe queries.
  class View : public rl_common::ModelView {
   public:
    /// The prediction with the external reward only (no intrinsic bonuses).
    rl_common::StateActionInfo query(const rl_common::State& input, int action) const override;
    /// query() and, into `*variance`, variance(): one descent of every tree for both (what
    /// a planner querying TEXPLORE-VANIR's bonuses needs; the same values as the two calls).
    rl_common::StateActionInfo query(const rl_common::State& input, int action,
                                     double* variance) const;
    /// Brings `info` up to date with this view (see rl_common::ModelView::refresh()).
    void refresh(const rl_common::State& input, int action, rl_common::StateActionInfo& info,
                 rl_common::PredictionStamp& stamp) const override {
      refresh(input, action, info, &stamp, nullptr);
    }
    /// refresh() and, into `*variance` (if not null), variance(), as query(input, action,
    /// variance) computes them. A null `stamp` recomputes everything (a plain query).
    void refresh(const rl_common::State& input, int action, rl_common::StateActionInfo& info,
                 rl_common::PredictionStamp* stamp, double* variance) const;
    /// D(s, a) above, in [0, ~1].
    double variance(const rl_common::State& input, int action) const;
    /// The distribution of feature j's prediction (relative change or absolute
    /// value).
    Distribution featureDistribution(const rl_common::State& input, int action,
                                     std::size_t feature) const;
    /// The same forests, each combined as `combination` (--taskcombo). Its revisions are this
    /// view's: do not refresh predictions of one from the other (query() it).
    std::shared_ptr<const View> recombined(Combination combination) const;
    /// Number of experiences learned when the view was taken.
    std::size_t numExperiences() const { return experiences_; }

   private:
    friend class FactoredModel;
    std::vector<float> treeInput(const rl_common::State& input, int action) const;
    std::shared_ptr<const Config> config_;
    std::vector<RandomForest::Snapshot> features_;
    RandomForest::Snapshot reward_;
    RandomForest::Snapshot terminal_;
    std::vector<std::uint64_t> revisions_;  ///< the features', the reward's, the terminal's
    std::size_t experiences_ = 0;
  };

  /// Throws std::invalid_argument on an inconsistent configuration.
  FactoredModel(const Config& config, std::uint64_t seed);
  /// Move-only: the forests share the input table.
  FactoredModel(const FactoredModel&) = delete;
  FactoredModel& operator=(const FactoredModel&) = delete;
  FactoredModel(FactoredModel&&) = default;
  FactoredModel& operator=(FactoredModel&&) = default;

  bool update(const std::vector<rl_common::Experience>& experiences) override;
  std::shared_ptr<const rl_common::ModelView> view() const override { return factoredView(); }
  std::shared_ptr<const View> factoredView() const;

  const Config& config() const { return *config_; }
  std::size_t numExperiences() const { return experiences_; }

 private:
  std::shared_ptr<const Config> config_;
  std::shared_ptr<C45Tree::InputTable> inputs_;  ///< x of every experience (before the forests)
  std::vector<RandomForest> features_;
  RandomForest reward_;
  RandomForest terminal_;
  /// Per forest (the features, the reward, the terminal), the revision of its predictions.
  std::vector<std::uint64_t> revisions_;
  std::size_t experiences_ = 0;
};

}  // namespace rl_agent
