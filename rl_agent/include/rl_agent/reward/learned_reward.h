/**
 * LearnedReward: an intrinsic reward that learns from the agent's experience, such as the
 * paper's competence-progress and prediction-error comparison methods (TEXPLORE-VANIR paper
 * §5.1). An ExplorationModel shows it every experience together with the model's prediction
 * for that state-action made before learning it; each model view then applies an immutable
 * snapshot of the bonus, so views stay thread-safe while learning goes on.
 */
#pragma once

#include <memory>

#include "rl_agent/reward/intrinsic_reward.h"
#include "rl_common/experience.h"
#include "rl_common/mdp_model.h"

namespace rl_agent {

class LearnedReward {
 public:
  virtual ~LearnedReward() = default;
  /// Learns from `e`, which the model predicted as `predicted` before learning it. Called by
  /// the model-learning thread only.
  virtual void observe(const rl_common::Experience& e,
                       const rl_common::StateActionInfo& predicted) = 0;
  /// The bonus as learned so far (immutable, thread-safe).
  virtual std::shared_ptr<const IntrinsicReward> snapshot() const = 0;
};

}  // namespace rl_agent
