/**
 * Model accuracy: how far a learned model's next-state predictions are from the true dynamics
 * (the TEXPLORE-VANIR paper §5.1, Fig. 4).
 *
 * For a state-action (s, a) with true next-state distribution P and predicted distribution Q,
 * the variational (total-variation) distance is
 *     TV(P, Q) = 1/2 * sum_{s'} |P(s') - Q(s')|,
 * over the union of both supports; it is 0 for identical distributions and 1 for disjoint ones.
 * The accuracy of a model is the mean TV over `samples` state-actions drawn uniformly (states
 * uniformly from the environment's reachable states, actions uniformly), as in the paper
 * (5000 samples every 25 steps). Distributions are compared on absolute next states; equal
 * states are merged before comparing. A factored prediction (one distribution per feature, whose
 * product can have millions of outcomes) is compared without expanding it: with P the true and
 * Q the predicted distribution,
 *     sum_{s'} |P(s') - Q(s')| = sum_{s' in supp P} |P(s') - Q(s')| + (|Q| - sum_{s' in supp P}
 * Q(s')), where |Q| is Q's total mass (1 for a normalised prediction).
 *
 * Beside the joint distance, evaluateDetailed() gives each feature's marginal distance
 * TV(P_j, Q_j) over the same samples. The joint distance of a factored model compounds its
 * features' errors (roughly 1 - prod_j (1 - TV_j)), so the marginals show which features carry
 * the error; and the joint distance per action shows which actions do.
 *
 * Cost: the paper's 5000 samples every 25 steps are as many model queries as the planner's
 * own. LightWorld has a few hundred reachable states, so the samples repeat: each state-action
 * drawn is measured once per measurement, and its prediction is kept between measurements and
 * brought up to date with ModelView::refresh() (a learned model re-reads only the forests that
 * changed). The figures are the ones a query per sample gives, to the last bit.
 */
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "rl_common/experience.h"
#include "rl_common/mdp_model.h"
#include "rl_common/random.h"
#include "rl_common/true_model.h"

namespace rl_experiment {

/// A distribution over next states (probabilities need not be merged per state).
using StateDistribution = std::vector<std::pair<rl_common::State, double>>;

/// 1/2 * L1 distance between two distributions over states, in [0, 1] when both sum to 1.
double variationalDistance(const StateDistribution& p, const StateDistribution& q);

/// The same between a true distribution `p` and a model's prediction (listed or factored).
double variationalDistance(const StateDistribution& p, const rl_common::StateActionInfo& q);

/// The true next-state distribution of an outcome list (rewards and terminal flags dropped).
StateDistribution nextStateDistribution(const std::vector<rl_common::Outcome>& outcomes);

/// Marginal distance of one feature: 1/2 * sum_v |P(s'_j = v) - Q(s'_j = v)|.
double marginalDistance(const StateDistribution& p, const rl_common::StateActionInfo& q,
                        std::size_t feature);

/// Mean variational distance between a learned model and the true dynamics.
class ModelAccuracy {
 public:
  /// `truth` must outlive this object; its reachable states are listed once here. Throws
  /// std::invalid_argument if there are none or `numActions` < 1.
  ModelAccuracy(const rl_common::TrueModel& truth, int numActions);

  /// Mean TV over `samples` state-actions drawn with `rng`. Throws std::invalid_argument if
  /// samples < 1. Not const: it keeps the predictions it made for the next measurement.
  double evaluate(const rl_common::ModelView& model, rl_common::Random& rng, int samples);

  /// One measurement in detail: the joint mean (evaluate() returns it),
  /// each feature's mean marginal distance, and the joint mean per action (NaN for an action
  /// not drawn).
  struct Report {
    double joint = 0.0;
    std::vector<double> marginal;   ///< one per state feature
    std::vector<double> perAction;  ///< one per action
    /// Joint distance per group of the sampled states, grouped by the values of the features
    /// given to evaluateDetailed() (e.g. LightWorld's room and have_key): the group's name
    /// ("f4=1 f2=0"), then the sum of distances and the number of samples.
    std::map<std::string, std::pair<double, int>> groups;
  };
  /// `groupBy`: feature indices whose values group the samples (empty: no groups); throws
  /// std::invalid_argument for an index out of range.
  Report evaluateDetailed(const rl_common::ModelView& model, rl_common::Random& rng, int samples,
                          const std::vector<int>& groupBy = {});

  std::size_t numReachableStates() const { return states_.size(); }

  /// Above this many state-actions, predictions are not kept between measurements (memory).
  static constexpr std::size_t kMaxKept = 100000;

 private:
  /// One state-action's true distribution, and its last measurement.
  struct Kept {
    bool truthKnown = false;
    StateDistribution truth;
    std::uint64_t measured = 0;  ///< the measurement that computed the fields below (0: none)
    rl_common::StateActionInfo prediction;
    rl_common::PredictionStamp stamp;
    double joint = 0.0;
    std::vector<double> marginal;
  };
  /// Kept entry of state `state` and action `action`, brought up to this measurement.
  const Kept& measure(const rl_common::ModelView& model, std::size_t state, int action);

  const rl_common::TrueModel& truth_;
  int numActions_;
  std::vector<rl_common::State> states_;
  std::vector<Kept> kept_;  ///< state-major, empty above kMaxKept
  Kept scratch_;            ///< the entry used when nothing is kept
  std::uint64_t measurement_ = 0;
};

}  // namespace rl_experiment
