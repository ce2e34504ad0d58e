#include "rl_agent/planner/real_time_planner.h"

#include <stdexcept>
#include <string>

namespace rl_agent {

using rl_common::Experience;
using rl_common::State;

RealTimePlanner::RealTimePlanner(std::unique_ptr<rl_common::MDPModel> model,
                                 std::unique_ptr<rl_common::Planner> planner)
    : RealTimePlanner(std::move(model), std::move(planner), Config()) {}

RealTimePlanner::RealTimePlanner(std::unique_ptr<rl_common::MDPModel> model,
                                 std::unique_ptr<rl_common::Planner> planner, const Config& config)
    : config_(config), model_(std::move(model)), planner_(std::move(planner)) {
  if (!model_) {
    throw std::invalid_argument("RealTimePlanner::RealTimePlanner(): model is null");
  }
  if (!planner_) {
    throw std::invalid_argument("RealTimePlanner::RealTimePlanner(): planner is null");
  }
  if (config_.rolloutsPerSlice < 1) {
    throw std::invalid_argument(
        "RealTimePlanner::RealTimePlanner(): rolloutsPerSlice must be at least 1 (got " +
        std::to_string(config_.rolloutsPerSlice) + ")");
  }
  latestView_ = model_->view();
  if (!latestView_) {
    throw std::invalid_argument("RealTimePlanner::RealTimePlanner(): the model's view is null");
  }
  planner_->setModel(latestView_);
  // No worker runs yet, so the members above need no lock; thread creation orders them.
  modelThread_ = std::thread(&RealTimePlanner::modelLoop, this);
  try {
    planThread_ = std::thread(&RealTimePlanner::planLoop, this);
  } catch (...) {
    {
      std::lock_guard<std::mutex> lock(control_);
      stopping_ = true;
    }
    notifyAll();
    modelThread_.join();
    throw;
  }
}

RealTimePlanner::~RealTimePlanner() {
  try {
    stop();
  } catch (...) {
    // A worker's error nobody asked for: the destructor must not throw.
  }
}

void RealTimePlanner::addExperience(const Experience& e) {
  {
    std::lock_guard<std::mutex> lock(control_);
    if (failed_) {
      return;
    }
    if (stopping_) {
      throw std::logic_error("RealTimePlanner::addExperience(): called after stop()");
    }
    queue_.push_back(e);
  }
  workCv_.notify_one();
}

void RealTimePlanner::addExperiences(const std::vector<Experience>& experiences) {
  {
    std::lock_guard<std::mutex> lock(control_);
    if (failed_) {
      return;
    }
    if (stopping_) {
      throw std::logic_error("RealTimePlanner::addExperiences(): called after stop()");
    }
    queue_.insert(queue_.end(), experiences.begin(), experiences.end());
  }
  workCv_.notify_one();
}

int RealTimePlanner::act(const State& s, std::chrono::steady_clock::time_point deadline) {
  {
    std::lock_guard<std::mutex> lock(control_);
    rethrowUnreportedLocked();
    if (stopping_) {
      throw std::runtime_error("RealTimePlanner::act(): the planner is stopped");
    }
    root_ = s;
    hasRoot_ = true;
    ++rootVersion_;
  }
  planCv_.notify_all();
  {
    std::unique_lock<std::mutex> lock(control_);
    actCv_.wait_until(lock, deadline, [this] { return stopping_; });
    rethrowUnreportedLocked();
    if (stopping_) {
      throw std::runtime_error("RealTimePlanner::act(): the planner was stopped");
    }
  }
  const int action = withPlanner([&s](rl_common::Planner& p) { return p.bestAction(s); });
  const long total = rollouts_.load();
  lastActRollouts_.store(total - rolloutsAtLastAct_.exchange(total));
  return action;
}

void RealTimePlanner::stop() {
  std::lock_guard<std::mutex> join(joinMutex_);
  {
    std::lock_guard<std::mutex> lock(control_);
    stopping_ = true;
  }
  notifyAll();
  if (modelThread_.joinable()) {
    modelThread_.join();
  }
  if (planThread_.joinable()) {
    planThread_.join();
  }
  std::lock_guard<std::mutex> lock(control_);
  rethrowUnreportedLocked();
}

std::unique_ptr<rl_common::Planner> RealTimePlanner::releasePlanner() {
  stop();
  std::lock_guard<std::mutex> lock(plannerMutex_);
  return std::move(planner_);
}

bool RealTimePlanner::running() const {
  std::lock_guard<std::mutex> lock(control_);
  return !stopping_;
}

std::shared_ptr<const rl_common::ModelView> RealTimePlanner::latestView() const {
  std::lock_guard<std::mutex> lock(control_);
  return latestView_;
}

RealTimePlanner::PlannerAccess::PlannerAccess(RealTimePlanner& owner) : owner_(owner) {
  {
    std::lock_guard<std::mutex> lock(owner_.control_);
    ++owner_.priorityWaiters_;
  }
  try {
    lock_ = std::unique_lock<std::mutex>(owner_.plannerMutex_);
  } catch (...) {
    {
      std::lock_guard<std::mutex> lock(owner_.control_);
      --owner_.priorityWaiters_;
    }
    owner_.planCv_.notify_all();
    throw;
  }
}

RealTimePlanner::PlannerAccess::~PlannerAccess() {
  lock_.unlock();  // release the planner before taking control_
  {
    std::lock_guard<std::mutex> lock(owner_.control_);
    --owner_.priorityWaiters_;
  }
  owner_.planCv_.notify_all();
}

void RealTimePlanner::modelLoop() {
  try {
    std::vector<Experience> batch;
    while (true) {
      {
        std::unique_lock<std::mutex> lock(control_);
        workCv_.wait(lock, [this] { return failed_ || stopping_ || !queue_.empty(); });
        if (failed_ || queue_.empty()) {
          return;  // a worker failed, or stopping with nothing left to learn
        }
        batch.clear();
        batch.swap(queue_);
      }
      // The slow part, outside every lock: the planning thread keeps planning on the view.
      const bool changed = model_->update(batch);
      experiencesLearned_.fetch_add(static_cast<long>(batch.size()));
      modelUpdates_.fetch_add(1);
      if (!changed) {
        continue;
      }
      std::shared_ptr<const rl_common::ModelView> view = model_->view();
      if (!view) {
        throw std::runtime_error("RealTimePlanner: the model returned a null view");
      }
      withPlanner([&view](rl_common::Planner& p) { p.setModel(view); });
      std::lock_guard<std::mutex> lock(control_);
      latestView_ = std::move(view);
    }
  } catch (...) {
    fail(std::current_exception());
  }
}

void RealTimePlanner::planLoop() {
  try {
    State root;
    std::uint64_t seen = 0;
    const auto budget = rl_common::PlanningBudget::ofRollouts(config_.rolloutsPerSlice);
    while (true) {
      {
        std::unique_lock<std::mutex> lock(control_);
        planCv_.wait(lock, [this] { return stopping_ || (hasRoot_ && priorityWaiters_ == 0); });
        if (stopping_) {
          return;
        }
        if (rootVersion_ != seen) {
          root = root_;
          seen = rootVersion_;
        }
      }
      long done;
      {
        std::lock_guard<std::mutex> lock(plannerMutex_);
        done = planner_->plan(root, budget);
      }
      rollouts_.fetch_add(done);
    }
  } catch (...) {
    fail(std::current_exception());
  }
}

void RealTimePlanner::fail(std::exception_ptr error) {
  {
    std::lock_guard<std::mutex> lock(control_);
    if (!error_) {
      error_ = std::move(error);
    }
    failed_ = true;
    stopping_ = true;
  }
  notifyAll();
}

void RealTimePlanner::rethrowUnreportedLocked() {
  if (error_ && !errorReported_) {
    errorReported_ = true;
    std::rethrow_exception(error_);
  }
}

void RealTimePlanner::notifyAll() {
  workCv_.notify_all();
  planCv_.notify_all();
  actCv_.notify_all();
}

}  // namespace rl_agent
