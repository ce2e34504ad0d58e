#include "rl_agent/model/model_registry.h"

#include <algorithm>
#include <stdexcept>

#include "rl_agent/model/m5_model.h"
#include "rl_agent/model/random_forest.h"

namespace rl_agent {

void LearnedModel::setIntrinsicEnabled(bool enabled) const {
  if (exploration != nullptr) exploration->setIntrinsicEnabled(enabled);
  if (tabular != nullptr) tabular->setOptimistic(enabled);
}

namespace {

std::unique_ptr<LearnedModel> treeModel(const ModelSettings& s) {
  if (s.explorer == nullptr) throw std::invalid_argument("modelRegistry(): tree needs an explorer");
  FactoredModel::Config c;
  c.numActions = s.numActions;
  c.featMin = s.featMin;
  c.featMax = s.featMax;
  c.extraInputs = s.extraInputs;
  c.relativeTransitions = s.relativeTransitions;
  c.episodic = s.episodic;
  c.forest.numTrees = s.numTrees;
  c.forest.combination = combinationFromName(s.combination);
  // A single tree is the plain C4.5 tree of the original (no split randomisation).
  c.forest.tree.featPct = s.numTrees == 1 ? 0.0 : 0.2;
  auto out = std::make_unique<LearnedModel>();
  auto m = std::make_unique<ExplorationModel>(c, s.seed, s.explorer->rewards, s.explorer->learners);
  out->exploration = m.get();
  out->model = std::move(m);
  return out;
}

std::unique_ptr<LearnedModel> tabularModel(const ModelSettings& s) {
  checkModelExplorer("tabular", s.explore);
  TabularModel::Config c;
  c.numActions = s.numActions;
  c.numFeatures = static_cast<int>(s.featMin.size());
  c.m = s.m;
  c.optimistic = s.explore == "unknown";
  c.rmax = s.rmax;
  auto out = std::make_unique<LearnedModel>();
  auto m = std::make_unique<TabularModel>(c);
  out->tabular = m.get();
  out->model = std::move(m);
  return out;
}

std::unique_ptr<LearnedModel> m5Model(const ModelSettings& s) {
  checkModelExplorer("m5tree", s.explore);
  M5Model::Config c;
  c.numActions = s.numActions;
  c.featMin = s.featMin;
  c.featMax = s.featMax;
  c.extraInputs = s.extraInputs;
  c.relativeTransitions = s.relativeTransitions;
  c.episodic = s.episodic;
  c.rewardRange = std::max(s.rewardRange, 1e-6f);
  auto out = std::make_unique<LearnedModel>();
  out->model = std::make_unique<M5Model>(c);
  return out;
}

}  // namespace

const ModelRegistry& modelRegistry() {
  static const ModelRegistry registry = [] {
    ModelRegistry reg("model");
    reg.add("tree", treeModel, "random forests of C4.5 trees (TEXPLORE)",
            {kAllExplorersFact, kBinnedInputsFact}, {"taskcombo"});
    reg.add("tabular", tabularModel, "counts per state-action (R-MAX)",
            {kUnknownExplorerFact, kBinnedInputsFact});
    reg.add("m5tree", m5Model, "regression trees with linear leaves (M5)");
    reg.addAlias("c45tree", "tree");
    reg.addAlias("texplore", "tree");
    return reg;
  }();
  return registry;
}

std::vector<std::string> explorersFor(const std::string& model) {
  const ModelRegistry& models = modelRegistry();
  if (models.hasFact(model, kAllExplorersFact)) return explorerRegistry().names();
  std::vector<std::string> out = explorerRegistry().namesWith(kSelectionOnlyFact);
  if (models.hasFact(model, kUnknownExplorerFact)) out.push_back("unknown");
  std::sort(out.begin(), out.end());
  return out;
}

void checkModelExplorer(const std::string& model, const std::string& explore) {
  const std::vector<std::string> valid = explorersFor(model);
  if (std::find(valid.begin(), valid.end(), explore) == valid.end()) {
    throw std::invalid_argument("option --explore " + explore + " is not available with --model " +
                                modelRegistry().canonical(model) +
                                "; valid: " + rl_common::joinNames(valid));
  }
}

void checkModelGrid(const std::string& model, const std::string& plannerName, bool searchPlanner,
                    bool grid) {
  if (!modelRegistry().hasFact(model, kBinnedInputsFact) && !searchPlanner && !grid) {
    throw std::invalid_argument("--model " + modelRegistry().canonical(model) + " with --planner " +
                                plannerName + " needs --nstates > 0 (the planner's state grid)");
  }
}

}  // namespace rl_agent
