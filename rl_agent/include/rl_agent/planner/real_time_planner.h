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
 *  - planning (K workers): each repeatedly runs a small budget of rollouts (`rolloutsPerSlice`)
 *    from the latest published root on its own planner. With K > 1 this is root-parallel
 *    search (Chaslot, Winands & van den Herik, "Parallel Monte-Carlo Tree Search", CG 2008):
 *    independent trees with their own seeds, whose root values act() averages; the trees
 *    share only the immutable model view, so the threads never wait for each other.
 *
 * Locking: planner k is only touched under its mutex (a slice of rollouts, setModel,
 * bestAction, withPlanner). Short calls (act's choice, setModel, withPlanner, forEachPlanner)
 * announce themselves first, and the planning threads stop taking new slices until they are
 * through, so they wait for at most one slice. A call that needs several planners locks them
 * in index order. The queue, the root, the stop flag and the first worker error live under
 * `control_`; no thread holds `control_` while waiting for a planner's mutex. The learner
 * (`model_`) is touched by the model-learning thread only.
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
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "rl_common/experience.h"
#include "rl_common/mdp_model.h"
#include "rl_common/planner.h"
#include "rl_common/random.h"

namespace rl_agent {

class RealTimePlanner {
 public:
  struct Config {
    long rolloutsPerSlice = 1;  ///< rollouts a planning thread runs per hold of its planner
    std::uint64_t seed = 0;     ///< ties between the averaged values of several trees
  };

  /// Starts the two worker threads after handing the planner the model's initial view.
  /// Throws std::invalid_argument for a null model or planner, a null view, or a bad config.
  RealTimePlanner(std::unique_ptr<rl_common::MDPModel> model,
                  std::unique_ptr<rl_common::Planner> planner);
  RealTimePlanner(std::unique_ptr<rl_common::MDPModel> model,
                  std::unique_ptr<rl_common::Planner> planner, const Config& config);
  /// One planning thread per planner (root-parallel search). Throws std::invalid_argument for
  /// an empty list or a null planner too.
  RealTimePlanner(std::unique_ptr<rl_common::MDPModel> model,
                  std::vector<std::unique_ptr<rl_common::Planner>> planners, const Config& config);
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
  /// then returns the greedy action in `s`: the planner's, or with several planners the best of
  /// their averaged values in `s` (ties at random; planner 0's choice if none has values). A
  /// deadline in the past returns at once. Rethrows a worker's exception; throws
  /// std::runtime_error once stopped. Call it from one thread.
  int act(const rl_common::State& s, std::chrono::steady_clock::time_point deadline);

  /// Stops and joins both workers; idempotent and safe from any thread (not from inside
  /// withPlanner). Rethrows a worker's exception not yet reported by act().
  void stop();
  /// False once stop() was called or a worker failed.
  bool running() const;
  /// stop(), then hands the planners back (e.g. to plan on a rebuilt model); the model is
  /// dropped. Afterwards act(), withPlanner() and forEachPlanner() must not be called.
  std::vector<std::unique_ptr<rl_common::Planner>> releasePlanners();

  /// Calls f(planner) with exclusive access to planner 0 (the only one unless several were
  /// given), e.g. to read values; the planning threads pause after their current slice.
  /// Returns f's result.
  template <class F>
  decltype(auto) withPlanner(F&& f) {
    PlannerAccess access(*this, 0, 1);
    return std::forward<F>(f)(*planners_[0]);
  }
  /// Calls f(planner) for every planner in turn, each with exclusive access, e.g. to set the
  /// action history of every search tree.
  template <class F>
  void forEachPlanner(F&& f) {
    for (std::size_t k = 0; k < planners_.size(); ++k) {
      PlannerAccess access(*this, k, 1);
      f(*planners_[k]);
    }
  }
  /// The action values in `s`: the planner's, or the mean over the planners that have values
  /// for `s` (empty if none has).
  std::vector<double> qValues(const rl_common::State& s);
  /// Number of planners, each with its planning thread.
  std::size_t numSearchThreads() const { return planners_.size(); }

  /// The model view the planner plans on now (the initial view before any update), before the
  /// view filter.
  std::shared_ptr<const rl_common::ModelView> latestView() const;

  /// What the planners plan on: filter(view) of every model view from now on (and of the
  /// latest one, at once); null: the views themselves. The filter runs on the model thread
  /// and on the caller's, so it must only read what it owns (e.g. an immutable list).
  using ViewFilter = std::function<std::shared_ptr<const rl_common::ModelView>(
      std::shared_ptr<const rl_common::ModelView>)>;
  void setViewFilter(ViewFilter filter);

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
  /// Exclusive, prioritised access to planners first .. first+count-1 for a scope (locked in
  /// index order).
  class PlannerAccess {
   public:
    PlannerAccess(RealTimePlanner& owner, std::size_t first, std::size_t count);
    ~PlannerAccess();
    PlannerAccess(const PlannerAccess&) = delete;
    PlannerAccess& operator=(const PlannerAccess&) = delete;

   private:
    RealTimePlanner& owner_;
    std::vector<std::unique_lock<std::mutex>> locks_;
  };

  /// The mean values in s over the planners that have them (the caller holds all of them).
  std::vector<double> meanValues(const rl_common::State& s) const;
  void modelLoop();
  void planLoop(std::size_t index);
  void fail(std::exception_ptr error);
  void rethrowUnreportedLocked();
  void notifyAll();

  const Config config_;
  std::unique_ptr<rl_common::MDPModel> model_;                 // model-learning thread only
  std::vector<std::unique_ptr<rl_common::Planner>> planners_;  // planner k under mutexes_[k]
  std::vector<std::unique_ptr<std::mutex>> mutexes_;
  rl_common::Random tieRng_;  // act() only

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
  /// Serialises the two writers of the planners' model (the model thread's new views and
  /// setViewFilter), so that the last filter set is the one planned on; taken before any
  /// planner's lock.
  std::mutex viewMutex_;
  ViewFilter filter_;  ///< guarded by viewMutex_

  std::atomic<long> rollouts_{0};
  std::atomic<long> rolloutsAtLastAct_{0};
  std::atomic<long> lastActRollouts_{0};
  std::atomic<long> modelUpdates_{0};
  std::atomic<long> experiencesLearned_{0};

  std::mutex joinMutex_;  // serialises stop()
  std::thread modelThread_;
  std::vector<std::thread> planThreads_;
};

}  // namespace rl_agent
