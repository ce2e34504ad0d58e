/**
 * RealTimePlanner: the RTMBA real-time architecture, model learning, planning and acting in
 * parallel so that actions come at a fixed rate however slow learning and planning are.
 *
 * Hester, Quinlan & Stone, "RTMBA: A Real-Time Model-Based Reinforcement Learning
 * Architecture for Robot Control", ICRA 2012; used by TEXPLORE (Hester & Stone, Machine
 * Learning 90(3), 2013) and TEXPLORE-VANIR (the original's ParallelETUCT). Three threads:
 *
 *  - acting (the caller): addExperience() queues an experience and returns at once;
 *    act(s, deadline) publishes s as the planning root, sleeps until the deadline (a
 *    condition-variable wait, no busy-waiting) and returns the planner's greedy action in s.
 *  - model learning (a worker): waits for queued experiences, swaps the whole queue out,
 *    updates the MDPModel with the batch outside every lock the other threads use, then hands
 *    model->view() (an immutable view sharing structure with the learner, never a deep copy)
 *    to the planner with setModel().
 *  - planning (a worker): repeatedly runs a small budget of rollouts (`rolloutsPerSlice`) from
 *    the latest published root.
 *
 * Locking: `planner_` is only touched under `plannerMutex_` (a slice of rollouts, setModel,
 * bestAction, withPlanner). Short calls (bestAction, setModel, withPlanner) announce
 * themselves first, and the planning thread stops taking new slices until they are through, so
 * they wait for at most one slice. The queue, the root, the stop flag and the first worker
 * error live under `control_`; no thread holds `control_` while waiting for `plannerMutex_`.
 * The learner (`model_`) is touched by the model-learning thread only.
 *
 * Failures: the first exception thrown in a worker stops both workers and is rethrown, once, to
 * the next caller of act() or stop(); after that act() throws std::runtime_error. stop() and the
 * destructor join both workers (no detach, no cancel) and are idempotent; experiences queued
 * before stop() are still learned before the model thread ends (unless a worker failed).
 */
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "rl_common/experience.h"
#include "rl_common/mdp_model.h"
#include "rl_common/planner.h"

namespace rl_agent {

class RealTimePlanner {
 public:
  struct Config {
    long rolloutsPerSlice = 1;  ///< rollouts the planning thread runs per hold of the planner
  };

  /// Starts the two worker threads after handing the planner the model's initial view.
  /// Throws std::invalid_argument for a null model or planner, a null view, or a bad config.
  RealTimePlanner(std::unique_ptr<rl_common::MDPModel> model,
                  std::unique_ptr<rl_common::Planner> planner);
  RealTimePlanner(std::unique_ptr<rl_common::MDPModel> model,
                  std::unique_ptr<rl_common::Planner> planner, const Config& config);
  /// stop(), swallowing a worker's error that nobody collected.
  ~RealTimePlanner();

  RealTimePlanner(const RealTimePlanner&) = delete;
  RealTimePlanner& operator=(const RealTimePlanner&) = delete;

  /// Queues an experience for the model-learning thread; returns at once. Ignored after a
  /// worker failure (act() reports it); throws std::logic_error after stop().
  void addExperience(const rl_common::Experience& e);
  /// Queues several experiences at once (e.g. seeds).
  void addExperiences(const std::vector<rl_common::Experience>& experiences);

  /// Makes `s` the planning root, waits until `deadline` while the workers plan and learn,
  /// then returns the greedy action in `s`. A deadline in the past returns at once. Rethrows a
  /// worker's exception; throws std::runtime_error once stopped.
  int act(const rl_common::State& s, std::chrono::steady_clock::time_point deadline);

  /// Stops and joins both workers; idempotent and safe from any thread (not from inside
  /// withPlanner). Rethrows a worker's exception not yet reported by act().
  void stop();
  /// False once stop() was called or a worker failed.
  bool running() const;
  /// stop(), then hands the planner back (e.g. to plan on a rebuilt model); the model is
  /// dropped. Afterwards act() and withPlanner() must not be called.
  std::unique_ptr<rl_common::Planner> releasePlanner();

  /// Calls f(planner) with exclusive access to the planner, e.g. to set an action history or
  /// read values; the planning thread pauses after its current slice. Returns f's result.
  template <class F>
  decltype(auto) withPlanner(F&& f) {
    PlannerAccess access(*this);
    return std::forward<F>(f)(*planner_);
  }

  /// The model view the planner plans on now (the initial view before any update).
  std::shared_ptr<const rl_common::ModelView> latestView() const;

  /// Rollouts completed since the last act() returned (or since the start).
  long rolloutsSinceLastAct() const { return rollouts_.load() - rolloutsAtLastAct_.load(); }
  /// Rollouts completed between the previous act() returning and the last one returning.
  long lastActRollouts() const { return lastActRollouts_.load(); }
  /// Rollouts completed since the start.
  long totalRollouts() const { return rollouts_.load(); }
  /// Completed model updates (one per batch of experiences).
  long modelUpdates() const { return modelUpdates_.load(); }
  /// Experiences the model has learned from.
  long experiencesLearned() const { return experiencesLearned_.load(); }

  const Config& config() const { return config_; }

 private:
  /// Exclusive, prioritised access to the planner for the duration of a scope.
  class PlannerAccess {
   public:
    explicit PlannerAccess(RealTimePlanner& owner);
    ~PlannerAccess();
    PlannerAccess(const PlannerAccess&) = delete;
    PlannerAccess& operator=(const PlannerAccess&) = delete;

   private:
    RealTimePlanner& owner_;
    std::unique_lock<std::mutex> lock_;
  };

  void modelLoop();
  void planLoop();
  void fail(std::exception_ptr error);
  void rethrowUnreportedLocked();
  void notifyAll();

  const Config config_;
  std::unique_ptr<rl_common::MDPModel> model_;   // model-learning thread only
  std::unique_ptr<rl_common::Planner> planner_;  // under plannerMutex_
  std::mutex plannerMutex_;

  mutable std::mutex control_;
  std::condition_variable workCv_;  // model thread: experiences queued, or stopping
  std::condition_variable planCv_;  // planning thread: root published, priority done, stopping
  std::condition_variable actCv_;   // act(): stopping (a failure ends the wait early)
  std::vector<rl_common::Experience> queue_;
  rl_common::State root_;
  bool hasRoot_ = false;
  std::uint64_t rootVersion_ = 0;
  int priorityWaiters_ = 0;
  bool stopping_ = false;
  bool failed_ = false;
  std::exception_ptr error_;
  bool errorReported_ = false;
  std::shared_ptr<const rl_common::ModelView> latestView_;

  std::atomic<long> rollouts_{0};
  std::atomic<long> rolloutsAtLastAct_{0};
  std::atomic<long> lastActRollouts_{0};
  std::atomic<long> modelUpdates_{0};
  std::atomic<long> experiencesLearned_{0};

  std::mutex joinMutex_;  // serialises stop()
  std::thread modelThread_;
  std::thread planThread_;
};

}  // namespace rl_agent
