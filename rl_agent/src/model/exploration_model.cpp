#include "rl_agent/model/exploration_model.h"

namespace rl_agent {

ExplorationModel::ExplorationModel(const FactoredModel::Config& config, std::uint64_t seed,
                                   Rewards rewards)
    : model_(config, seed),
      visited_(config.numActions, config.featMin, config.featMax),
      rewards_(std::make_shared<const Rewards>(std::move(rewards))) {}

bool ExplorationModel::update(const std::vector<rl_common::Experience>& experiences) {
  const bool changed = model_.update(experiences);  // validates the experiences first
  for (const auto& e : experiences) visited_.add(e.s, e.action);
  return changed || !experiences.empty();  // novelty changes with every experience
}

std::shared_ptr<const ExplorationModel::View> ExplorationModel::explorationView() const {
  auto v = std::make_shared<View>();
  v->model_ = model_.factoredView();
  v->visited_ = visited_.snapshot();
  if (enabled_ && !rewards_->empty()) v->rewards_ = rewards_;
  return v;
}

rl_common::StateActionInfo ExplorationModel::View::query(const rl_common::State& input,
                                                         int action) const {
  rl_common::StateActionInfo info = model_->query(input, action);
  if (rewards_ == nullptr) return info;
  const BonusContext context{*model_, visited_, input, action};
  for (const auto& r : *rewards_) r->apply(context, &info);
  return info;
}

}  // namespace rl_agent
