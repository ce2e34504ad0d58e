#include "rl_agent/reward/region_error_reward.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace rl_agent {

namespace {

/// The immutable bonus of one snapshot: a value per region.
class RegionBonus : public IntrinsicReward {
 public:
  RegionBonus(std::string name, std::shared_ptr<const RandomRegions> regions,
              std::vector<double> bonus)
      : name_(std::move(name)), regions_(std::move(regions)), bonus_(std::move(bonus)) {}
  std::string name() const override { return name_; }
  void apply(const BonusContext& c, rl_common::StateActionInfo* info) const override {
    const double b = bonus_[static_cast<std::size_t>(regions_->regionOf(c.input))];
    if (b == 0.0) return;
    info->otherReward += static_cast<float>(b);
    info->reward += static_cast<float>(b);
  }

 private:
  std::string name_;
  std::shared_ptr<const RandomRegions> regions_;
  std::vector<double> bonus_;
};

double mean(std::deque<double>::const_iterator a, std::deque<double>::const_iterator b) {
  const auto n = std::distance(a, b);
  return n == 0 ? 0.0 : std::accumulate(a, b, 0.0) / static_cast<double>(n);
}

}  // namespace

RegionErrorReward::RegionErrorReward(const Config& config,
                                     std::shared_ptr<const RandomRegions> regions)
    : config_(config), regions_(std::move(regions)) {
  if (regions_ == nullptr || !(config.weight >= 0.0) || config.window < 2) {
    throw std::invalid_argument(
        "RegionErrorReward::RegionErrorReward(): need regions, weight >= 0 and window >= 2");
  }
  errors_.resize(static_cast<std::size_t>(regions_->size()));
}

double RegionErrorReward::predictionError(const rl_common::Experience& e,
                                          const rl_common::StateActionInfo& predicted) {
  if (e.terminal) return 1.0 - std::clamp(static_cast<double>(predicted.termProb), 0.0, 1.0);
  const auto close = [](float a, float b) { return std::fabs(a - b) <= 1e-4f; };
  double p = 0.0;
  if (!predicted.factored.empty()) {  // independent product of per-feature distributions
    p = predicted.factored.size() == e.next.size() ? 1.0 : 0.0;
    for (std::size_t j = 0; j < e.next.size() && p > 0.0; ++j) {
      double pj = 0.0;
      for (const auto& [value, q] : predicted.factored[j]) {
        if (close(value, e.next[j])) pj += q;
      }
      p *= pj;
    }
  } else {
    for (const auto& [next, prob] : predicted.transitions) {
      bool same = next.size() >= e.next.size();
      for (std::size_t j = 0; same && j < e.next.size(); ++j) same = close(next[j], e.next[j]);
      if (same) p += prob;
    }
  }
  return 1.0 - std::clamp(p, 0.0, 1.0);
}

void RegionErrorReward::observe(const rl_common::Experience& e,
                                const rl_common::StateActionInfo& predicted) {
  auto& curve = errors_[static_cast<std::size_t>(regions_->regionOf(e.s))];
  curve.push_back(predictionError(e, predicted));
  while (static_cast<int>(curve.size()) > config_.window) curve.pop_front();
}

double RegionErrorReward::interest(int region) const {
  const auto& curve = errors_.at(static_cast<std::size_t>(region));
  if (config_.kind == Kind::PredictionError) {
    return curve.empty() ? 1.0 : mean(curve.begin(), curve.end());
  }
  if (curve.size() < 2) return 0.0;
  const auto half = curve.begin() + static_cast<std::ptrdiff_t>(curve.size() / 2);
  return std::fabs(mean(curve.begin(), half) - mean(half, curve.end()));
}

std::shared_ptr<const IntrinsicReward> RegionErrorReward::snapshot() const {
  std::vector<double> bonus(errors_.size());
  for (std::size_t r = 0; r < bonus.size(); ++r) {
    bonus[r] = config_.weight * interest(static_cast<int>(r));
  }
  return std::make_shared<RegionBonus>(
      config_.kind == Kind::CompetenceProgress ? "competence" : "prederror", regions_,
      std::move(bonus));
}

}  // namespace rl_agent
