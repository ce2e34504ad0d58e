/**
 * ExplorationModel: a FactoredModel plus the record of visited state-actions,
 * whose views add intrinsic rewards to every prediction (the original's
 * ExplorationModel wrapper, shared/spec/ORIGINAL.md §5.1, §5.4): the planner
 * sees R^(s,a) = E[reward forest] + sum_k bonus_k(s,a), e.g. TEXPLORE-VANIR's
 * v*D(s,a) + n*delta(s,a), with each part kept in the prediction's reward
 * breakdown. Intrinsic rewards can be switched off (the task phase of the
 * paper's experiments) without losing what was learned.
 */
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "rl_agent/model/factored_model.h"
#include "rl_agent/model/novelty_index.h"
#include "rl_agent/reward/intrinsic_reward.h"
#include "rl_agent/reward/learned_reward.h"

namespace rl_agent {

class ExplorationModel : public rl_common::MDPModel {
 public:
  using Rewards = std::vector<std::shared_ptr<const IntrinsicReward>>;
  /// Bonuses that learn from prediction errors (see LearnedReward).
  using Learners = std::vector<std::shared_ptr<LearnedReward>>;

  /// Immutable view: the model's prediction plus the bonuses. Thread-safe.
  class View : public rl_common::ModelView {
   public:
    rl_common::StateActionInfo query(const rl_common::State& input, int action) const override;
    /// The model's part through FactoredModel::View::refresh() (only changed forests are
    /// re-read); the bonuses are applied afresh, as query() does (novelty changes with every
    /// experience, and a bonus costs a fraction of a forest query).
    void refresh(const rl_common::State& input, int action, rl_common::StateActionInfo& info,
                 rl_common::PredictionStamp& stamp) const override;
    const FactoredModel::View& model() const { return *model_; }
    const NoveltyIndex::Snapshot& visited() const { return visited_; }

   private:
    friend class ExplorationModel;
    /// query() (null stamp) and refresh(): the model's part, then the bonuses.
    void fill(const rl_common::State& input, int action, rl_common::StateActionInfo& info,
              rl_common::PredictionStamp* stamp) const;
    std::shared_ptr<const FactoredModel::View> model_;
    NoveltyIndex::Snapshot visited_;
    std::shared_ptr<const Rewards> rewards_;  ///< null when intrinsic rewards are off
    bool needsVariance_ = false;              ///< some reward reads the model's variance
  };

  ExplorationModel(const FactoredModel::Config& config, std::uint64_t seed, Rewards rewards,
                   Learners learners = {});

  /// Learns the model and records each (s, a) as visited (seeds and terminal
  /// ones too). Learned rewards first see each experience with the model's prediction
  /// for it from before this update.
  bool update(const std::vector<rl_common::Experience>& experiences) override;
  std::shared_ptr<const rl_common::ModelView> view() const override { return explorationView(); }
  std::shared_ptr<const View> explorationView() const;

  /// Turns the intrinsic rewards on or off for the views taken from now on.
  void setIntrinsicEnabled(bool enabled) { enabled_ = enabled; }
  bool intrinsicEnabled() const { return enabled_; }
  const FactoredModel& model() const { return model_; }
  const Rewards& rewards() const { return *rewards_; }

 private:
  FactoredModel model_;
  NoveltyIndex visited_;
  std::shared_ptr<const Rewards> rewards_;
  Learners learners_;
  std::atomic<bool> enabled_{true};  ///< set by the acting thread, read by the learner
};

}  // namespace rl_agent
