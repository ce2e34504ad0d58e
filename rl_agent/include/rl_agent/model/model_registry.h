/**
 * The model registry: each --model value names the transition, reward and termination model a
 * model-based agent learns (shared/spec/ORIGINAL.md §3.1), with the facts the agent and its
 * option checks need:
 *
 *   tree     random forests of incremental C4.5 trees per feature, reward and terminal, with
 *            the visited record behind every intrinsic reward (ExplorationModel; Hester & Stone
 *            2013, 2017); serves every explorer; inputs binned with --nstates
 *   tabular  counts per state-action, R-MAX optimism for --explore unknown (TabularModel;
 *            Brafman & Tennenholtz 2002); selection-only explorers and unknown; binned inputs
 *   m5tree   regression trees with linear leaves (M5Model; Quinlan 1992); selection-only
 *            explorers; continuous inputs, so a dynamic-programming planner needs --nstates
 */
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rl_agent/model/exploration_model.h"
#include "rl_agent/model/tabular_model.h"
#include "rl_agent/reward/explorer_registry.h"
#include "rl_common/mdp_model.h"
#include "rl_common/registry.h"

namespace rl_agent {

/// What every model is built from: the task, the agent's model options and the explorer.
struct ModelSettings {
  int numActions = 0;
  std::vector<float> featMin, featMax;
  bool episodic = true;
  float rewardRange = 1.0f;
  int extraInputs = 0;                 ///< action-history inputs after the features
  bool relativeTransitions = false;    ///< predict each feature's change (--reltrans)
  int numTrees = 1;                    ///< --nmodels
  std::string combination;             ///< --combo (a forest's combination)
  int m = 0;                           ///< visits before a state-action is known (tabular)
  float rmax = 1.0f;                   ///< optimistic value of unknown state-actions
  std::string explore;                 ///< the --explore name
  const Explorer* explorer = nullptr;  ///< its rewards and learners (tree models)
  std::uint64_t seed = 0;              ///< the model's random source
};

/// A learned model and the switches of the two kinds that have one.
struct LearnedModel {
  std::unique_ptr<rl_common::MDPModel> model;
  ExplorationModel* exploration = nullptr;  ///< the model, when it is a tree model
  TabularModel* tabular = nullptr;          ///< the model, when it is tabular

  /// Intrinsic rewards (tree) or R-MAX optimism (tabular) on or off; nothing for other models.
  void setIntrinsicEnabled(bool enabled) const;
};

/// The model serves every explorer, not only the selection-only ones.
inline constexpr const char* kAllExplorersFact = "all-explorers";
/// The model serves --explore unknown (R-MAX optimism) beside the selection-only explorers.
inline constexpr const char* kUnknownExplorerFact = "explore-unknown";
/// The agent bins the model's inputs with --nstates (m5tree regresses on continuous inputs).
inline constexpr const char* kBinnedInputsFact = "binned-inputs";

using ModelRegistry = rl_common::Registry<LearnedModel, const ModelSettings&>;

const ModelRegistry& modelRegistry();

/// The --explore values `model` serves, sorted.
std::vector<std::string> explorersFor(const std::string& model);
/// Throws std::invalid_argument, naming the valid explorers, unless `model` serves `explore`.
void checkModelExplorer(const std::string& model, const std::string& explore);
/// Throws std::invalid_argument if a model on continuous inputs (no kBinnedInputsFact) would
/// get a dynamic-programming planner (`searchPlanner` false) without a state grid (`grid`).
void checkModelGrid(const std::string& model, const std::string& plannerName, bool searchPlanner,
                    bool grid);

}  // namespace rl_agent
