#include "rl_agent/model/exploration_model.h"

namespace rl_agent {

ExplorationModel::ExplorationModel(const FactoredModel::Config& config, std::uint64_t seed,
                                   Rewards rewards, Learners learners)
    : model_(config, seed),
      visited_(config.numActions, config.featMin, config.featMax),
      rewards_(std::make_shared<const Rewards>(std::move(rewards))),
      learners_(std::move(learners)) {}

bool ExplorationModel::update(const std::vector<rl_common::Experience>& experiences) {
  if (!learners_.empty() && !experiences.empty()) {
    const auto before = model_.factoredView();
    for (const auto& e : experiences) {
      const rl_common::StateActionInfo predicted = before->query(e.s, e.action);
      for (const auto& l : learners_) l->observe(e, predicted);
    }
  }
  const bool changed = model_.update(experiences);  // validates the experiences first
  for (const auto& e : experiences) visited_.add(e.s, e.action);
  return changed || !experiences.empty();  // novelty changes with every experience
}

std::shared_ptr<const ExplorationModel::View> ExplorationModel::explorationView() const {
  auto v = std::make_shared<View>();
  v->model_ = model_.factoredView();
  v->visited_ = visited_.snapshot();
  if (enabled_ && !learners_.empty()) {
    auto all = std::make_shared<Rewards>(*rewards_);
    for (const auto& l : learners_) all->push_back(l->snapshot());
    v->rewards_ = std::move(all);
  } else if (enabled_ && !rewards_->empty()) {
    v->rewards_ = rewards_;
  }
  if (v->rewards_) {
    for (const auto& r : *v->rewards_) v->needsVariance_ = v->needsVariance_ || r->usesVariance();
  }
  return v;
}

rl_common::StateActionInfo ExplorationModel::View::query(const rl_common::State& input,
                                                         int action) const {
  rl_common::StateActionInfo info;
  fill(input, action, info, nullptr);
  return info;
}

void ExplorationModel::View::refresh(const rl_common::State& input, int action,
                                     rl_common::StateActionInfo& info,
                                     rl_common::PredictionStamp& stamp) const {
  fill(input, action, info, &stamp);
}

void ExplorationModel::View::fill(const rl_common::State& input, int action,
                                  rl_common::StateActionInfo& info,
                                  rl_common::PredictionStamp* stamp) const {
  const bool needVariance = rewards_ != nullptr && needsVariance_;  // decided once per view
  double variance = 0.0;
  model_->refresh(input, action, info, stamp, needVariance ? &variance : nullptr);
  if (rewards_ == nullptr) return;
  const BonusContext context{*model_, visited_, input, action, needVariance ? &variance : nullptr};
  for (const auto& r : *rewards_) r->apply(context, &info);
}

}  // namespace rl_agent
