/**
 * BoltzmannSelector: softmax ("Boltzmann") action selection with temperature τ (Sutton & Barto
 * 2018, §2.8/§13.1; the paper's Boltzmann comparison agent with τ = 0.2, TEXPLORE-VANIR paper
 * §5.1, Fig. 7):
 *
 *   P(a) = exp((Q(a) − max Q) / τ) / Σ_b exp((Q(b) − max Q) / τ)
 *
 * (shifted by max Q for numerical safety; the probabilities are unchanged).
 */
#pragma once

#include <vector>

#include "rl_common/random.h"

namespace rl_agent {

class BoltzmannSelector {
 public:
  /// The probabilities above. Throws std::invalid_argument for τ <= 0 or no values.
  static std::vector<double> probabilities(const std::vector<double>& q, double tau);
  /// An action drawn from probabilities(q, tau).
  static int sample(const std::vector<double>& q, double tau, rl_common::Random& rng);
};

}  // namespace rl_agent
