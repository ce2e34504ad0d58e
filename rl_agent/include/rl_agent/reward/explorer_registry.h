/**
 * The explorer registry: each --explore value names the intrinsic rewards a model-based agent
 * plans with, or how it picks actions (shared/spec/ORIGINAL.md §3.1, §5.5; the comparison
 * methods of the TEXPLORE-VANIR paper §5.1).
 *
 *   greedy           none: external reward only
 *   epsilongreedy    none, and the agent acts at random with probability epsilon
 *   variancenovelty  TEXPLORE-VANIR: v * D(s,a) + n * delta(s,a)
 *   unknown          R-MAX-style: reward rmax and termination for (s,a) seen fewer than m
 *                    times (Brafman & Tennenholtz 2002)
 *   unvisitedstates  + n for states never visited
 *   unvisitedactions + n for state-actions never taken
 *   random           no bonus; the agent acts uniformly at random (the paper's random agent)
 *   competence       R-IAC-style competence progress per random region, weight v
 *                    (RegionErrorReward; Baranes & Oudeyer 2009)
 *   prederror        prediction error per random region, weight v (RegionErrorReward)
 *   boltzmann        no bonus; softmax action selection with temperature tau
 */
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "rl_agent/learning_defaults.h"
#include "rl_agent/reward/intrinsic_reward.h"
#include "rl_agent/reward/learned_reward.h"
#include "rl_common/registry.h"

namespace rl_agent {

struct ExplorerSettings {
  float v = 0.0f;  ///< variance coefficient (and the competence / prederror weight)
  float n = 0.0f;  ///< novelty / unvisited bonus
  /// VANIR's novelty of (s, a) against the states where a was taken (false, the original), or
  /// of s against the states where any action was taken (true).
  bool stateNovelty = false;
  int m = defaults::kKnownVisits;       ///< visits before a state-action is known
  float rmax = 1.0f;                    ///< optimistic value for unknown state-actions
  float tau = defaults::kBoltzmannTau;  ///< Boltzmann temperature
  /// Declared feature ranges (the competence and prederror regions need them).
  std::vector<float> featMin, featMax;
  std::uint64_t seed = 1;  ///< seed of the random regions
  int regions = 16;        ///< number of random regions
  int window = 20;         ///< errors kept per region
};

struct Explorer {
  std::vector<std::shared_ptr<const IntrinsicReward>> rewards;
  std::vector<std::shared_ptr<LearnedReward>> learners;  ///< bonuses learned from errors
  bool epsilonGreedy = false;
  bool randomActions = false;  ///< act uniformly at random (the model still learns)
  bool boltzmann = false;      ///< softmax on the planner's Q-values with temperature tau
  float tau = defaults::kBoltzmannTau;
};

/// The fact of the explorers that add no bonus and only change how actions are chosen
/// (greedy, epsilongreedy, random, boltzmann): every model serves them.
inline constexpr const char* kSelectionOnlyFact = "selection-only";
/// The explorers a model-free agent accepts (greedy, epsilongreedy): it acts epsilon-greedily
/// either way.
inline constexpr const char* kModelFreeSelectionFact = "model-free-selection";
/// The explorer an agent's preset may name that means plain greedy when its weights --v and
/// --n are both 0 and --explore was not given (texplore is TEXPLORE-VANIR only with v or n, as
/// the original).
inline constexpr const char* kGreedyWithoutWeightsFact = "greedy-without-weights";

using ExplorerRegistry = rl_common::Registry<Explorer, const ExplorerSettings&>;

const ExplorerRegistry& explorerRegistry();

}  // namespace rl_agent
