#include "rl_agent/planner/policy_iteration.h"

#include <algorithm>
#include <cmath>

namespace rl_agent {

long PolicyIteration::solve(const rl_common::PlanningBudget& budget,
                            const std::vector<int>& /*changed*/) {
  const int n = static_cast<int>(states_.size());
  const int A = config_.numActions;
  // Current policy: greedy on the stored Q (warm start).
  policy_.resize(states_.size());
  for (int s = 0; s < n; ++s) {
    const auto& q = states_[static_cast<std::size_t>(s)].q;
    policy_[static_cast<std::size_t>(s)] =
        static_cast<int>(std::max_element(q.begin(), q.end()) - q.begin());
  }
  std::vector<double> v(states_.size());
  for (int s = 0; s < n; ++s) v[static_cast<std::size_t>(s)] = maxQ(s);
  auto evalBackup = [&](int s, int a) {
    const Node& node = states_[static_cast<std::size_t>(s)];
    const auto ai = static_cast<std::size_t>(a);
    double future = 0.0;
    for (const auto& succ : node.next[ai])
      future += succ.p * v[static_cast<std::size_t>(succ.state)];
    return node.reward[ai] + config_.gamma * node.continueProb[ai] * future;
  };
  long iterations = 0;
  while (allows(budget, iterations)) {
    // Policy evaluation.
    for (long sweep = 0; sweep < 100000; ++sweep) {
      double maxChange = 0.0;
      for (int s = 0; s < n; ++s) {
        if (!states_[static_cast<std::size_t>(s)].expanded) continue;
        const double value = evalBackup(s, policy_[static_cast<std::size_t>(s)]);
        maxChange = std::max(maxChange, std::fabs(value - v[static_cast<std::size_t>(s)]));
        v[static_cast<std::size_t>(s)] = value;
      }
      if (maxChange < config_.tolerance) break;
    }
    // Policy improvement.
    bool stable = true;
    for (int s = 0; s < n; ++s) {
      Node& node = states_[static_cast<std::size_t>(s)];
      if (!node.expanded) continue;
      for (int a = 0; a < A; ++a) node.q[static_cast<std::size_t>(a)] = evalBackup(s, a);
      int& pi = policy_[static_cast<std::size_t>(s)];
      const int best =
          static_cast<int>(std::max_element(node.q.begin(), node.q.end()) - node.q.begin());
      if (node.q[static_cast<std::size_t>(best)] >
          node.q[static_cast<std::size_t>(pi)] + config_.tolerance) {
        pi = best;
        stable = false;
      }
    }
    ++iterations;
    if (stable) break;
  }
  lastIterations_ = iterations;
  return iterations;
}

}  // namespace rl_agent
