/**
 * Stocks: the factored stock-trading domain of Strehl, Diuk & Littman, "Efficient structure
 * learning in factored-state MDPs", AAAI 2007, as the original package's Stocks (shared/spec/
 * ORIGINAL.md §8).
 *
 * There are S sectors (--nsectors) of N stocks each (--nstocks). State (S + S·N binary
 * features): first whether each sector is owned, then whether each stock is rising, sector by
 * sector. Actions 0..S−1 flip ownership of that sector; action S does nothing. Then every stock
 * moves: it rises with probability 0.1 + 0.8·(fraction of its sector rising before the step)
 * (deterministic mode: it rises if that probability exceeds 0.5). The reward counts, over the
 * sectors owned after the action, +1 per stock now rising and −1 per stock now falling.
 * Non-episodic; random start (every feature a fair coin).
 */
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rl_common/environment.h"
#include "rl_common/random.h"

namespace rl_env {

class Stocks : public rl_common::Environment {
 public:
  /// The most features (sectors x (stocks + 1)) a task may have: the agents' limit for a
  /// description (rl_agent::kMaxDescribedFeatures).
  static constexpr long long kMaxFeatures = 65536;
  /// Throws std::invalid_argument unless both counts are positive and the task has at most
  /// kMaxFeatures features.
  Stocks(std::uint64_t seed, bool stochastic, int nsectors, int nstocks);

  // rl_common::Environment
  const rl_common::State& sensation() const override { return state_; }
  float apply(int action) override;
  bool terminal() const override { return false; }
  void reset() override;
  int numActions() const override { return nsectors_ + 1; }
  void getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const override;
  void getMinMaxReward(float* min, float* max) const override;
  bool isEpisodic() const override { return false; }
  std::string name() const override { return "Stocks"; }
  bool isStochastic() const override { return stochastic_; }

  /// Sets the state: S + S·N features, each 0 or 1. Throws std::invalid_argument otherwise.
  void setState(const rl_common::State& s);

  int numSectors() const { return nsectors_; }
  int stocksPerSector() const { return nstocks_; }
  /// Index of the ownership feature of `sector` and of the rising feature of a stock.
  int ownedIndex(int sector) const { return sector; }
  int risingIndex(int sector, int stock) const { return nsectors_ + sector * nstocks_ + stock; }
  /// The probability that a stock of `sector` rises at the next step, given the state.
  double riseProbability(int sector) const;

 private:
  rl_common::Random rng_;
  bool stochastic_;
  int nsectors_;
  int nstocks_;
  rl_common::State state_;
};

}  // namespace rl_env
