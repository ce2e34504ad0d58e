#include "rl_agent/agent/discretization_agent.h"

#include <stdexcept>

namespace rl_agent {

DiscretizationAgent::DiscretizationAgent(std::unique_ptr<rl_common::Agent> inner,
                                         std::vector<int> statesPerDim, std::vector<float> featMin,
                                         std::vector<float> featMax)
    : inner_(std::move(inner)) {
  if (inner_ == nullptr) {
    throw std::invalid_argument("DiscretizationAgent::DiscretizationAgent(): null agent");
  }
  const std::size_t d = featMin.size();
  if (featMax.size() != d || statesPerDim.empty() ||
      (statesPerDim.size() != 1 && statesPerDim.size() != d)) {
    throw std::invalid_argument(
        "DiscretizationAgent::DiscretizationAgent(): need one bin count, or one per feature, "
        "and matching feature ranges");
  }
  for (int n : statesPerDim) {
    if (n < 0) {
      throw std::invalid_argument("DiscretizationAgent::DiscretizationAgent(): negative --nstates");
    }
  }
  grid_ = StateGrid(statesPerDim, featMin, featMax);
}

rl_common::State DiscretizationAgent::discretize(const rl_common::State& s) const {
  if (s.size() != grid_.size()) {
    throw std::invalid_argument("DiscretizationAgent::discretize(): state has " +
                                std::to_string(s.size()) + " features, expected " +
                                std::to_string(grid_.size()));
  }
  return grid_.apply(s);
}

int DiscretizationAgent::firstAction(const rl_common::State& s) {
  return inner_->firstAction(discretize(s));
}

int DiscretizationAgent::nextAction(float reward, const rl_common::State& s) {
  return inner_->nextAction(reward, discretize(s));
}

void DiscretizationAgent::seedExperiences(const std::vector<rl_common::Experience>& seeds) {
  std::vector<rl_common::Experience> binned = seeds;
  for (auto& e : binned) {
    e.s = discretize(e.s);
    e.next = discretize(e.next);
  }
  inner_->seedExperiences(binned);
}

RewardBreakdown DiscretizationAgent::lastRewardBreakdown() const {
  const auto* src = dynamic_cast<const RewardBreakdownSource*>(inner_.get());
  return src != nullptr ? src->lastRewardBreakdown() : RewardBreakdown{};
}

}  // namespace rl_agent
