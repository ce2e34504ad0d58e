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
  factor_.assign(d, 0.0f);
  for (std::size_t j = 0; j < d; ++j) {
    const int n = statesPerDim.size() == 1 ? statesPerDim[0] : statesPerDim[j];
    if (n < 0) {
      throw std::invalid_argument("DiscretizationAgent::DiscretizationAgent(): negative --nstates");
    }
    if (n > 0) factor_[j] = (featMax[j] - featMin[j]) / static_cast<float>(n);
  }
}

rl_common::State DiscretizationAgent::discretize(const rl_common::State& s) const {
  if (s.size() != factor_.size()) {
    throw std::invalid_argument("DiscretizationAgent::discretize(): state has " +
                                std::to_string(s.size()) + " features, expected " +
                                std::to_string(factor_.size()));
  }
  rl_common::State out(s);
  for (std::size_t j = 0; j < s.size(); ++j) {
    const float f = factor_[j];
    if (f <= 0.0f) continue;
    const int bin = s[j] > 0.0f ? static_cast<int>((s[j] + f / 2.0f) / f)
                                : static_cast<int>((s[j] - f / 2.0f) / f);
    out[j] = f * static_cast<float>(bin);
  }
  return out;
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
