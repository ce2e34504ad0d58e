// Shared by the agent tests: the deterministic 8-cell corridor (actions 0 left, 1 right,
// 2 stay; cell 7 is the goal) and agent options parsed as the agent node parses them.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "rl_agent/agent/agent_options.h"
#include "rl_common/environment.h"

namespace test_corridor {

inline rl_common::EnvironmentDescription corridorTask() {
  rl_common::EnvironmentDescription d;
  d.numActions = 3;
  d.minFeatures = {0.0f};
  d.maxFeatures = {7.0f};
  d.minReward = 0.0f;
  d.maxReward = 1.0f;
  d.episodic = true;
  d.stochastic = false;
  return d;
}

/// The cell after action `a` in cell `x`.
inline int step(int x, int a) {
  return std::max(0, std::min(7, x + (a == 1 ? 1 : a == 0 ? -1 : 0)));
}

/// `--agent agent` plus `extra`, then the agent's defaults and the option rules.
inline rl_agent::AgentOptions parseOptions(const std::string& agent,
                                           const std::vector<std::string>& extra) {
  rl_agent::AgentOptions o;
  rl_common::OptionParser p("test", "");
  rl_agent::addAgentOptions(p, &o);
  std::vector<std::string> args{"--agent", agent};
  args.insert(args.end(), extra.begin(), extra.end());
  p.parse(args);
  rl_agent::applyAgentDefaults(p, &o);
  rl_agent::checkAgentOptions(p, o);
  return o;
}

}  // namespace test_corridor
