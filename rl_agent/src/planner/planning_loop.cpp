#include "rl_agent/planner/planning_loop.h"

#include <stdexcept>
#include <thread>
#include <utility>

namespace rl_agent {

// ---- synchronous ----

SyncPlanningLoop::SyncPlanningLoop(std::unique_ptr<rl_common::MDPModel> model,
                                   std::unique_ptr<UctPlanner> planner, long rollouts,
                                   bool lazyViews)
    : SyncPlanningLoop(std::move(model), nullptr, rollouts, lazyViews, planner.get(), nullptr) {
  planner_ = std::move(planner);
  resetView();
}

SyncPlanningLoop::SyncPlanningLoop(std::unique_ptr<rl_common::MDPModel> model,
                                   std::unique_ptr<StateSpacePlanner> planner, long rollouts,
                                   bool lazyViews)
    : SyncPlanningLoop(std::move(model), nullptr, rollouts, lazyViews, nullptr, planner.get()) {
  planner_ = std::move(planner);
  resetView();
}

SyncPlanningLoop::SyncPlanningLoop(std::unique_ptr<rl_common::MDPModel> model,
                                   std::unique_ptr<rl_common::Planner> planner, long rollouts,
                                   bool lazyViews, UctPlanner* search, StateSpacePlanner* dp)
    : model_(std::move(model)),
      planner_(std::move(planner)),
      search_(search),
      dp_(dp),
      rollouts_(rollouts),
      lazyViews_(lazyViews) {
  if (model_ == nullptr) throw std::invalid_argument("SyncPlanningLoop: null model");
}

void SyncPlanningLoop::resetView() {
  planner_->setModel(model_->view());
  filterKey_ = nullptr;
  viewPending_ = false;
}

void SyncPlanningLoop::learn(const rl_common::Experience& e) {
  const auto start = Clock::now();
  model_->update({e});
  // Novelty changes with every experience; with lazy views the next filterViews() sets it.
  if (lazyViews_) {
    viewPending_ = true;
  } else {
    planner_->setModel(model_->view());
  }
  lastLearnSeconds_ = std::chrono::duration<double>(Clock::now() - start).count();
}

void SyncPlanningLoop::learnAll(const std::vector<rl_common::Experience>& experiences) {
  model_->update(experiences);
  resetView();
}

void SyncPlanningLoop::filterViews(const void* key, const std::function<ViewFilter()>& makeFilter) {
  if (viewPending_ || key != filterKey_) {
    auto view = model_->view();
    planner_->setModel(key != nullptr ? makeFilter()(std::move(view)) : std::move(view));
  }
  viewPending_ = false;
  filterKey_ = key;
}

void SyncPlanningLoop::refreshView() { resetView(); }

int SyncPlanningLoop::act(const rl_common::State& s, Clock::time_point due, bool planning) {
  if (!planning) {
    lastRollouts_ = 0;
    return 0;
  }
  // A dynamic-programming planner without a budget solves to convergence; a search runs
  // until the action is due.
  rl_common::PlanningBudget budget;
  if (rollouts_ > 0) {
    budget = rl_common::PlanningBudget::ofRollouts(rollouts_);
  } else if (search_ != nullptr) {
    budget = rl_common::PlanningBudget::until(due);
  }
  lastRollouts_ = planner_->plan(s, budget);
  return planner_->bestAction(s);
}

void SyncPlanningLoop::replaceModel(std::unique_ptr<rl_common::MDPModel> model) {
  model_ = std::move(model);
  planner_->setModel(model_->view());
  filterKey_ = nullptr;  // a pending update stays pending, as it was before the relabelling
}

void SyncPlanningLoop::forEachSearchPlanner(const std::function<void(UctPlanner&)>& f) {
  if (search_ != nullptr) f(*search_);
}

rl_common::State SyncPlanningLoop::modelInput(const rl_common::State& s,
                                              const std::vector<int>& history) {
  if (search_ == nullptr) return s;
  search_->setActionHistory(history);
  return search_->modelInput(s);
}

// ---- real time ----

namespace {

std::vector<std::unique_ptr<rl_common::Planner>> asPlanners(
    std::vector<std::unique_ptr<UctPlanner>> planners, std::vector<UctPlanner*>* typed) {
  std::vector<std::unique_ptr<rl_common::Planner>> out;
  for (auto& p : planners) {
    if (p == nullptr) throw std::invalid_argument("RealTimePlanningLoop: null planner");
    typed->push_back(p.get());
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace

RealTimePlanningLoop::RealTimePlanningLoop(std::unique_ptr<rl_common::MDPModel> model,
                                           std::vector<std::unique_ptr<UctPlanner>> planners,
                                           const RealTimePlanner::Config& config)
    : config_(config) {
  auto untyped = asPlanners(std::move(planners), &search_);
  realTime_ = std::make_unique<RealTimePlanner>(std::move(model), std::move(untyped), config_);
}

RealTimePlanningLoop::~RealTimePlanningLoop() { stop(); }

void RealTimePlanningLoop::stop() noexcept {
  try {
    realTime_->stop();
  } catch (...) {
    // A worker's failure was already reported by act(); nothing is left to clean up.
  }
}

void RealTimePlanningLoop::filterViews(const void* key,
                                       const std::function<ViewFilter()>& makeFilter) {
  if (key != filterKey_) realTime_->setViewFilter(key != nullptr ? makeFilter() : nullptr);
  filterKey_ = key;
}

int RealTimePlanningLoop::act(const rl_common::State& s, Clock::time_point due, bool) {
  return realTime_->act(s, due);  // the threads plan whether or not the action is used
}

void RealTimePlanningLoop::waitUntil(Clock::time_point due) { std::this_thread::sleep_until(due); }

void RealTimePlanningLoop::replaceModel(std::unique_ptr<rl_common::MDPModel> model) {
  // The planners keep their values; the planner's own order (and so search_) is kept.
  auto planners = realTime_->releasePlanners();
  realTime_.reset();
  filterKey_ = nullptr;  // a new real-time planner has no view filter
  realTime_ = std::make_unique<RealTimePlanner>(std::move(model), std::move(planners), config_);
}

void RealTimePlanningLoop::forEachSearchPlanner(const std::function<void(UctPlanner&)>& f) {
  std::size_t k = 0;
  // planner k is held by forEachPlanner while search_[k], the same object, is used.
  realTime_->forEachPlanner([&](rl_common::Planner&) { f(*search_[k++]); });
}

rl_common::State RealTimePlanningLoop::modelInput(const rl_common::State& s,
                                                  const std::vector<int>& history) {
  forEachSearchPlanner([&](UctPlanner& p) { p.setActionHistory(history); });
  return realTime_->withPlanner([&](rl_common::Planner&) { return search_[0]->modelInput(s); });
}

}  // namespace rl_agent
