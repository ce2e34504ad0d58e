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

#include <memory>
#include <utility>
#include <vector>

#include "rl_common/experience.h"

namespace rl_common {

/// A model's prediction for one state-action.
struct StateActionInfo {
  /// Absolute next states with their probabilities (summing to 1 when known).
  std::vector<std::pair<State, double>> transitions;
  float reward = 0.0f;    ///< predicted reward, intrinsic bonuses included
  float termProb = 0.0f;  ///< probability that the transition is terminal
  bool known = false;     ///< false when the model has no data for this state-action
  /// The reward's parts (reward = external + variance + novelty + other).
  float externalReward = 0.0f;
  float varianceReward = 0.0f;
  float noveltyReward = 0.0f;
  float otherReward = 0.0f;
};

class ModelView {
 public:
  virtual ~ModelView() = default;
  /// Prediction for taking `action` in `input` (a state, possibly followed by history
  /// features). Thread-safe.
  virtual StateActionInfo query(const State& input, int action) const = 0;
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
