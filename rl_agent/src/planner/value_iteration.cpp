#include "rl_agent/planner/value_iteration.h"

#include <algorithm>
#include <cmath>

namespace rl_agent {

long ValueIteration::solve(const rl_common::PlanningBudget& budget,
                           const std::vector<int>& /*changed*/) {
  long sweeps = 0;
  const int A = config_.numActions;
  while (allows(budget, sweeps)) {
    double maxChange = 0.0;
    for (int s = 0; s < static_cast<int>(states_.size()); ++s) {
      if (!states_[static_cast<std::size_t>(s)].expanded) continue;
      for (int a = 0; a < A; ++a) {
        const double q = backup(s, a);
        double& old = states_[static_cast<std::size_t>(s)].q[static_cast<std::size_t>(a)];
        maxChange = std::max(maxChange, std::fabs(q - old));
        old = q;
      }
    }
    ++sweeps;
    if (maxChange < config_.tolerance) break;
  }
  lastSweeps_ = sweeps;
  return sweeps;
}

}  // namespace rl_agent
