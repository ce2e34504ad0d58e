#include "rl_agent/planner/prioritized_sweeping.h"

#include <cmath>
#include <queue>
#include <utility>

namespace rl_agent {

long PrioritizedSweeping::solve(const rl_common::PlanningBudget& budget,
                                const std::vector<int>& changed) {
  const int n = static_cast<int>(states_.size());
  const int A = config_.numActions;
  priority_.resize(states_.size(), 0.0);
  if (!changed.empty()) {
    // Predecessor lists of the current predictions (max probability over actions).
    preds_.assign(states_.size(), {});
    for (int s = 0; s < n; ++s) {
      const Node& node = states_[static_cast<std::size_t>(s)];
      if (!node.expanded) continue;
      for (const auto& succ : node.next) {
        for (const auto& t : succ) preds_[static_cast<std::size_t>(t.state)].push_back({s, t.p});
      }
    }
  }
  using Item = std::pair<double, int>;
  std::priority_queue<Item> queue;
  auto push = [&](int s, double p) {
    if (p > config_.tolerance && p > priority_[static_cast<std::size_t>(s)]) {
      priority_[static_cast<std::size_t>(s)] = p;
      queue.push({p, s});
    }
  };
  for (int s : changed) {
    double best = -1e300;
    for (int a = 0; a < A; ++a) best = std::max(best, backup(s, a));
    push(s, std::fabs(best - maxQ(s)));
  }
  // States still queued from an earlier call keep their priority.
  for (int s = 0; s < n; ++s) {
    const double p = priority_[static_cast<std::size_t>(s)];
    if (p > config_.tolerance) queue.push({p, s});
  }
  long backups = 0;
  while (!queue.empty() && allows(budget, backups)) {
    const auto [p, s] = queue.top();
    queue.pop();
    if (p != priority_[static_cast<std::size_t>(s)]) continue;  // stale entry
    priority_[static_cast<std::size_t>(s)] = 0.0;
    Node& node = states_[static_cast<std::size_t>(s)];
    if (!node.expanded) continue;
    const double before = maxQ(s);
    for (int a = 0; a < A; ++a) node.q[static_cast<std::size_t>(a)] = backup(s, a);
    ++backups;
    const double delta = std::fabs(maxQ(s) - before);
    if (static_cast<std::size_t>(s) >= preds_.size()) continue;
    for (const auto& pred : preds_[static_cast<std::size_t>(s)]) {
      push(pred.state, config_.gamma * pred.p * delta);
    }
  }
  lastBackups_ = backups;
  return backups;
}

}  // namespace rl_agent
