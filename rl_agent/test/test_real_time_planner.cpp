#include "rl_agent/planner/real_time_planner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "rl_agent/planner/uct_planner.h"

using rl_agent::RealTimePlanner;
using rl_agent::UctPlanner;
using rl_common::Experience;
using rl_common::State;
using rl_common::StateActionInfo;
using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

namespace {

/// What the test model did, shared with the test after the model is handed over.
struct Stats {
  std::atomic<long> experiences{0};
  std::atomic<long> updates{0};
  std::atomic<long> views{0};
};

/// The chain of states 0..5 (action 1 right, 0 left, arriving at 5 pays 1 and ends). Immutable;
/// `version` only tells views apart. With `throwOnQuery`, every query throws.
class ChainView : public rl_common::ModelView {
 public:
  ChainView(long version, bool throwOnQuery) : version_(version), throwOnQuery_(throwOnQuery) {}

  StateActionInfo query(const State& s, int a) const override {
    if (throwOnQuery_) {
      throw std::runtime_error("query failed");
    }
    StateActionInfo info;
    info.known = true;
    const float x = s[0];
    if (a == 1 && x >= 4.0f) {
      info.transitions = {{State{5.0f}, 1.0}};
      info.reward = 1.0f;
      info.termProb = 1.0f;
      return info;
    }
    info.transitions = {{State{a == 1 ? x + 1.0f : std::max(0.0f, x - 1.0f)}, 1.0}};
    return info;
  }

  long version() const { return version_; }

 private:
  const long version_;
  const bool throwOnQuery_;
};

/// A learner that only counts; its state is touched by the model-learning thread alone.
class CountingModel : public rl_common::MDPModel {
 public:
  struct Options {
    milliseconds updateDelay{0};
    bool throwOnUpdate = false;
    bool throwOnQuery = false;
  };
  CountingModel(std::shared_ptr<Stats> stats, Options options)
      : stats_(std::move(stats)), options_(options) {}

  bool update(const std::vector<Experience>& experiences) override {
    if (options_.throwOnUpdate) {
      throw std::runtime_error("boom");
    }
    if (options_.updateDelay.count() > 0) {
      std::this_thread::sleep_for(options_.updateDelay);  // a slow learner
    }
    stats_->experiences += static_cast<long>(experiences.size());
    ++stats_->updates;
    ++version_;
    return true;
  }

  std::shared_ptr<const rl_common::ModelView> view() const override {
    ++stats_->views;
    return std::make_shared<ChainView>(version_, options_.throwOnQuery);
  }

 private:
  std::shared_ptr<Stats> stats_;
  Options options_;
  long version_ = 0;
};

std::unique_ptr<UctPlanner> makePlanner(std::uint64_t seed = 1) {
  UctPlanner::Config c;
  c.numActions = 2;
  c.gamma = 0.9;
  c.featMin = {0.0f};
  c.featMax = {5.0f};
  return std::make_unique<UctPlanner>(c, seed);
}

std::unique_ptr<RealTimePlanner> makeRtp(const std::shared_ptr<Stats>& stats,
                                         CountingModel::Options options = {}) {
  return std::make_unique<RealTimePlanner>(std::make_unique<CountingModel>(stats, options),
                                           makePlanner());
}

Experience step(float x, int a) {
  return Experience{State{x}, a, 0.0f, State{a == 1 ? x + 1.0f : std::max(0.0f, x - 1.0f)}, false};
}

/// Acts with short deadlines until act() throws; returns the message ("" if it never did).
std::string actUntilThrows(RealTimePlanner& rtp) {
  for (int i = 0; i < 500; ++i) {
    try {
      rtp.act(State{0.0f}, Clock::now() + milliseconds(10));
    } catch (const std::exception& e) {
      return e.what();
    }
  }
  return "";
}

}  // namespace

TEST(RealTimePlanner, ActReturnsAtItsDeadline) {
  auto stats = std::make_shared<Stats>();
  auto rtp = makeRtp(stats);
  for (int i = 0; i < 3; ++i) {
    const auto deadline = Clock::now() + milliseconds(50);
    const int a = rtp->act(State{0.0f}, deadline);
    const auto returned = Clock::now();
    EXPECT_GE(returned, deadline);
    EXPECT_LT(returned, deadline + milliseconds(500));  // sanity only
    EXPECT_TRUE(a == 0 || a == 1);
  }
  // A deadline in the past returns at once (no timing assertion beyond sanity).
  const auto start = Clock::now();
  rtp->act(State{0.0f}, start - milliseconds(10));
  EXPECT_LT(Clock::now(), start + milliseconds(500));
}

TEST(RealTimePlanner, ExperiencesReachTheModel) {
  auto stats = std::make_shared<Stats>();
  auto rtp = makeRtp(stats);
  const auto initialView = rtp->latestView();
  for (int i = 0; i < 25; ++i) {
    rtp->addExperience(step(static_cast<float>(i % 5), i % 2));
  }
  rtp->addExperiences({step(0.0f, 1), step(1.0f, 1)});
  rtp->act(State{0.0f}, Clock::now() + milliseconds(20));
  rtp->stop();  // learns what is still queued, then joins
  EXPECT_EQ(stats->experiences.load(), 27);
  EXPECT_EQ(rtp->experiencesLearned(), 27);
  EXPECT_GE(rtp->modelUpdates(), 1);
  EXPECT_EQ(rtp->modelUpdates(), stats->updates.load());
  // Each update published a new view to the planner (plus the initial one).
  EXPECT_EQ(stats->views.load(), stats->updates.load() + 1);
  const auto latest = std::dynamic_pointer_cast<const ChainView>(rtp->latestView());
  ASSERT_NE(latest, nullptr);
  EXPECT_NE(latest, initialView);
  EXPECT_EQ(latest->version(), stats->updates.load());
  const auto version = rtp->withPlanner(
      [](rl_common::Planner& p) { return dynamic_cast<UctPlanner&>(p).modelVersion(); });
  EXPECT_EQ(version, static_cast<std::uint64_t>(stats->updates.load() + 1));
}

TEST(RealTimePlanner, PlanningThreadRollsOutBetweenActs) {
  auto stats = std::make_shared<Stats>();
  auto rtp = makeRtp(stats);
  EXPECT_EQ(rtp->totalRollouts(), 0);  // no root yet: nothing to plan from
  rtp->act(State{0.0f}, Clock::now() + milliseconds(100));
  EXPECT_GT(rtp->lastActRollouts(), 0);
  rtp->act(State{0.0f}, Clock::now() + milliseconds(100));
  EXPECT_GT(rtp->lastActRollouts(), 0);
  // Count-based, not time-based: once enough rollouts ran, the obvious action wins.
  const auto giveUp = Clock::now() + std::chrono::seconds(10);
  while (rtp->totalRollouts() < 3000 && Clock::now() < giveUp) {
    rtp->act(State{0.0f}, Clock::now() + milliseconds(50));
  }
  ASSERT_GE(rtp->totalRollouts(), 3000);
  EXPECT_EQ(rtp->act(State{0.0f}, Clock::now()), 1);
  const long done = rtp->totalRollouts();
  rtp->stop();
  EXPECT_FALSE(rtp->running());
  EXPECT_GE(rtp->totalRollouts(), done);
}

TEST(RealTimePlanner, StopJoinsWhileThreadsAreBusy) {
  auto stats = std::make_shared<Stats>();
  CountingModel::Options slow;
  slow.updateDelay = milliseconds(30);
  auto rtp = makeRtp(stats, slow);
  for (int i = 0; i < 10; ++i) {
    rtp->addExperience(step(static_cast<float>(i % 5), 1));
    rtp->act(State{static_cast<float>(i % 5)}, Clock::now() + milliseconds(5));
  }
  rtp->addExperience(step(0.0f, 1));
  const auto start = Clock::now();
  rtp->stop();  // the model thread is mid-update, the planning thread mid-rollout
  EXPECT_LT(Clock::now(), start + std::chrono::seconds(2));  // sanity only
  EXPECT_FALSE(rtp->running());
  EXPECT_EQ(stats->experiences.load(), 11);
  EXPECT_NO_THROW(rtp->stop());  // idempotent
  EXPECT_THROW(rtp->act(State{0.0f}, Clock::now()), std::runtime_error);
  EXPECT_THROW(rtp->addExperience(step(0.0f, 1)), std::logic_error);
  // Still usable for reading after the stop.
  EXPECT_FALSE(rtp->withPlanner([](rl_common::Planner& p) {
                    return dynamic_cast<UctPlanner&>(p).qValues(State{0.0f});
                  })
                   .empty());

  // The destructor alone joins busy threads too.
  auto other = makeRtp(stats, slow);
  other->addExperience(step(0.0f, 1));
  other->act(State{0.0f}, Clock::now() + milliseconds(5));
  other.reset();
}

TEST(RealTimePlanner, RepeatedStartAndStop) {
  auto stats = std::make_shared<Stats>();
  for (int i = 0; i < 40; ++i) {
    auto rtp = makeRtp(stats);
    if (i % 3 != 0) {
      rtp->addExperience(step(0.0f, 1));
    }
    if (i % 2 == 0) {
      rtp->act(State{0.0f}, Clock::now() + milliseconds(1));
    }
    if (i % 4 == 0) {
      rtp->stop();
      rtp->stop();
    }
    // otherwise the destructor stops it
  }
  SUCCEED();
}

TEST(RealTimePlanner, ModelUpdateExceptionSurfacesFromAct) {
  auto stats = std::make_shared<Stats>();
  CountingModel::Options throwing;
  throwing.throwOnUpdate = true;
  auto rtp = makeRtp(stats, throwing);
  rtp->addExperience(step(0.0f, 1));
  EXPECT_EQ(actUntilThrows(*rtp), "boom");
  EXPECT_FALSE(rtp->running());
  EXPECT_NO_THROW(rtp->addExperience(step(0.0f, 1)));                     // ignored after a failure
  EXPECT_THROW(rtp->act(State{0.0f}, Clock::now()), std::runtime_error);  // stopped
  EXPECT_NO_THROW(rtp->stop());  // already reported by act()
}

TEST(RealTimePlanner, ModelUpdateExceptionSurfacesFromStop) {
  auto stats = std::make_shared<Stats>();
  CountingModel::Options throwing;
  throwing.throwOnUpdate = true;
  auto rtp = makeRtp(stats, throwing);
  rtp->addExperience(step(0.0f, 1));
  try {
    rtp->stop();  // the queued experience is learned (and fails) before the join completes
    ADD_FAILURE() << "stop() did not rethrow the model's exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "boom");
  }
  EXPECT_NO_THROW(rtp->stop());

  // Nobody collects the error: the destructor swallows it.
  auto other = makeRtp(stats, throwing);
  other->addExperience(step(0.0f, 1));
  EXPECT_NO_THROW(other.reset());
}

TEST(RealTimePlanner, PlanningExceptionSurfacesFromAct) {
  auto stats = std::make_shared<Stats>();
  CountingModel::Options throwing;
  throwing.throwOnQuery = true;
  auto rtp = makeRtp(stats, throwing);
  EXPECT_EQ(actUntilThrows(*rtp), "query failed");
  EXPECT_NO_THROW(rtp->stop());
}

TEST(RealTimePlanner, RejectsBadConstruction) {
  auto stats = std::make_shared<Stats>();
  EXPECT_THROW(RealTimePlanner(nullptr, makePlanner()), std::invalid_argument);
  EXPECT_THROW(
      RealTimePlanner(std::make_unique<CountingModel>(stats, CountingModel::Options()), nullptr),
      std::invalid_argument);
  RealTimePlanner::Config c;
  c.rolloutsPerSlice = 0;
  EXPECT_THROW(RealTimePlanner(std::make_unique<CountingModel>(stats, CountingModel::Options()),
                               makePlanner(), c),
               std::invalid_argument);
}

namespace {

/// A planner with fixed values in every state; counts its rollouts.
class FixedValues : public rl_common::Planner {
 public:
  explicit FixedValues(std::vector<double> q) : q_(std::move(q)) {}
  void setModel(std::shared_ptr<const rl_common::ModelView> /*model*/) override { ++models; }
  long plan(const State& /*s*/, const rl_common::PlanningBudget& budget) override {
    rollouts += budget.rollouts;
    return budget.rollouts;
  }
  int bestAction(const State& /*s*/) override {
    return static_cast<int>(std::max_element(q_.begin(), q_.end()) - q_.begin());
  }
  std::vector<double> qValues(const State& /*s*/) const override { return q_; }
  std::atomic<long> rollouts{0};
  std::atomic<long> models{0};

 private:
  std::vector<double> q_;
};

}  // namespace

TEST(RealTimePlanner, SeveralSearchThreadsEachPlanAndActOnTheMeanValues) {
  // Tree 0 prefers action 0 (1.0 against 0.2), tree 1 action 1 (0.0 against 1.0): the means
  // are 0.5 and 0.6, so the root-parallel choice is action 1, which neither tree alone nor
  // tree 0 (the single-tree answer) gives.
  auto stats = std::make_shared<Stats>();
  std::vector<std::unique_ptr<rl_common::Planner>> planners;
  planners.push_back(std::make_unique<FixedValues>(std::vector<double>{1.0, 0.2}));
  planners.push_back(std::make_unique<FixedValues>(std::vector<double>{0.0, 1.0}));
  auto* first = static_cast<FixedValues*>(planners[0].get());
  auto* second = static_cast<FixedValues*>(planners[1].get());
  RealTimePlanner rtp(std::make_unique<CountingModel>(stats, CountingModel::Options()),
                      std::move(planners), RealTimePlanner::Config());
  EXPECT_EQ(rtp.numSearchThreads(), 2u);
  EXPECT_EQ(rtp.act(State{0.0f}, Clock::now() + milliseconds(50)), 1);
  const std::vector<double> mean = rtp.qValues(State{0.0f});
  ASSERT_EQ(mean.size(), 2u);
  EXPECT_DOUBLE_EQ(mean[0], 0.5);
  EXPECT_DOUBLE_EQ(mean[1], 0.6);
  // Both threads planned; every planner gets every model view.
  const auto giveUp = Clock::now() + std::chrono::seconds(10);
  while ((first->rollouts == 0 || second->rollouts == 0) && Clock::now() < giveUp) {
    rtp.act(State{0.0f}, Clock::now() + milliseconds(10));
  }
  EXPECT_GT(first->rollouts.load(), 0);
  EXPECT_GT(second->rollouts.load(), 0);
  rtp.addExperience(step(0.0f, 1));
  rtp.stop();
  EXPECT_EQ(first->models.load(), second->models.load());
  EXPECT_EQ(first->models.load(), stats->updates.load() + 1);
  int visited = 0;
  const auto planners2 = rtp.releasePlanners();
  for (const auto& p : planners2) visited += p != nullptr ? 1 : 0;
  EXPECT_EQ(visited, 2);
}

TEST(RealTimePlanner, TwoUctTreesLearnTheChain) {
  // Real planners on one model: both trees search, and their mean values pick "right".
  auto stats = std::make_shared<Stats>();
  std::vector<std::unique_ptr<rl_common::Planner>> planners;
  planners.push_back(makePlanner(1));
  planners.push_back(makePlanner(2));
  RealTimePlanner rtp(std::make_unique<CountingModel>(stats, CountingModel::Options()),
                      std::move(planners), RealTimePlanner::Config());
  const auto giveUp = Clock::now() + std::chrono::seconds(10);
  while (rtp.totalRollouts() < 6000 && Clock::now() < giveUp) {
    rtp.act(State{0.0f}, Clock::now() + milliseconds(50));
  }
  ASSERT_GE(rtp.totalRollouts(), 6000);
  rtp.forEachPlanner([&](rl_common::Planner& p) {
    EXPECT_GT(static_cast<UctPlanner&>(p).stateVisits(State{0.0f}), 100);
  });
  EXPECT_EQ(rtp.act(State{0.0f}, Clock::now()), 1);
}

TEST(RealTimePlanner, RejectsAnEmptyOrNullPlannerList) {
  auto stats = std::make_shared<Stats>();
  EXPECT_THROW(RealTimePlanner(std::make_unique<CountingModel>(stats, CountingModel::Options()),
                               std::vector<std::unique_ptr<rl_common::Planner>>{},
                               RealTimePlanner::Config()),
               std::invalid_argument);
  std::vector<std::unique_ptr<rl_common::Planner>> withNull;
  withNull.push_back(makePlanner());
  withNull.push_back(nullptr);
  EXPECT_THROW(RealTimePlanner(std::make_unique<CountingModel>(stats, CountingModel::Options()),
                               std::move(withNull), RealTimePlanner::Config()),
               std::invalid_argument);
}

namespace {

/// The chain mirrored: going left from 1 pays 1 and ends; nothing else pays.
class LeftPays : public rl_common::ModelView {
 public:
  explicit LeftPays(std::shared_ptr<const rl_common::ModelView> base) : base_(std::move(base)) {}
  StateActionInfo query(const State& s, int a) const override {
    StateActionInfo info = base_->query(s, a);
    info.reward = 0.0f;
    info.termProb = 0.0f;
    if (a == 1 && s[0] >= 4.0f) info.transitions = {{State{5.0f}, 1.0}};
    if (a == 0 && s[0] <= 1.0f) {
      info.reward = 1.0f;
      info.termProb = 1.0f;
    }
    return info;
  }

 private:
  std::shared_ptr<const rl_common::ModelView> base_;
};

}  // namespace

TEST(RealTimePlanner, AViewFilterIsWhatThePlannersPlanOnThroughModelUpdates) {
  auto stats = std::make_shared<Stats>();
  RealTimePlanner rtp(std::make_unique<CountingModel>(stats, CountingModel::Options()),
                      makePlanner(), RealTimePlanner::Config());
  auto filtered = std::make_shared<std::atomic<long>>(0);
  rtp.setViewFilter([filtered](std::shared_ptr<const rl_common::ModelView> view) {
    ++*filtered;
    return std::shared_ptr<const rl_common::ModelView>(std::make_shared<LeftPays>(view));
  });
  EXPECT_EQ(filtered->load(), 1) << "the latest view is filtered at once";
  const auto giveUp = Clock::now() + std::chrono::seconds(10);
  while (rtp.totalRollouts() < 3000 && Clock::now() < giveUp) {
    rtp.addExperience(step(2.0f, 1));  // new model views, each filtered
    rtp.act(State{2.0f}, Clock::now() + milliseconds(20));
  }
  ASSERT_GE(rtp.totalRollouts(), 3000);
  EXPECT_GT(filtered->load(), 1);
  EXPECT_EQ(rtp.act(State{2.0f}, Clock::now()), 0) << "planned on the chain, not the filter";
  // latestView() is the model's own view.
  EXPECT_NE(std::dynamic_pointer_cast<const ChainView>(rtp.latestView()), nullptr);
  rtp.setViewFilter(nullptr);
  const long before = filtered->load();
  rtp.addExperience(step(2.0f, 1));
  rtp.act(State{2.0f}, Clock::now() + milliseconds(50));
  EXPECT_EQ(filtered->load(), before) << "a removed filter is not called";
}
