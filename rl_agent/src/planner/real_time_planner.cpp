#include "rl_agent/planner/real_time_planner.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rl_agent {

using rl_common::Experience;
using rl_common::State;

RealTimePlanner::RealTimePlanner(std::unique_ptr<rl_common::MDPModel> model,
                                 std::unique_ptr<rl_common::Planner> planner)
    : RealTimePlanner(std::move(model), std::move(planner), Config()) {}

namespace {

std::vector<std::unique_ptr<rl_common::Planner>> one(std::unique_ptr<rl_common::Planner> p) {
  std::vector<std::unique_ptr<rl_common::Planner>> v;
  v.push_back(std::move(p));
  return v;
}

}  // namespace

RealTimePlanner::RealTimePlanner(std::unique_ptr<rl_common::MDPModel> model,
                                 std::unique_ptr<rl_common::Planner> planner, const Config& config)
    : RealTimePlanner(std::move(model), one(std::move(planner)), config) {}

RealTimePlanner::RealTimePlanner(std::unique_ptr<rl_common::MDPModel> model,
                                 std::vector<std::unique_ptr<rl_common::Planner>> planners,
                                 const Config& config)
    : config_(config),
      model_(std::move(model)),
      planners_(std::move(planners)),
      tieRng_(config.seed) {
  if (!model_) {
    throw std::invalid_argument("RealTimePlanner::RealTimePlanner(): model is null");
  }
  if (planners_.empty()) {
    throw std::invalid_argument("RealTimePlanner::RealTimePlanner(): no planner");
  }
  for (const auto& p : planners_) {
    if (!p) throw std::invalid_argument("RealTimePlanner::RealTimePlanner(): planner is null");
    mutexes_.push_back(std::make_unique<std::mutex>());
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
  for (auto& p : planners_) p->setModel(latestView_);
  // No worker runs yet, so the members above need no lock; thread creation orders them.
  modelThread_ = std::thread(&RealTimePlanner::modelLoop, this);
  try {
    for (std::size_t k = 0; k < planners_.size(); ++k) {
      planThreads_.emplace_back(&RealTimePlanner::planLoop, this, k);
    }
  } catch (...) {
    {
      std::lock_guard<std::mutex> lock(control_);
      stopping_ = true;
    }
    notifyAll();
    modelThread_.join();
    for (auto& t : planThreads_) t.join();
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
  int action;
  if (planners_.size() == 1) {
    action = withPlanner([&s](rl_common::Planner& p) { return p.bestAction(s); });
  } else {
    PlannerAccess all(*this, 0, planners_.size());
    const std::vector<double> q = meanValues(s);
    if (q.empty()) {
      action = planners_[0]->bestAction(s);
    } else {
      // Near-equal values are ties, as in UctPlanner::bestAction.
      const double best = *std::max_element(q.begin(), q.end());
      std::vector<int> ties;
      for (std::size_t a = 0; a < q.size(); ++a) {
        if (q[a] >= best - 1e-4) ties.push_back(static_cast<int>(a));
      }
      action = ties[ties.size() > 1 ? static_cast<std::size_t>(
                                          tieRng_.uniformInt(0, static_cast<int>(ties.size()) - 1))
                                    : 0];
    }
  }
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
  for (auto& t : planThreads_) {
    if (t.joinable()) t.join();
  }
  std::lock_guard<std::mutex> lock(control_);
  rethrowUnreportedLocked();
}

std::vector<std::unique_ptr<rl_common::Planner>> RealTimePlanner::releasePlanners() {
  stop();  // every worker is joined: no lock is needed
  return std::move(planners_);
}

std::vector<double> RealTimePlanner::meanValues(const State& s) const {
  std::vector<double> sum;
  int trees = 0;
  for (const auto& p : planners_) {
    const std::vector<double> q = p->qValues(s);
    if (q.empty() || (!sum.empty() && q.size() != sum.size())) continue;
    if (sum.empty()) sum.assign(q.size(), 0.0);
    for (std::size_t a = 0; a < q.size(); ++a) sum[a] += q[a];
    ++trees;
  }
  for (double& v : sum) v /= trees;
  return sum;
}

std::vector<double> RealTimePlanner::qValues(const State& s) {
  PlannerAccess all(*this, 0, planners_.size());
  return meanValues(s);
}

bool RealTimePlanner::running() const {
  std::lock_guard<std::mutex> lock(control_);
  return !stopping_;
}

std::shared_ptr<const rl_common::ModelView> RealTimePlanner::latestView() const {
  std::lock_guard<std::mutex> lock(control_);
  return latestView_;
}

void RealTimePlanner::setViewFilter(ViewFilter filter) {
  std::lock_guard<std::mutex> serial(viewMutex_);
  filter_ = std::move(filter);
  const auto view = latestView();
  const auto planned = filter_ ? filter_(view) : view;
  forEachPlanner([&planned](rl_common::Planner& p) { p.setModel(planned); });
}

RealTimePlanner::PlannerAccess::PlannerAccess(RealTimePlanner& owner, std::size_t first,
                                              std::size_t count)
    : owner_(owner) {
  {
    std::lock_guard<std::mutex> lock(owner_.control_);
    ++owner_.priorityWaiters_;
  }
  try {
    for (std::size_t k = first; k < first + count; ++k) locks_.emplace_back(*owner_.mutexes_[k]);
  } catch (...) {
    locks_.clear();
    {
      std::lock_guard<std::mutex> lock(owner_.control_);
      --owner_.priorityWaiters_;
    }
    owner_.planCv_.notify_all();
    throw;
  }
}

RealTimePlanner::PlannerAccess::~PlannerAccess() {
  locks_.clear();  // release the planners before taking control_
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
      std::lock_guard<std::mutex> serial(viewMutex_);
      const auto planned = filter_ ? filter_(view) : view;
      forEachPlanner([&planned](rl_common::Planner& p) { p.setModel(planned); });
      std::lock_guard<std::mutex> lock(control_);
      latestView_ = std::move(view);
    }
  } catch (...) {
    fail(std::current_exception());
  }
}

void RealTimePlanner::planLoop(std::size_t index) {
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
        std::lock_guard<std::mutex> lock(*mutexes_[index]);
        done = planners_[index]->plan(root, budget);
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
