/**
 * PlanningLoop: how a model-based agent learns and plans between two actions, behind one
 * interface, so the agent never asks which of the two it runs.
 *
 *   SyncPlanningLoop      each step learns from the last transition, then plans (a rollout
 *                         budget, until the action is due, or a dynamic-programming planner to
 *                         convergence) before acting: with a rollout budget the same seed gives
 *                         the same run.
 *   RealTimePlanningLoop  the RTMBA architecture (RealTimePlanner; Hester, Quinlan & Stone,
 *                         ICRA 2012): model learning and K search threads run beside the agent,
 *                         which acts when the action is due.
 *
 * The loop owns the model and the planners. Search planners (UCT) are kept by their type, so
 * the agent reaches their action history, UCB bound and records without a downcast.
 */
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <vector>

#include "rl_agent/planner/real_time_planner.h"
#include "rl_agent/planner/state_space_planner.h"
#include "rl_agent/planner/uct_planner.h"
#include "rl_common/experience.h"
#include "rl_common/mdp_model.h"
#include "rl_common/planner.h"

namespace rl_agent {

class PlanningLoop {
 public:
  using Clock = std::chrono::steady_clock;
  using ViewFilter = RealTimePlanner::ViewFilter;

  virtual ~PlanningLoop() = default;

  /// Learns from one step's experience (synchronously now, or queued for the model thread).
  virtual void learn(const rl_common::Experience& e) = 0;
  /// Learns from experiences given before the first step (seeds); the planners see the model
  /// at once, unfiltered.
  virtual void learnAll(const std::vector<rl_common::Experience>& experiences) = 0;
  /// Filters the planners' views of the model from now on (StepDeferral's one-way steps).
  /// `key` changes whenever the filter would wrap differently (null: no filter); the planners
  /// get a new view only then (a new view caps the search tree's counts) or, synchronously,
  /// when a model update is waiting for it.
  virtual void filterViews(const void* key, const std::function<ViewFilter()>& makeFilter) = 0;
  /// The model's intrinsic switch changed: plan on its current view, unfiltered (in real time
  /// the model thread takes the new view after the next experience).
  virtual void refreshView() = 0;
  /// Plans from `s` and returns the planner's greedy action, due at `due`. `planning` false: the
  /// action will not be used (random exploration) and a synchronous loop does not plan.
  virtual int act(const rl_common::State& s, Clock::time_point due, bool planning) = 0;
  /// Keeps the action rate when the action was chosen elsewhere (the task-phase planner).
  virtual void waitUntil(Clock::time_point due) = 0;
  /// Rollouts (or solver iterations) spent on the last act().
  virtual long lastRollouts() const = 0;
  /// Seconds the last learn() spent updating the model (0 in real time).
  virtual double lastLearnSeconds() const = 0;
  /// The planner's Q(s, ·) (averaged over search threads); empty if it has none.
  virtual std::vector<double> qValues(const rl_common::State& s) = 0;
  /// The model's latest view; thread-safe.
  virtual std::shared_ptr<const rl_common::ModelView> latestView() const = 0;
  /// Replaces the model (already trained) and plans on it with the same planners, keeping
  /// their values; view filters are dropped.
  virtual void replaceModel(std::unique_ptr<rl_common::MDPModel> model) = 0;
  /// Calls f on each search planner, one at a time under the loop's access rules; none for a
  /// dynamic-programming planner.
  virtual void forEachSearchPlanner(const std::function<void(UctPlanner&)>& f) = 0;
  /// The model's query input for `s` after the actions `history` (search planners only).
  virtual rl_common::State modelInput(const rl_common::State& s,
                                      const std::vector<int>& history) = 0;
  /// The dynamic-programming planner, or null for search planners.
  virtual const StateSpacePlanner* statePlanner() const = 0;
  virtual bool realTime() const = 0;
  /// Stops background threads (real time); idempotent, never throws.
  virtual void stop() noexcept = 0;
};

class SyncPlanningLoop : public PlanningLoop {
 public:
  /// One search planner. `rollouts` > 0: that many rollouts a step; 0: until the action is
  /// due. `lazyViews`: a model update waits for the next filterViews() to reach the planner.
  SyncPlanningLoop(std::unique_ptr<rl_common::MDPModel> model, std::unique_ptr<UctPlanner> planner,
                   long rollouts, bool lazyViews);
  /// One dynamic-programming planner. `rollouts` > 0: at most that many iterations; 0: to
  /// convergence.
  SyncPlanningLoop(std::unique_ptr<rl_common::MDPModel> model,
                   std::unique_ptr<StateSpacePlanner> planner, long rollouts, bool lazyViews);

  void learn(const rl_common::Experience& e) override;
  void learnAll(const std::vector<rl_common::Experience>& experiences) override;
  void filterViews(const void* key, const std::function<ViewFilter()>& makeFilter) override;
  void refreshView() override;
  int act(const rl_common::State& s, Clock::time_point due, bool planning) override;
  void waitUntil(Clock::time_point) override {}
  long lastRollouts() const override { return lastRollouts_; }
  double lastLearnSeconds() const override { return lastLearnSeconds_; }
  std::vector<double> qValues(const rl_common::State& s) override { return planner_->qValues(s); }
  std::shared_ptr<const rl_common::ModelView> latestView() const override { return model_->view(); }
  void replaceModel(std::unique_ptr<rl_common::MDPModel> model) override;
  void forEachSearchPlanner(const std::function<void(UctPlanner&)>& f) override;
  rl_common::State modelInput(const rl_common::State& s, const std::vector<int>& history) override;
  const StateSpacePlanner* statePlanner() const override { return dp_; }
  bool realTime() const override { return false; }
  void stop() noexcept override {}

 private:
  SyncPlanningLoop(std::unique_ptr<rl_common::MDPModel> model,
                   std::unique_ptr<rl_common::Planner> planner, long rollouts, bool lazyViews,
                   UctPlanner* search, StateSpacePlanner* dp);
  /// Hands the model's view to the planner, unfiltered.
  void resetView();

  std::unique_ptr<rl_common::MDPModel> model_;
  std::unique_ptr<rl_common::Planner> planner_;
  UctPlanner* search_ = nullptr;
  StateSpacePlanner* dp_ = nullptr;
  long rollouts_ = 0;
  bool lazyViews_ = false;
  bool viewPending_ = false;  ///< lazyViews: a model update the planner has not seen yet
  const void* filterKey_ = nullptr;
  long lastRollouts_ = 0;
  double lastLearnSeconds_ = 0.0;
};

class RealTimePlanningLoop : public PlanningLoop {
 public:
  /// Root-parallel search over `planners` (one per search thread, at least one).
  RealTimePlanningLoop(std::unique_ptr<rl_common::MDPModel> model,
                       std::vector<std::unique_ptr<UctPlanner>> planners,
                       const RealTimePlanner::Config& config);
  ~RealTimePlanningLoop() override;

  void learn(const rl_common::Experience& e) override { realTime_->addExperience(e); }
  void learnAll(const std::vector<rl_common::Experience>& experiences) override {
    realTime_->addExperiences(experiences);
  }
  void filterViews(const void* key, const std::function<ViewFilter()>& makeFilter) override;
  void refreshView() override {}
  int act(const rl_common::State& s, Clock::time_point due, bool planning) override;
  void waitUntil(Clock::time_point due) override;
  long lastRollouts() const override { return realTime_->lastActRollouts(); }
  double lastLearnSeconds() const override { return 0.0; }
  std::vector<double> qValues(const rl_common::State& s) override { return realTime_->qValues(s); }
  std::shared_ptr<const rl_common::ModelView> latestView() const override {
    return realTime_->latestView();
  }
  void replaceModel(std::unique_ptr<rl_common::MDPModel> model) override;
  void forEachSearchPlanner(const std::function<void(UctPlanner&)>& f) override;
  rl_common::State modelInput(const rl_common::State& s, const std::vector<int>& history) override;
  const StateSpacePlanner* statePlanner() const override { return nullptr; }
  bool realTime() const override { return true; }
  void stop() noexcept override;

 private:
  RealTimePlanner::Config config_;
  std::vector<UctPlanner*> search_;  ///< the planners realTime_ owns, in its order
  std::unique_ptr<RealTimePlanner> realTime_;
  const void* filterKey_ = nullptr;
};

}  // namespace rl_agent
