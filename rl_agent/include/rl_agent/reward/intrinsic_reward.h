/**
 * IntrinsicReward: one weighted exploration bonus added to a model's predicted
 * reward, so a planner is drawn to where the bonus is high (TEXPLORE-VANIR
 * paper §4.2; the original's ExplorationModel, shared/spec/ORIGINAL.md §5).
 * Each bonus is its own component; an ExplorationModel applies a list of them
 * to every query, recording each part in the prediction's reward breakdown.
 */
#pragma once

#include <string>

#include "rl_agent/model/factored_model.h"
#include "rl_agent/model/novelty_index.h"
#include "rl_common/mdp_model.h"

namespace rl_agent {

/// What a bonus may look at for one query.
struct BonusContext {
  const FactoredModel::View& model;       ///< the learned model (external reward only)
  const NoveltyIndex::Snapshot& visited;  ///< visited state-actions
  const rl_common::State& input;          ///< queried state (plus history features)
  int action;
  /// model.variance(input, action) when it was computed with the prediction, else null.
  const double* variance = nullptr;
};

class IntrinsicReward {
 public:
  virtual ~IntrinsicReward() = default;
  /// Short name for logs, e.g. "variance".
  virtual std::string name() const = 0;
  /// Adds the bonus to `info` (reward and the matching breakdown field).
  /// Thread-safe.
  virtual void apply(const BonusContext& context, rl_common::StateActionInfo* info) const = 0;
  /// True if apply() reads the model's variance: the model then computes it with the
  /// prediction, from the same descent of its trees.
  virtual bool usesVariance() const { return false; }
};

}  // namespace rl_agent
