#include "rl_agent/agent/boltzmann_selector.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rl_agent {

std::vector<double> BoltzmannSelector::probabilities(const std::vector<double>& q, double tau) {
  if (q.empty() || !(tau > 0.0)) {
    throw std::invalid_argument("BoltzmannSelector::probabilities(): need values and tau > 0");
  }
  const double best = *std::max_element(q.begin(), q.end());
  std::vector<double> p(q.size());
  double sum = 0.0;
  for (std::size_t a = 0; a < q.size(); ++a) {
    p[a] = std::exp((q[a] - best) / tau);
    sum += p[a];
  }
  for (double& v : p) v /= sum;
  return p;
}

int BoltzmannSelector::sample(const std::vector<double>& q, double tau, rl_common::Random& rng) {
  const std::vector<double> p = probabilities(q, tau);
  double u = rng.uniform();
  for (std::size_t a = 0; a < p.size(); ++a) {
    if (u < p[a]) return static_cast<int>(a);
    u -= p[a];
  }
  return static_cast<int>(p.size()) - 1;
}

}  // namespace rl_agent
