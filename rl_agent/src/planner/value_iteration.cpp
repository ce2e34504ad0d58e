#include "rl_agent/planner/value_iteration.h"

#include <algorithm>
#include <cmath>

namespace rl_agent {

long ValueIteration::solve(const rl_common::PlanningBudget& budget,
                           const std::vector<int>& /*changed*/) {
  long sweeps = 0;
  const int A = config_.numActions;
  // max_a Q(s, a) of every state, kept current after each backup: the same in-place
  // (Gauss-Seidel) sweep as recomputing it per successor, without the repeated scans.
  std::vector<double> values(states_.size());
  for (std::size_t s = 0; s < states_.size(); ++s) values[s] = maxQ(static_cast<int>(s));
  while (allows(budget, sweeps)) {
    double maxChange = 0.0;
    for (int s = 0; s < static_cast<int>(states_.size()); ++s) {
      auto& q = states_[static_cast<std::size_t>(s)].q;
      if (!states_[static_cast<std::size_t>(s)].expanded) continue;
      for (int a = 0; a < A; ++a) {
        const double backedUp = backup(s, a, values);
        double& old = q[static_cast<std::size_t>(a)];
        maxChange = std::max(maxChange, std::fabs(backedUp - old));
        old = backedUp;
        values[static_cast<std::size_t>(s)] = *std::max_element(q.begin(), q.end());
      }
    }
    ++sweeps;
    if (maxChange < config_.tolerance) break;
  }
  lastSweeps_ = sweeps;
  return sweeps;
}

}  // namespace rl_agent
