#include "rl_agent/agent/model_based_agent.h"

#include <algorithm>
#include <stdexcept>

#include "rl_agent/agent/policy_export.h"
#include "rl_agent/agent/policy_file.h"
#include "rl_agent/model/no_history_view.h"
#include "rl_agent/planner/planner_registry.h"

namespace rl_agent {

namespace {

using Clock = PlanningLoop::Clock;

std::unique_ptr<Explorer> makeExplorer(const ModelBasedConfig& c) {
  return explorerRegistry().create(c.explore, c.explorer);
}

void checkTask(const ModelBasedConfig& c, const rl_common::EnvironmentDescription& task) {
  if (task.numActions < 1 || task.minFeatures.empty()) {
    throw std::invalid_argument(
        "ModelBasedAgent::ModelBasedAgent(): task has no actions or "
        "features");
  }
  for (int f : c.taskKey) {
    if (f < 0 || f >= static_cast<int>(task.minFeatures.size())) {
      throw std::invalid_argument("ModelBasedAgent::ModelBasedAgent(): --taskkey feature " +
                                  std::to_string(f) + " out of range; the task has features 0.." +
                                  std::to_string(task.minFeatures.size() - 1));
    }
  }
}

/// The configuration of `options`, once their --nstates fits the task.
ModelBasedConfig checkedConfig(const AgentOptions& options,
                               const rl_common::EnvironmentDescription& task) {
  if (binsStates(options)) checkStatesPerDim(options, task.minFeatures.size());
  return modelBasedConfig(options, task);
}

}  // namespace

ModelBasedAgent::ModelBasedAgent(const AgentOptions& options,
                                 const rl_common::EnvironmentDescription& task)
    : ModelBasedAgent(checkedConfig(options, task), task) {}

ModelBasedAgent::ModelBasedAgent(const Config& config,
                                 const rl_common::EnvironmentDescription& task)
    : config_(config),
      task_(task),
      rng_(rl_common::Random::deriveSeed(config.seed, "actions")),
      selector_(ActionSelector::Mode::Greedy, std::max(1, task.numActions), 0.0, 1.0) {
  checkTask(config, task);
  // The explorer, built once: its action choice and the model's bonuses.
  const std::unique_ptr<Explorer> explorer = makeExplorer(config);
  checkModelExplorer(config.model, config.explore);
  checkModelGrid(config.model, config.planner,
                 plannerRegistry().hasFact(config.planner, kSearchPlannerFact),
                 !config.planning.dp.statesPerDim.empty());
  selector_ = ActionSelector::forExplorer(*explorer, task.numActions, config.epsilon);
  // An action history never comes back, so with --history every step would look one-way.
  if (config.defer > 0 && config.history == 0) {
    deferral_ = std::make_unique<StepDeferral>(config.defer, config.deferRegions);
  } else if (config.deferRegions > 0) {
    throw std::invalid_argument(
        "ModelBasedAgent::ModelBasedAgent(): --deferregions needs a deferral: --defer above 0 "
        "and no --history");
  }
  if (!config.statesPerDim.empty()) {
    grid_ = StateGrid(config.statesPerDim, task.minFeatures, task.maxFeatures);
  }
  if (config.taskPlanner) taskPhase_.emplace(config.taskPhase);

  model_ = makeModel(*explorer);
  if (config.taskCombination && (!config.taskPlanner || model_.exploration == nullptr)) {
    throw std::invalid_argument(
        "ModelBasedAgent::ModelBasedAgent(): --taskcombo needs --taskplanner vi and a forest "
        "model (--model tree)");
  }
  PlannerSettings planning = config.planning;
  planning.lazyViews = deferral_ != nullptr;  // the deferral filters each new view first
  loop_ = makePlanningLoop(config.planner, planning, std::move(model_.model));
}

ModelBasedAgent::~ModelBasedAgent() {
  if (loop_) loop_->stop();
}

LearnedModel ModelBasedAgent::makeModel(const Explorer& explorer) const {
  ModelSettings settings = config_.models;
  settings.explorer = &explorer;
  return std::move(*modelRegistry().create(config_.model, settings));
}

rl_common::State ModelBasedAgent::modelInput(const rl_common::State& s) {
  if (config_.history == 0) return s;
  return loop_->modelInput(s, history_);
}

void ModelBasedAgent::learn(const rl_common::Experience& e) {
  if (taskPhase_) taskPhase_->observe(e.next);
  log_.addStep(e);
  loop_->learn(e);
}

void ModelBasedAgent::seedExperiences(const std::vector<rl_common::Experience>& seeds) {
  std::vector<rl_common::Experience> inputs;
  for (const auto& seed : seeds) {
    rl_common::Experience e = seed;
    e.s = grid_.apply(e.s);
    e.next = grid_.apply(e.next);
    // Seeds carry no action history: "none" for every past action.
    e.s.resize(e.s.size() + static_cast<std::size_t>(config_.history * task_.numActions), 0.0f);
    inputs.push_back(std::move(e));
  }
  log_.addSeeds(inputs);
  loop_->learnAll(inputs);
}

int ModelBasedAgent::planAction(const rl_common::State& s, const rl_common::State& input,
                                Clock::time_point due) {
  if (deferral_) {
    // The model as it is now, learned from the last step.
    deferral_->observe(*loop_->latestView(), lastAction_ >= 0 ? lastInput_ : rl_common::State{},
                       lastAction_, input, task_.numActions);
    // The planner sees the one-way steps it must put off (only while exploring).
    loop_->filterViews(exploring_ ? deferral_->planningKey() : nullptr,
                       [this] { return deferral_->viewFilter(); });
  }
  if (taskPlannerActive()) {
    const int action = taskPhase_->plan(s, taskModelView());
    lastRollouts_ = taskPhase_->lastIterations();
    loop_->waitUntil(due);  // keep the action rate
    return action;
  }
  const int action = loop_->act(s, due, !exploring_ || selector_.needsPlanner());
  lastRollouts_ = loop_->lastRollouts();
  return action;
}

int ModelBasedAgent::chooseAction(const rl_common::State& raw) {
  const auto due = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(1.0 / config_.actRate));
  const rl_common::State s = grid_.apply(raw);
  const rl_common::State input = modelInput(s);
  const auto planStart = Clock::now();
  int action = planAction(s, input, due);
  lastPlanSeconds_ = std::chrono::duration<double>(Clock::now() - planStart).count();
  // The planner's values at s, read once: for Boltzmann choice and the step's breakdown.
  const std::vector<double> q =
      taskPlannerActive() && taskPhase_->planned() ? taskPhase_->qValues(s) : loop_->qValues(s);
  const bool fullQ = static_cast<int>(q.size()) == task_.numActions;
  if (exploring_) {
    action = selector_.choose(action, q, rng_);
    if (deferral_ && fullQ) action = deferral_->choose(input, action, q, rng_);
  }
  // What the model predicts the chosen action earns, part by part.
  const auto info = loop_->latestView()->query(input, action);
  lastBreakdown_ = {info.varianceReward, info.noveltyReward, info.otherReward};
  if (fullQ) {
    lastBreakdown_.plannedValue = q[static_cast<std::size_t>(action)];
    const auto [lo, hi] = std::minmax_element(q.begin(), q.end());
    lastBreakdown_.valueSpread = *hi - *lo;
  }
  lastInput_ = input;
  lastAction_ = action;
  if (config_.history > 0) {
    history_.push_back(action);
    if (static_cast<int>(history_.size()) > config_.history) history_.erase(history_.begin());
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
  learn({lastInput_, lastAction_, reward, grid_.apply(s), false});
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
  // In real time the model thread reads these (atomic) flags when it takes its next view,
  // after the next experience.
  exploring_ = enabled;
  if (taskPhase_) taskPhase_->reset();  // a task phase plans afresh, on the model as it is then
  model_.setIntrinsicEnabled(enabled);
  loop_->refreshView();
  applyUcbBound();
}

void ModelBasedAgent::applyUcbBound() {
  const bool task = !exploring_ && config_.taskUcbGiven;
  const ModelBasedConfig::Ucb& ucb = task ? config_.taskUcb : config_.exploreUcb;
  loop_->forEachSearchPlanner([&](UctPlanner& p) { p.setUcbBound(ucb.bound, ucb.c); });
}

void ModelBasedAgent::relabelRewards(const std::vector<float>& rewards) {
  const std::vector<rl_common::Experience> replay = log_.relabel(rewards);
  if (taskPhase_) taskPhase_->reset();  // its table is of the model before the new rewards
  // The explorer's learned bonuses learn along with their model: a rebuilt model gets fresh
  // ones, which learn from the same experiences.
  const std::unique_ptr<Explorer> explorer = makeExplorer(config_);
  LearnedModel rebuilt = makeModel(*explorer);
  rebuilt.model->update(replay);
  rebuilt.setIntrinsicEnabled(exploring_);
  model_ = std::move(rebuilt);
  loop_->replaceModel(std::move(model_.model));
}

std::shared_ptr<const ExplorationModel::View> ModelBasedAgent::modelView() const {
  if (model_.exploration == nullptr) return nullptr;
  return std::static_pointer_cast<const ExplorationModel::View>(loop_->latestView());
}

std::shared_ptr<const rl_common::ModelView> ModelBasedAgent::learnedModelView() const {
  std::shared_ptr<const rl_common::ModelView> learned;
  if (model_.exploration != nullptr) {
    const auto view = modelView();
    if (view == nullptr) return nullptr;
    learned = std::shared_ptr<const rl_common::ModelView>(view, &view->model());
  } else {
    // Tabular and M5 views: the optimism of R-MAX changes reward and termination only.
    learned = loop_->latestView();
  }
  if (config_.history == 0 || learned == nullptr) return learned;
  return std::make_shared<NoHistoryView>(
      std::move(learned), task_.minFeatures.size(),
      static_cast<std::size_t>(config_.history * task_.numActions));
}

std::shared_ptr<const rl_common::ModelView> ModelBasedAgent::taskModelView() const {
  if (!config_.taskCombination) return learnedModelView();
  const auto view = modelView();  // a forest model: the option checks say so
  if (view == nullptr) return nullptr;
  // --taskplanner vi takes no --history, so the recombined forests take states as they are.
  return view->model().recombined(*config_.taskCombination);
}

void ModelBasedAgent::savePolicy(const std::string& filename) {
  if (filename.empty()) return;
  const std::size_t d = task_.minFeatures.size();
  PolicyFile::write(filename, static_cast<int>(d), task_.numActions,
                    policyTable(*loop_, d, task_.numActions));
}

}  // namespace rl_agent
