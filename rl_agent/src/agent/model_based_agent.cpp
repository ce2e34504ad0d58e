#include "rl_agent/agent/model_based_agent.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "rl_agent/reward/explorer_registry.h"

namespace rl_agent {

namespace {

using Clock = std::chrono::steady_clock;

FactoredModel::Config modelConfig(const AgentOptions& o,
                                  const rl_common::EnvironmentDescription& t) {
  if (o.model != "tree") {
    throw std::invalid_argument("ModelBasedAgent::ModelBasedAgent(): model '" + o.model +
                                "' is not available to texplore/modelbased yet; use --model tree");
  }
  FactoredModel::Config c;
  c.numActions = t.numActions;
  c.featMin = t.minFeatures;
  c.featMax = t.maxFeatures;
  c.extraInputs = o.history * t.numActions;
  c.relativeTransitions = o.reltrans;
  c.episodic = t.episodic;
  c.forest.numTrees = o.nmodels;
  c.forest.combination = combinationFromName(o.combo);
  // A single tree is the plain C4.5 tree of the original (no split randomisation).
  c.forest.tree.featPct = o.nmodels == 1 ? 0.0 : 0.2;
  return c;
}

UctPlanner::Config plannerConfig(const AgentOptions& o,
                                 const rl_common::EnvironmentDescription& t) {
  if (o.planner != "uct" && o.planner != "parallel-uct") {
    throw std::invalid_argument("ModelBasedAgent::ModelBasedAgent(): planner '" + o.planner +
                                "' is not available yet; use uct or parallel-uct");
  }
  UctPlanner::Config c;
  c.numActions = t.numActions;
  c.gamma = o.gamma;
  c.lambda = o.lambda;
  c.rewardRange = t.rewardRange();
  c.featMin = t.minFeatures;
  c.featMax = t.maxFeatures;
  if (o.nstates > 0) c.statesPerDim = {o.nstates};
  c.history = o.history;
  c.trackActual = true;
  return c;
}

}  // namespace

ModelBasedAgent::ModelBasedAgent(const AgentOptions& options,
                                 const rl_common::EnvironmentDescription& task)
    : options_(options), task_(task), rng_(rl_common::Random::deriveSeed(options.seed, "actions")) {
  if (task.numActions < 1 || task.minFeatures.empty()) {
    throw std::invalid_argument(
        "ModelBasedAgent::ModelBasedAgent(): task has no actions or "
        "features");
  }
  ExplorerSettings settings;
  settings.v = options.v;
  settings.n = options.n;
  settings.m = options.m;
  const float rmax = task.maxReward > 0.0f ? task.maxReward : 1.0f;
  settings.rmax = rmax / (1.0f - std::min(options.gamma, 0.999f));  // the original's qmax
  const auto explorer = explorerRegistry().create(options.explore, settings);
  epsilonGreedy_ = explorer->epsilonGreedy;
  auto model = std::make_unique<ExplorationModel>(
      modelConfig(options, task), rl_common::Random::deriveSeed(options.seed, "model"),
      explorer->rewards);
  auto planner = std::make_unique<UctPlanner>(
      plannerConfig(options, task), rl_common::Random::deriveSeed(options.seed, "planner"));
  modelPtr_ = model.get();
  history_.clear();
  if (options.planner == "parallel-uct" && options.rollouts == 0) {
    realTime_ = std::make_unique<RealTimePlanner>(std::move(model), std::move(planner));
  } else {
    planner->setModel(model->view());
    model_ = std::move(model);
    planner_ = std::move(planner);
  }
}

ModelBasedAgent::~ModelBasedAgent() {
  if (realTime_) {
    try {
      realTime_->stop();
    } catch (...) {
      // A worker's failure was already reported by act(); nothing is left to clean up.
    }
  }
}

rl_common::State ModelBasedAgent::modelInput(const rl_common::State& s) {
  if (options_.history == 0) return s;
  if (realTime_) {
    return realTime_->withPlanner([&](rl_common::Planner& p) {
      auto& uct = static_cast<UctPlanner&>(p);
      uct.setActionHistory(history_);
      return uct.modelInput(s);
    });
  }
  planner_->setActionHistory(history_);
  return planner_->modelInput(s);
}

void ModelBasedAgent::learn(const rl_common::Experience& e) {
  if (realTime_) {
    realTime_->addExperience(e);
  } else {
    model_->update({e});
    planner_->setModel(model_->view());  // novelty changes with every experience
  }
}

void ModelBasedAgent::seedExperiences(const std::vector<rl_common::Experience>& seeds) {
  std::vector<rl_common::Experience> inputs;
  for (const auto& seed : seeds) {
    rl_common::Experience e = seed;
    // Seeds carry no action history: "none" for every past action.
    e.s.resize(e.s.size() + static_cast<std::size_t>(options_.history * task_.numActions), 0.0f);
    inputs.push_back(std::move(e));
  }
  if (realTime_) {
    realTime_->addExperiences(inputs);
  } else {
    model_->update(inputs);
    planner_->setModel(model_->view());
  }
}

int ModelBasedAgent::chooseAction(const rl_common::State& s) {
  const auto due = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(1.0 / options_.actrate));
  const rl_common::State input = modelInput(s);
  int action;
  if (realTime_) {
    action = realTime_->act(s, due);
    lastRollouts_ = realTime_->lastActRollouts();
  } else {
    const auto budget = options_.rollouts > 0
                            ? rl_common::PlanningBudget::ofRollouts(options_.rollouts)
                            : rl_common::PlanningBudget::until(due);
    lastRollouts_ = planner_->plan(s, budget);
    action = planner_->bestAction(s);
  }
  if (epsilonGreedy_ && rng_.bernoulli(options_.epsilon)) {
    action = rng_.uniformInt(0, task_.numActions - 1);
  }
  // What the model predicts the chosen action earns, part by part.
  const auto info = modelView()->query(input, action);
  lastBreakdown_ = {info.varianceReward, info.noveltyReward, info.otherReward};
  lastInput_ = input;
  lastAction_ = action;
  if (options_.history > 0) {
    history_.push_back(action);
    if (static_cast<int>(history_.size()) > options_.history) history_.erase(history_.begin());
  }
  return action;
}

int ModelBasedAgent::firstAction(const rl_common::State& s) {
  history_.clear();
  return chooseAction(s);
}

int ModelBasedAgent::nextAction(float reward, const rl_common::State& s) {
  if (lastAction_ < 0) {
    throw std::logic_error("ModelBasedAgent::nextAction(): called before firstAction()");
  }
  learn({lastInput_, lastAction_, reward, s, false});
  return chooseAction(s);
}

void ModelBasedAgent::lastAction(float reward) {
  if (lastAction_ < 0) {
    throw std::logic_error("ModelBasedAgent::lastAction(): called before firstAction()");
  }
  const rl_common::State last(lastInput_.begin(), lastInput_.begin() + task_.minFeatures.size());
  learn({lastInput_, lastAction_, reward, last, true});
  lastAction_ = -1;
}

void ModelBasedAgent::setIntrinsicEnabled(bool enabled) {
  // In real time the model thread reads this (atomic) flag when it takes its next view, after
  // the next experience.
  if (realTime_) {
    modelPtr_->setIntrinsicEnabled(enabled);
  } else {
    model_->setIntrinsicEnabled(enabled);
    planner_->setModel(model_->view());
  }
}

std::shared_ptr<const ExplorationModel::View> ModelBasedAgent::modelView() const {
  if (realTime_) {
    return std::static_pointer_cast<const ExplorationModel::View>(realTime_->latestView());
  }
  return model_->explorationView();
}

}  // namespace rl_agent
