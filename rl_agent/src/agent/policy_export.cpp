#include "rl_agent/agent/policy_export.h"

#include <map>

namespace rl_agent {

PolicyFile::Table policyTable(PlanningLoop& loop, std::size_t numFeatures, int numActions) {
  const std::size_t d = numFeatures;
  PolicyFile::Table table;
  if (const StateSpacePlanner* dp = loop.statePlanner()) {
    for (const auto& s : dp->expandedStates()) {
      if (s.size() != d) continue;
      const std::vector<double> q = dp->qValues(s);
      table.emplace(s, std::vector<float>(q.begin(), q.end()));
    }
    return table;
  }
  std::map<rl_common::State, long> visitsOf;
  loop.forEachSearchPlanner([&](UctPlanner& uct) {
    uct.forEachRecord([&](const rl_common::State& key, const std::vector<double>& q, long n) {
      if (key.size() < d || static_cast<int>(q.size()) != numActions) return;
      rl_common::State s(key.begin(), key.begin() + static_cast<std::ptrdiff_t>(d));
      const auto it = visitsOf.find(s);
      if (it != visitsOf.end() && it->second >= n) return;
      visitsOf[s] = n;
      table[s] = std::vector<float>(q.begin(), q.end());
    });
  });
  return table;
}

}  // namespace rl_agent
