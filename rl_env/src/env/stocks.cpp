#include "rl_env/env/stocks.h"

#include <stdexcept>

#include "env_detail.h"

namespace rl_env {

Stocks::Stocks(std::uint64_t seed, bool stochastic, int nsectors, int nstocks)
    : rng_(seed), stochastic_(stochastic), nsectors_(nsectors), nstocks_(nstocks) {
  if (nsectors <= 0 || nstocks <= 0) {
    throw std::invalid_argument("Stocks::Stocks(): nsectors and nstocks must be > 0, got " +
                                std::to_string(nsectors) + " and " + std::to_string(nstocks));
  }
  // One feature per sector (owned) and per stock (rising): agents learn a forest per feature.
  const long long features = static_cast<long long>(nsectors) * (nstocks + 1LL);
  if (features > kMaxFeatures) {
    throw std::invalid_argument("Stocks::Stocks(): " + std::to_string(nsectors) + " sectors of " +
                                std::to_string(nstocks) + " stocks make " +
                                std::to_string(features) + " features; at most " +
                                std::to_string(kMaxFeatures));
  }
  reset();
}

void Stocks::reset() {
  state_.assign(static_cast<std::size_t>(nsectors_ + nsectors_ * nstocks_), 0.0f);
  for (float& f : state_) f = rng_.bernoulli(0.5) ? 1.0f : 0.0f;
}

double Stocks::riseProbability(int sector) const {
  int rising = 0;
  for (int k = 0; k < nstocks_; ++k) {
    if (state_[static_cast<std::size_t>(risingIndex(sector, k))] > 0.5f) ++rising;
  }
  return 0.1 + 0.8 * static_cast<double>(rising) / nstocks_;
}

float Stocks::apply(int action) {
  detail::checkAction(action, numActions(), "Stocks::apply()");
  if (action < nsectors_) {
    float& owned = state_[static_cast<std::size_t>(ownedIndex(action))];
    owned = owned > 0.5f ? 0.0f : 1.0f;
  }
  std::vector<double> p(static_cast<std::size_t>(nsectors_));
  for (int s = 0; s < nsectors_; ++s) p[static_cast<std::size_t>(s)] = riseProbability(s);
  float reward = 0.0f;
  for (int s = 0; s < nsectors_; ++s) {
    const bool owned = state_[static_cast<std::size_t>(ownedIndex(s))] > 0.5f;
    for (int k = 0; k < nstocks_; ++k) {
      const double ps = p[static_cast<std::size_t>(s)];
      const bool rises = stochastic_ ? rng_.bernoulli(ps) : ps > 0.5;
      state_[static_cast<std::size_t>(risingIndex(s, k))] = rises ? 1.0f : 0.0f;
      if (owned) reward += rises ? 1.0f : -1.0f;
    }
  }
  return reward;
}

void Stocks::setState(const rl_common::State& s) {
  const char* where = "Stocks::setState()";
  detail::checkStateSize(s, state_.size(), where);
  for (std::size_t i = 0; i < s.size(); ++i) detail::integerFeature(s, i, 0, 1, where);
  state_ = s;
}

void Stocks::getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const {
  min->assign(state_.size(), 0.0f);
  max->assign(state_.size(), 1.0f);
}

void Stocks::getMinMaxReward(float* min, float* max) const {
  *max = static_cast<float>(nsectors_ * nstocks_);
  *min = -*max;
}

}  // namespace rl_env
