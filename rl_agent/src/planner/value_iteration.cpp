#include "rl_agent/planner/value_iteration.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rl_agent {

long ValueIteration::solve(const rl_common::PlanningBudget& budget,
                           const std::vector<int>& /*changed*/) {
  long sweeps = 0;
  const auto As = static_cast<std::size_t>(config_.numActions);
  // max_a Q(s, a) of every state, kept current after each backup: the same in-place
  // (Gauss-Seidel) sweep as recomputing it per successor, without the repeated scans.
  std::vector<double> values(states_.size());
  for (std::size_t s = 0; s < states_.size(); ++s) values[s] = maxQ(static_cast<int>(s));
  // Q(s,a) = base_a + loop_a V(s): the rest of the backup, and γ(1 − T) P(s|s,a).
  std::vector<double> base(As), loop(As);
  while (allows(budget, sweeps)) {
    double maxChange = 0.0;
    for (int s = 0; s < static_cast<int>(states_.size()); ++s) {
      const auto si = static_cast<std::size_t>(s);
      Node& n = states_[si];
      if (!n.expanded) continue;
      // V(s) solved exactly given the other states' values: the fixed point of
      // V = max_a (base_a + loop_a V) is max_a base_a / (1 − loop_a), as loop_a ≤ γ < 1. A plain
      // backup shrinks a self-loop's error only by loop_a a sweep (a no-op PRESS, a move into
      // a wall), which at γ 0.99 took hundreds of sweeps.
      double v = -std::numeric_limits<double>::infinity();
      for (std::size_t a = 0; a < As; ++a) {
        double other = 0.0, self = 0.0;
        for (const auto& succ : n.next[a]) {
          if (succ.state == s) {
            self += succ.p;
          } else {
            other += succ.p * values[static_cast<std::size_t>(succ.state)];
          }
        }
        const double discount = config_.gamma * n.continueProb[a];
        base[a] = n.reward[a] + discount * other;
        loop[a] = discount * self;
        v = std::max(v, base[a] / (1.0 - loop[a]));
      }
      for (std::size_t a = 0; a < As; ++a) {
        const double backedUp = base[a] + loop[a] * v;
        maxChange = std::max(maxChange, std::fabs(backedUp - n.q[a]));
        n.q[a] = backedUp;
      }
      values[si] = *std::max_element(n.q.begin(), n.q.end());
    }
    ++sweeps;
    if (maxChange < config_.tolerance) break;
  }
  lastSweeps_ = sweeps;
  return sweeps;
}

}  // namespace rl_agent
