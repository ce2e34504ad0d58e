#include "rl_agent/reward/explorer_registry.h"

#include <stdexcept>

#include "rl_agent/reward/novelty_reward.h"
#include "rl_agent/reward/random_regions.h"
#include "rl_agent/reward/region_error_reward.h"
#include "rl_agent/reward/unknown_reward.h"
#include "rl_agent/reward/unvisited_action_reward.h"
#include "rl_agent/reward/unvisited_state_reward.h"
#include "rl_agent/reward/variance_reward.h"

namespace rl_agent {

namespace {

/// An explorer whose one intrinsic reward is a visit-count bonus of weight n.
template <class Bonus>
ExplorerRegistry::Factory countBonusExplorer() {
  return [](const ExplorerSettings& s) {
    auto e = std::make_unique<Explorer>();
    e->rewards.push_back(std::make_shared<Bonus>(s.n));
    return e;
  };
}

ExplorerRegistry build() {
  ExplorerRegistry reg("explore type");
  reg.add("greedy", [](const ExplorerSettings&) { return std::make_unique<Explorer>(); },
          "external reward only", {kSelectionOnlyFact, kModelFreeSelectionFact});
  reg.add("epsilongreedy",
          [](const ExplorerSettings&) {
            auto e = std::make_unique<Explorer>();
            e->epsilonGreedy = true;
            return e;
          },
          "random action with probability epsilon", {kSelectionOnlyFact, kModelFreeSelectionFact},
          {"epsilon"});
  reg.add("variancenovelty",
          [](const ExplorerSettings& s) {
            auto e = std::make_unique<Explorer>();
            if (s.v != 0.0f) e->rewards.push_back(std::make_shared<VarianceReward>(s.v));
            if (s.n != 0.0f)
              e->rewards.push_back(std::make_shared<NoveltyReward>(s.n, s.stateNovelty));
            return e;
          },
          "TEXPLORE-VANIR: v * variance + n * novelty", {kGreedyWithoutWeightsFact},
          {"v", "n", "novelty"});
  reg.add(
      "unknown",
      [](const ExplorerSettings& s) {
        auto e = std::make_unique<Explorer>();
        e->rewards.push_back(std::make_shared<UnknownReward>(s.m, s.rmax));
        return e;
      },
      "R-MAX-style optimism for state-actions seen fewer than m times");
  reg.add("unvisitedstates", countBonusExplorer<UnvisitedStateReward>(),
          "bonus n for unvisited states", {}, {"n"});
  reg.add("unvisitedactions", countBonusExplorer<UnvisitedActionReward>(),
          "bonus n for untried state-actions", {}, {"n"});
  reg.add("random",
          [](const ExplorerSettings&) {
            auto e = std::make_unique<Explorer>();
            e->randomActions = true;
            return e;
          },
          "uniformly random actions (the paper's random agent)", {kSelectionOnlyFact});
  reg.add("boltzmann",
          [](const ExplorerSettings& s) {
            if (!(s.tau > 0.0f))
              throw std::invalid_argument("explorerRegistry(): boltzmann needs tau > 0");
            auto e = std::make_unique<Explorer>();
            e->boltzmann = true;
            e->tau = s.tau;
            return e;
          },
          "softmax action selection with temperature tau", {kSelectionOnlyFact}, {"tau"});
  const auto regionExplorer = [](RegionErrorReward::Kind kind) {
    return [kind](const ExplorerSettings& s) {
      auto regions = std::make_shared<const RandomRegions>(s.featMin, s.featMax, s.regions, s.seed);
      RegionErrorReward::Config c;
      c.kind = kind;
      c.weight = s.v;
      c.window = s.window;
      auto e = std::make_unique<Explorer>();
      e->learners.push_back(std::make_shared<RegionErrorReward>(c, std::move(regions)));
      return e;
    };
  };
  reg.add("competence", regionExplorer(RegionErrorReward::Kind::CompetenceProgress),
          "R-IAC-style competence progress in random regions (weight v)", {}, {"v"});
  reg.add("prederror", regionExplorer(RegionErrorReward::Kind::PredictionError),
          "prediction error in random regions (weight v)", {}, {"v"});
  // The region bonuses' weight is 1 unless given (without it they would add nothing).
  reg.setOptionValues("competence", {{"v", "1"}});
  reg.setOptionValues("prederror", {{"v", "1"}});
  return reg;
}

}  // namespace

const ExplorerRegistry& explorerRegistry() {
  static const ExplorerRegistry registry = build();
  return registry;
}

}  // namespace rl_agent
