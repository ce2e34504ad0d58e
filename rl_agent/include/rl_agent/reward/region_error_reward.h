/**
 * RegionErrorReward: the paper's two R-IAC-style comparison explorers on the TEXPLORE model
 * (TEXPLORE-VANIR paper §5.1; Baranes & Oudeyer, "R-IAC", IEEE TAMD 1(3), 2009).
 *
 * The state space is split into random regions at the start (RandomRegions). For every
 * experience (s, a, r, s') the model's prediction error, made before the model learns it, is
 *
 *   e = 1 − P̂(s' | s, a)         (the total-variation distance between the predicted
 *                                  next-state distribution and the observed outcome),
 *   e = 1 − P̂(terminal | s, a)   for a terminal experience,
 *
 * and is appended to the error curve of s's region (the last `window` errors are kept). With
 * E_old and E_new the mean errors of the older and newer halves of that window:
 *
 *   competence  (competence progress, R-IAC's interest): bonus(s,a) = w · |E_old − E_new|
 *               (0 with fewer than 2 errors);
 *   prederror   (prediction error): bonus(s,a) = w · mean(window)  (w · 1 for a region
 *               without any experience yet: nothing is predicted there).
 *
 * The bonus depends on the region of s only and goes into the prediction's `otherReward`.
 */
#pragma once

#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "rl_agent/reward/learned_reward.h"
#include "rl_agent/reward/random_regions.h"

namespace rl_agent {

class RegionErrorReward : public LearnedReward {
 public:
  enum class Kind { CompetenceProgress, PredictionError };
  struct Config {
    Kind kind = Kind::CompetenceProgress;
    double weight = 1.0;  ///< w
    int window = 20;      ///< errors kept per region (ζ)
  };

  /// Throws std::invalid_argument for a null partition, weight < 0 or window < 2.
  RegionErrorReward(const Config& config, std::shared_ptr<const RandomRegions> regions);

  void observe(const rl_common::Experience& e,
               const rl_common::StateActionInfo& predicted) override;
  std::shared_ptr<const IntrinsicReward> snapshot() const override;

  /// The error e above.
  static double predictionError(const rl_common::Experience& e,
                                const rl_common::StateActionInfo& predicted);
  /// The unweighted bonus of a region (interest or mean error).
  double interest(int region) const;
  const RandomRegions& regions() const { return *regions_; }

 private:
  Config config_;
  std::shared_ptr<const RandomRegions> regions_;
  std::vector<std::deque<double>> errors_;
};

}  // namespace rl_agent
