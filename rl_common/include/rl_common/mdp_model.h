/**
 * MDPModel and ModelView: a learned model of an MDP, split into a learning side and immutable
 * views for planning.
 *
 * The learner (MDPModel) is updated with experiences by one thread. view() returns an
 * immutable ModelView of the model as it is now: const queries on it are safe from any thread
 * while the learner keeps learning, and obtaining one must not deep-copy the model (views
 * share structure with the learner). Planners query views only.
 *
 * A query input may be longer than the state: with an action history (the original's
 * --history), the planner appends the history features to the state, as the model was trained.
 */
#pragma once

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "rl_common/experience.h"

namespace rl_common {

/// One feature's predicted next values: (absolute value, probability) pairs.
using FeatureDistribution = std::vector<std::pair<float, double>>;

/// A model's prediction for one state-action.
///
/// The next-state distribution comes in one of two forms: `transitions` lists absolute next
/// states with their probabilities (tabular models), or `factored` gives one distribution per
/// feature whose independent product is the next-state distribution (TEXPLORE's factored
/// forests, whose product can have far too many outcomes to list). Exactly one of them is
/// non-empty for a known prediction. Use sampleNextState(), transitionProbability() or
/// expandTransitions() below to read either form.
struct StateActionInfo {
  /// Absolute next states with their probabilities (summing to 1 when known).
  std::vector<std::pair<State, double>> transitions;
  /// Per-feature distributions of the next state's absolute values (independent product).
  std::vector<FeatureDistribution> factored;
  float reward = 0.0f;    ///< predicted reward, intrinsic bonuses included
  float termProb = 0.0f;  ///< probability that the transition is terminal
  bool known = false;     ///< false when the model has no data for this state-action
  /// The reward's parts (reward = external + variance + novelty + other).
  float externalReward = 0.0f;
  float varianceReward = 0.0f;
  float noveltyReward = 0.0f;
  float otherReward = 0.0f;
};

/// P(next | info): the listed probability, or the product of the per-feature probabilities.
inline double transitionProbability(const StateActionInfo& info, const State& next) {
  if (!info.factored.empty()) {
    if (next.size() != info.factored.size()) return 0.0;
    double p = 1.0;
    for (std::size_t j = 0; j < next.size() && p > 0.0; ++j) {
      double pj = 0.0;
      for (const auto& [value, q] : info.factored[j]) {
        if (value == next[j]) pj += q;
      }
      p *= pj;
    }
    return p;
  }
  double p = 0.0;
  for (const auto& [s, q] : info.transitions) {
    if (s == next) p += q;
  }
  return p;
}

/// The next-state distribution as an explicit list. A factored prediction is expanded into
/// its product, dropping combinations below `minProbability` and renormalising (the most
/// probable combination is always kept).
inline std::vector<std::pair<State, double>> expandTransitions(const StateActionInfo& info,
                                                               double minProbability = 1e-6) {
  if (info.factored.empty()) return info.transitions;
  std::vector<std::pair<State, double>> partial{{State(), 1.0}};
  for (const FeatureDistribution& dist : info.factored) {
    std::vector<std::pair<State, double>> next;
    std::pair<State, double> best{State(), -1.0};
    for (const auto& [prefix, p] : partial) {
      for (const auto& [value, q] : dist) {
        if (p * q < minProbability) {
          if (p * q > best.second) {
            best = {prefix, p * q};
            best.first.push_back(value);
          }
          continue;
        }
        State s = prefix;
        s.push_back(value);
        next.emplace_back(std::move(s), p * q);
      }
    }
    if (next.empty() && best.second >= 0.0) next.push_back(std::move(best));
    partial = std::move(next);
  }
  double total = 0.0;
  for (const auto& o : partial) total += o.second;
  if (total > 0.0) {
    for (auto& o : partial) o.second /= total;
  }
  return partial;
}

/// What a view records with a prediction so that a later view of the same model can tell which
/// parts of it still hold (see ModelView::refresh()). Opaque to planners; empty: nothing known.
struct PredictionStamp {
  std::vector<std::uint64_t> revisions;  ///< per part of the model, the revision it came from
  std::vector<double> parts;             ///< per part, values the view needs again (variances)
  void clear() {
    revisions.clear();
    parts.clear();
  }
};

class ModelView {
 public:
  virtual ~ModelView() = default;
  /// Prediction for taking `action` in `input` (a state, possibly followed by history
  /// features). Thread-safe.
  virtual StateActionInfo query(const State& input, int action) const = 0;
  /// Makes `info` exactly what query(input, action) returns, where `info` and `stamp` are empty
  /// or what an earlier refresh() of the same input and action, on this view or on any other
  /// view, left there. A view of a learned model recomputes only the parts of the model that
  /// changed since `stamp` (a planner that caches predictions across model versions re-reads
  /// one forest of a changed tree instead of all of them); this default queries again.
  /// Thread-safe.
  virtual void refresh(const State& input, int action, StateActionInfo& info,
                       PredictionStamp& stamp) const {
    info = query(input, action);
    stamp.clear();
  }
};

class MDPModel {
 public:
  virtual ~MDPModel() = default;
  /// Learns from experiences; returns true if the model's predictions may have changed.
  virtual bool update(const std::vector<Experience>& experiences) = 0;
  /// An immutable view of the model as it is now (cheap; shares structure).
  virtual std::shared_ptr<const ModelView> view() const = 0;
};

}  // namespace rl_common
