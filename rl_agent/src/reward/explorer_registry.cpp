#include "rl_agent/reward/explorer_registry.h"

#include "rl_agent/reward/novelty_reward.h"
#include "rl_agent/reward/unknown_reward.h"
#include "rl_agent/reward/unvisited_action_reward.h"
#include "rl_agent/reward/unvisited_state_reward.h"
#include "rl_agent/reward/variance_reward.h"

namespace rl_agent {

namespace {

ExplorerRegistry build() {
  ExplorerRegistry reg("explore type");
  reg.add(
      "greedy", [](const ExplorerSettings&) { return std::make_unique<Explorer>(); },
      "external reward only");
  reg.add(
      "epsilongreedy",
      [](const ExplorerSettings&) {
        auto e = std::make_unique<Explorer>();
        e->epsilonGreedy = true;
        return e;
      },
      "random action with probability epsilon");
  reg.add(
      "variancenovelty",
      [](const ExplorerSettings& s) {
        auto e = std::make_unique<Explorer>();
        if (s.v != 0.0f) e->rewards.push_back(std::make_shared<VarianceReward>(s.v));
        if (s.n != 0.0f) e->rewards.push_back(std::make_shared<NoveltyReward>(s.n));
        return e;
      },
      "TEXPLORE-VANIR: v * variance + n * novelty");
  reg.add(
      "unknown",
      [](const ExplorerSettings& s) {
        auto e = std::make_unique<Explorer>();
        e->rewards.push_back(std::make_shared<UnknownReward>(s.m, s.rmax));
        return e;
      },
      "R-MAX-style optimism for state-actions seen fewer than m times");
  reg.add(
      "unvisitedstates",
      [](const ExplorerSettings& s) {
        auto e = std::make_unique<Explorer>();
        e->rewards.push_back(std::make_shared<UnvisitedStateReward>(s.n));
        return e;
      },
      "bonus n for unvisited states");
  reg.add(
      "unvisitedactions",
      [](const ExplorerSettings& s) {
        auto e = std::make_unique<Explorer>();
        e->rewards.push_back(std::make_shared<UnvisitedActionReward>(s.n));
        return e;
      },
      "bonus n for untried state-actions");
  return reg;
}

}  // namespace

const ExplorerRegistry& explorerRegistry() {
  static const ExplorerRegistry registry = build();
  return registry;
}

}  // namespace rl_agent
