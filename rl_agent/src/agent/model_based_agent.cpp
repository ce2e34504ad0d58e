#include "rl_agent/agent/model_based_agent.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <stdexcept>
#include <thread>

#include "rl_agent/agent/boltzmann_selector.h"
#include "rl_agent/agent/policy_file.h"
#include "rl_agent/model/m5_model.h"
#include "rl_agent/planner/policy_iteration.h"
#include "rl_agent/planner/prioritized_sweeping.h"
#include "rl_agent/planner/value_iteration.h"
#include "rl_agent/reward/explorer_registry.h"

namespace rl_agent {

namespace {

using Clock = std::chrono::steady_clock;

bool isUct(const std::string& planner) {
  return planner == "uct" || planner == "parallel-uct" || planner == "delayed-uct" ||
         planner == "delayed-parallel-uct";
}

/// Explorers that only change how actions are chosen (no bonus): every model serves them.
bool selectionOnly(const std::string& explore) {
  return explorerRegistry().hasFact(explore, kSelectionOnlyFact);
}

bool isRealTimeUct(const std::string& planner) {
  return planner == "parallel-uct" || planner == "delayed-parallel-uct";
}

FactoredModel::Config modelConfig(const AgentOptions& o,
                                  const rl_common::EnvironmentDescription& t) {
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

RealTimePlanner::Config realTimeConfig(std::uint64_t plannerSeed) {
  RealTimePlanner::Config c;
  c.seed = rl_common::Random::deriveSeed(plannerSeed, "search-ties");
  return c;
}

UctPlanner::Config plannerConfig(const AgentOptions& o,
                                 const rl_common::EnvironmentDescription& t) {
  UctPlanner::Config c;
  c.numActions = t.numActions;
  c.gamma = o.gamma;
  c.lambda = o.lambda;
  c.rewardRange = t.rewardRange();
  c.featMin = t.minFeatures;
  c.featMax = t.maxFeatures;
  if (binsStates(o)) c.statesPerDim = o.nstates;
  c.history = o.history;
  c.trackActual = true;
  c.countPathVisits = o.pathvisits;
  c.ucbBound =
      o.ucb == "normalized" ? UctPlanner::UcbBound::Normalized : UctPlanner::UcbBound::Range;
  c.ucbC = o.ucbc;
  c.bonusOncePerPath = o.bonusonce;
  c.maxDepth = o.depth;
  c.minOutcomeProbability = o.minprob;
  return c;
}

/// What every dynamic-programming planner of the agent shares: actions, discount, the feature
/// ranges (successors outside them are not real: the original's check) and the --nstates grid.
StateSpacePlanner::Config dpConfig(const AgentOptions& o,
                                   const rl_common::EnvironmentDescription& t) {
  StateSpacePlanner::Config c;
  c.numActions = t.numActions;
  c.gamma = std::min(static_cast<double>(o.gamma), 0.999999);
  c.featMin = t.minFeatures;
  c.featMax = t.maxFeatures;
  if (binsStates(o)) c.statesPerDim = o.nstates;  // the planner's grid, as the original's
  return c;
}

std::unique_ptr<StateSpacePlanner> dpPlanner(const AgentOptions& o,
                                             const rl_common::EnvironmentDescription& t,
                                             std::uint64_t seed) {
  StateSpacePlanner::Config c = dpConfig(o, t);
  if (o.planner == "vi") {
    c.maxSteps = 100;  // the original's ValueIteration MAX_STEPS
    return std::make_unique<ValueIteration>(c, seed);
  }
  c.maxSteps = 10;  // the original's PolicyIteration / PrioritizedSweeping MAX_STEPS
  if (o.planner == "pi") return std::make_unique<PolicyIteration>(c, seed);
  if (o.planner == "sweeping") return std::make_unique<PrioritizedSweeping>(c, seed);
  throw std::invalid_argument("ModelBasedAgent::ModelBasedAgent(): unknown planner '" + o.planner +
                              "'; valid: vi, pi, sweeping, uct, parallel-uct, delayed-uct, "
                              "delayed-parallel-uct");
}

}  // namespace

ExplorerSettings ModelBasedAgent::explorerSettings() const {
  ExplorerSettings settings;
  settings.v = options_.v;
  settings.n = options_.n;
  settings.stateNovelty = options_.novelty == "state";
  settings.m = options_.m;
  settings.tau = options_.tau;
  settings.featMin = task_.minFeatures;
  settings.featMax = task_.maxFeatures;
  settings.seed = rl_common::Random::deriveSeed(options_.seed, "regions");
  const float rmax = task_.maxReward > 0.0f ? task_.maxReward : 1.0f;
  settings.rmax = rmax / (1.0f - std::min(options_.gamma, 0.999f));  // the original's qmax
  return settings;
}

std::unique_ptr<rl_common::MDPModel> ModelBasedAgent::makeModel() {
  exploration_ = nullptr;
  tabular_ = nullptr;
  std::unique_ptr<rl_common::MDPModel> model;
  const auto explorer = explorerRegistry().create(options_.explore, explorerSettings());
  const auto reject = [&](const char* modelName) {
    throw std::invalid_argument("ModelBasedAgent::ModelBasedAgent(): --explore " +
                                options_.explore + " is not available with --model " + modelName);
  };
  if (options_.model == "tree") {
    auto m = std::make_unique<ExplorationModel>(
        modelConfig(options_, task_), rl_common::Random::deriveSeed(options_.seed, "model"),
        explorer->rewards, explorer->learners);
    exploration_ = m.get();
    model = std::move(m);
  } else if (options_.model == "tabular") {
    const bool unknown = options_.explore == "unknown";
    if (!selectionOnly(options_.explore) && !unknown) reject("tabular");
    TabularModel::Config c;
    c.numActions = task_.numActions;
    c.numFeatures = static_cast<int>(task_.minFeatures.size());
    c.m = options_.m;
    c.optimistic = unknown;
    c.rmax = explorerSettings().rmax;
    auto m = std::make_unique<TabularModel>(c);
    tabular_ = m.get();
    model = std::move(m);
  } else if (options_.model == "m5tree") {
    if (!selectionOnly(options_.explore)) reject("m5tree");
    if (!isUct(options_.planner) && !binsStates(options_)) {
      throw std::invalid_argument(
          "ModelBasedAgent::ModelBasedAgent(): --model m5tree with --planner " + options_.planner +
          " needs --nstates > 0 (the planner's state grid)");
    }
    M5Model::Config c;
    c.numActions = task_.numActions;
    c.featMin = task_.minFeatures;
    c.featMax = task_.maxFeatures;
    c.extraInputs = options_.history * task_.numActions;
    c.relativeTransitions = options_.reltrans;
    c.episodic = task_.episodic;
    c.rewardRange = std::max(task_.rewardRange(), 1e-6f);
    model = std::make_unique<M5Model>(c);
  } else {
    throw std::invalid_argument("ModelBasedAgent::ModelBasedAgent(): unknown model '" +
                                options_.model + "'; valid: tabular, tree, m5tree");
  }

  modelPtr_ = model.get();
  return model;
}

ModelBasedAgent::ModelBasedAgent(const AgentOptions& options,
                                 const rl_common::EnvironmentDescription& task)
    : options_(options), task_(task), rng_(rl_common::Random::deriveSeed(options.seed, "actions")) {
  if (task.numActions < 1 || task.minFeatures.empty()) {
    throw std::invalid_argument(
        "ModelBasedAgent::ModelBasedAgent(): task has no actions or "
        "features");
  }
  if (binsStates(options)) checkStatesPerDim(options, task.minFeatures.size());
  for (int f : options.taskkey) {
    if (f < 0 || f >= static_cast<int>(task.minFeatures.size())) {
      throw std::invalid_argument("ModelBasedAgent::ModelBasedAgent(): --taskkey feature " +
                                  std::to_string(f) + " out of range; the task has features 0.." +
                                  std::to_string(task.minFeatures.size() - 1));
    }
  }
  const auto explorer = explorerRegistry().create(options.explore, explorerSettings());
  epsilonGreedy_ = explorer->epsilonGreedy;
  randomActions_ = explorer->randomActions;
  boltzmann_ = explorer->boltzmann;
  tau_ = explorer->tau;
  // The explorer's own deferral, unless given; an action history never comes back, so with
  // --history every step would look one-way.
  const long defer = options.defer >= 0 ? options.defer : explorer->deferSteps;
  if (defer > 0 && options.history == 0) {
    deferral_ = std::make_unique<StepDeferral>(defer, options.deferregions);
  } else if (options.deferregions > 0) {
    throw std::invalid_argument(
        "ModelBasedAgent::ModelBasedAgent(): --deferregions needs a deferral: --defer above 0 "
        "(its default defers only for --explore variancenovelty with --v or --n above 0) and "
        "no --history");
  }

  if (binsStates(options) && options.model != "m5tree") {
    grid_ = StateGrid(options.nstates, task.minFeatures, task.maxFeatures);
  }

  std::unique_ptr<rl_common::MDPModel> model = makeModel();

  // The planner.
  const std::uint64_t plannerSeed = rl_common::Random::deriveSeed(options.seed, "planner");
  std::unique_ptr<rl_common::Planner> planner;
  if (isUct(options.planner)) {
    auto p = std::make_unique<UctPlanner>(plannerConfig(options, task), plannerSeed);
    uct_ = p.get();
    planner = std::move(p);
  } else {
    if (options.history > 0) {
      throw std::invalid_argument(
          "ModelBasedAgent::ModelBasedAgent(): --history needs a UCT "
          "planner, not '" +
          options.planner + "'");
    }
    auto p = dpPlanner(options, task, plannerSeed);
    dp_ = p.get();
    planner = std::move(p);
  }
  history_.clear();
  if (isRealTimeUct(options.planner) && options.rollouts == 0) {
    uct_ = nullptr;  // owned and serialised by realTime_ from now on
    // Root-parallel search: tree 0 keeps the planner's seed, the others get streams of their own.
    // The trees share one memory budget (their tables and prediction caches split it), so
    // memory does not grow with the number of threads.
    const int threads = searchThreads(options);
    std::vector<std::unique_ptr<rl_common::Planner>> planners;
    if (threads == 1) {
      planners.push_back(std::move(planner));
    } else {
      for (int k = 0; k < threads; ++k) {
        UctPlanner::Config c = plannerConfig(options, task);
        c.maxStates = std::max<std::size_t>(1000, c.maxStates / static_cast<std::size_t>(threads));
        c.maxCachedPredictions =
            std::max<std::size_t>(1000, c.maxCachedPredictions / static_cast<std::size_t>(threads));
        planners.push_back(std::make_unique<UctPlanner>(
            c, k == 0 ? plannerSeed
                      : rl_common::Random::deriveSeed(plannerSeed, "search",
                                                      static_cast<std::uint64_t>(k))));
      }
    }
    realTime_ = std::make_unique<RealTimePlanner>(std::move(model), std::move(planners),
                                                  realTimeConfig(plannerSeed));
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

rl_common::State ModelBasedAgent::binned(const rl_common::State& s) const { return grid_.apply(s); }

rl_common::State ModelBasedAgent::modelInput(const rl_common::State& s) {
  if (options_.history == 0) return s;
  if (realTime_) {
    realTime_->forEachPlanner(
        [&](rl_common::Planner& p) { static_cast<UctPlanner&>(p).setActionHistory(history_); });
    return realTime_->withPlanner(
        [&](rl_common::Planner& p) { return static_cast<UctPlanner&>(p).modelInput(s); });
  }
  uct_->setActionHistory(history_);
  return uct_->modelInput(s);
}

void ModelBasedAgent::learn(const rl_common::Experience& e) {
  ++learned_;
  if (options_.taskplanner == "vi" && options_.taskrecent > 0) {
    recentStates_.push_back(e.next);
    if (static_cast<int>(recentStates_.size()) > options_.taskrecent) recentStates_.pop_front();
  }
  if (recording_) {
    recorded_.push_back({e, true});
    ++recordedSteps_;
  }
  if (realTime_) {
    realTime_->addExperience(e);
  } else {
    const auto start = Clock::now();
    model_->update({e});
    // Novelty changes with every experience; with --defer the next chooseAction() sets it.
    if (deferral_) {
      modelPending_ = true;
    } else {
      planner_->setModel(model_->view());
    }
    lastLearnSeconds_ = std::chrono::duration<double>(Clock::now() - start).count();
  }
}

void ModelBasedAgent::seedExperiences(const std::vector<rl_common::Experience>& seeds) {
  std::vector<rl_common::Experience> inputs;
  for (const auto& seed : seeds) {
    rl_common::Experience e = seed;
    e.s = binned(e.s);
    e.next = binned(e.next);
    // Seeds carry no action history: "none" for every past action.
    e.s.resize(e.s.size() + static_cast<std::size_t>(options_.history * task_.numActions), 0.0f);
    inputs.push_back(std::move(e));
  }
  learned_ += inputs.size();
  if (recording_) {
    for (const auto& e : inputs) recorded_.push_back({e, false});
  }
  if (realTime_) {
    realTime_->addExperiences(inputs);
  } else {
    model_->update(inputs);
    planner_->setModel(model_->view());
    deferralKey_ = nullptr;  // not a deferring view: the next chooseAction() wraps it if needed
    modelPending_ = false;
  }
}

int ModelBasedAgent::planTaskStep(const rl_common::State& s) {
  // A fresh table every step, rooted at s: the model changed, and with --taskkey the table's
  // representatives must be the states imagined from s, not from earlier visits.
  StateSpacePlanner::Config c = dpConfig(options_, task_);
  c.maxSteps = options_.taskdepth;
  c.maxStates = 20000;  // bounds a step's model queries (6 per state)
  // 0.01 plans better than the default 0.1 but takes 20 times longer (0.3 s against 15 ms a
  // step on LightWorld); the most likely outcome alone (0.5) strands the agent.
  c.minTransitionProbability = options_.taskminprob;
  c.keyFeatures = options_.taskkey;
  c.keyMarginal = options_.taskoutcomes == "key";
  auto planner = std::make_unique<ValueIteration>(
      c, rl_common::Random::deriveSeed(options_.seed, "task planner", taskSteps_++));
  planner->warmStartFrom(taskPlanner_.get());  // last step's values: far fewer sweeps
  planner->setModel(learnedModelView());
  // The states just observed are their entries' representatives (oldest first, so the newest
  // of an entry wins; the current state last): imagined ones alone let each of two cells
  // promise a route through the other that the model gets wrong from the real state, and the
  // greedy agent oscillates between them (docs/science/lightworld-curiosity.md §5.2).
  planner->addStates(std::vector<rl_common::State>(recentStates_.begin(), recentStates_.end()));
  lastRollouts_ = planner->plan(s, options_.tasksweeps > 0
                                       ? rl_common::PlanningBudget::ofRollouts(options_.tasksweeps)
                                       : rl_common::PlanningBudget{});
  planner->warmStartFrom(nullptr);
  taskPlanner_ = std::move(planner);
  return taskPlanner_->bestAction(s);
}

std::vector<double> ModelBasedAgent::plannerValues(const rl_common::State& s) {
  if (taskPlannerActive() && taskPlanner_) return taskPlanner_->qValues(s);
  if (realTime_) {
    return realTime_->qValues(s);
  }
  if (uct_ != nullptr) return uct_->qValues(s);
  return dp_->qValues(s);
}

int ModelBasedAgent::chooseAction(const rl_common::State& raw) {
  const auto due = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(1.0 / options_.actrate));
  const rl_common::State s = binned(raw);
  const rl_common::State input = modelInput(s);
  if (deferral_) {
    const auto view = currentView();  // the model as it is now, learned from the last step
    deferral_->observe(*view, lastAction_ >= 0 ? lastInput_ : rl_common::State{}, lastAction_,
                       input, task_.numActions);
    // The planner sees the one-way steps it must put off. Synchronously, learn() leaves the
    // model to this call; in real time the planners' views are filtered when that changes.
    // Only when something changed: a new model view caps the search tree's visit counts.
    const void* key = exploring_ ? deferral_->planningKey() : nullptr;
    if (!realTime_) {
      if (modelPending_ || key != deferralKey_) {
        planner_->setModel(key != nullptr ? deferral_->planningView(view) : view);
      }
      modelPending_ = false;
    } else if (key != deferralKey_) {
      realTime_->setViewFilter(key != nullptr ? deferral_->viewFilter() : nullptr);
    }
    deferralKey_ = key;
  }
  const auto planStart = Clock::now();
  int action;
  if (taskPlannerActive()) {
    action = planTaskStep(s);
    if (realTime_) std::this_thread::sleep_until(due);  // keep the action rate
  } else if (realTime_) {
    action = realTime_->act(s, due);
    lastRollouts_ = realTime_->lastActRollouts();
  } else if (randomActions_ && exploring_) {
    action = 0;  // replaced below; no planning needed
    lastRollouts_ = 0;
  } else if (dp_ != nullptr) {
    const auto budget = options_.rollouts > 0
                            ? rl_common::PlanningBudget::ofRollouts(options_.rollouts)
                            : rl_common::PlanningBudget{};
    lastRollouts_ = planner_->plan(s, budget);
    action = planner_->bestAction(s);
  } else {
    const auto budget = options_.rollouts > 0
                            ? rl_common::PlanningBudget::ofRollouts(options_.rollouts)
                            : rl_common::PlanningBudget::until(due);
    lastRollouts_ = planner_->plan(s, budget);
    action = planner_->bestAction(s);
  }
  lastPlanSeconds_ = std::chrono::duration<double>(Clock::now() - planStart).count();
  // The planner's values at s, read once: for Boltzmann choice and the step's breakdown.
  const std::vector<double> q = plannerValues(s);
  if (!exploring_) {
    // The planner's greedy action.
  } else if (randomActions_) {
    action = rng_.uniformInt(0, task_.numActions - 1);
  } else if (boltzmann_) {
    if (static_cast<int>(q.size()) == task_.numActions) {
      action = BoltzmannSelector::sample(q, tau_, rng_);
    }
  } else if (epsilonGreedy_ && rng_.bernoulli(options_.epsilon)) {
    action = rng_.uniformInt(0, task_.numActions - 1);
  }
  if (deferral_ && exploring_ && static_cast<int>(q.size()) == task_.numActions) {
    action = deferral_->choose(input, action, q, rng_);
  }
  // What the model predicts the chosen action earns, part by part.
  const auto info = currentView()->query(input, action);
  lastBreakdown_ = {info.varianceReward, info.noveltyReward, info.otherReward};
  if (static_cast<int>(q.size()) == task_.numActions) {
    lastBreakdown_.plannedValue = q[static_cast<std::size_t>(action)];
    const auto [lo, hi] = std::minmax_element(q.begin(), q.end());
    lastBreakdown_.valueSpread = *hi - *lo;
  }
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
  learn({lastInput_, lastAction_, reward, binned(s), false});
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
  taskPlanner_.reset();  // a task phase plans afresh, on the model as it is then
  if (exploration_ != nullptr) exploration_->setIntrinsicEnabled(enabled);
  if (tabular_ != nullptr) tabular_->setOptimistic(enabled);
  if (!realTime_) {
    planner_->setModel(model_->view());
    deferralKey_ = nullptr;  // the view just set is not a deferring one
    modelPending_ = false;
  }
  applyUcbBound();
}

void ModelBasedAgent::applyUcbBound() {
  const bool task = !exploring_ && options_.taskucb != "same";
  const std::string& name = task ? options_.taskucb : options_.ucb;
  const auto bound =
      name == "normalized" ? UctPlanner::UcbBound::Normalized : UctPlanner::UcbBound::Range;
  const double c = task ? options_.taskucbc : options_.ucbc;
  if (realTime_) {
    realTime_->forEachPlanner(
        [&](rl_common::Planner& p) { static_cast<UctPlanner&>(p).setUcbBound(bound, c); });
  } else if (uct_ != nullptr) {
    uct_->setUcbBound(bound, c);
  }
}

void ModelBasedAgent::recordExperiences(bool on) {
  if (on && !recording_ && learned_ > 0) {
    throw std::logic_error("ModelBasedAgent::recordExperiences(): " + std::to_string(learned_) +
                           " experiences were learned before recording started");
  }
  recording_ = on;
}

void ModelBasedAgent::relabelRewards(const std::vector<float>& rewards) {
  if (!recording_) {
    throw std::logic_error(
        "ModelBasedAgent::relabelRewards(): experiences were not recorded "
        "(recordExperiences(true) before the first experience)");
  }
  if (rewards.size() != recordedSteps_) {
    throw std::invalid_argument(
        "ModelBasedAgent::relabelRewards(): " + std::to_string(rewards.size()) + " rewards for " +
        std::to_string(recordedSteps_) + " recorded steps");
  }
  std::vector<rl_common::Experience> replay;
  replay.reserve(recorded_.size());
  std::size_t next = 0;
  for (auto& r : recorded_) {
    if (r.step) r.experience.reward = rewards[next++];
    replay.push_back(r.experience);
  }
  taskPlanner_.reset();  // its snapshot is of the model before the new rewards
  std::vector<std::unique_ptr<rl_common::Planner>> planners;
  if (realTime_) {
    planners = realTime_->releasePlanners();
  } else {
    planners.push_back(std::move(planner_));
  }
  realTime_.reset();
  deferralKey_ = nullptr;  // a new real-time planner has no view filter
  model_.reset();
  std::unique_ptr<rl_common::MDPModel> model = makeModel();
  model->update(replay);
  if (exploration_ != nullptr) exploration_->setIntrinsicEnabled(exploring_);
  if (tabular_ != nullptr) tabular_->setOptimistic(exploring_);
  if (isRealTimeUct(options_.planner) && options_.rollouts == 0) {
    realTime_ = std::make_unique<RealTimePlanner>(
        std::move(model), std::move(planners),
        realTimeConfig(rl_common::Random::deriveSeed(options_.seed, "planner")));
  } else {
    std::unique_ptr<rl_common::Planner> planner = std::move(planners.front());
    planner->setModel(model->view());
    model_ = std::move(model);
    planner_ = std::move(planner);
  }
}

std::shared_ptr<const rl_common::ModelView> ModelBasedAgent::currentView() const {
  if (realTime_) return realTime_->latestView();
  return model_->view();
}

std::shared_ptr<const ExplorationModel::View> ModelBasedAgent::modelView() const {
  if (exploration_ == nullptr) return nullptr;
  if (realTime_) {
    return std::static_pointer_cast<const ExplorationModel::View>(realTime_->latestView());
  }
  return exploration_->explorationView();
}

std::shared_ptr<const rl_common::ModelView> ModelBasedAgent::learnedModelView() const {
  if (exploration_ != nullptr) {
    const auto view = modelView();
    if (view == nullptr) return nullptr;
    return std::shared_ptr<const rl_common::ModelView>(view, &view->model());
  }
  // Tabular and M5 views: the optimism of R-MAX changes reward and termination only.
  return currentView();
}

void ModelBasedAgent::savePolicy(const std::string& filename) {
  if (filename.empty()) return;
  const std::size_t d = task_.minFeatures.size();
  PolicyFile::Table table;
  if (dp_ != nullptr) {
    for (const auto& s : dp_->expandedStates()) {
      if (s.size() != d) continue;
      const std::vector<double> q = dp_->qValues(s);
      table.emplace(s, std::vector<float>(q.begin(), q.end()));
    }
  } else {
    // UCT: every state of the planner's table. With --history a state has a record per action
    // history; the file (keyed by state alone) gets the most visited one's values.
    std::map<rl_common::State, long> visitsOf;
    const auto collect = [&](const UctPlanner& uct) {
      uct.forEachRecord([&](const rl_common::State& key, const std::vector<double>& q, long n) {
        if (key.size() < d || static_cast<int>(q.size()) != task_.numActions) return;
        rl_common::State s(key.begin(), key.begin() + static_cast<std::ptrdiff_t>(d));
        const auto it = visitsOf.find(s);
        if (it != visitsOf.end() && it->second >= n) return;
        visitsOf[s] = n;
        table[s] = std::vector<float>(q.begin(), q.end());
      });
    };
    if (realTime_) {
      // Every search tree: a state keeps the values of its most visited record.
      realTime_->forEachPlanner(
          [&](rl_common::Planner& p) { collect(static_cast<UctPlanner&>(p)); });
    } else if (uct_ != nullptr) {
      collect(*uct_);
    } else {
      return;
    }
  }
  PolicyFile::write(filename, static_cast<int>(d), task_.numActions, table);
}

}  // namespace rl_agent
