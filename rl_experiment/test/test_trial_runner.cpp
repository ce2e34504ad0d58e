#include "rl_experiment/runner/trial_runner.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "rl_agent/agent/agent_registry.h"
#include "rl_agent/agent/model_based_agent.h"

namespace {

// Counts down from `start`; terminal at 0 if episodic. Reward 1 per step.
class Countdown : public rl_common::Environment {
 public:
  Countdown(int start, bool episodic) : start_(start), episodic_(episodic) { reset(); }
  const rl_common::State& sensation() const override { return s_; }
  float apply(int) override {
    s_[0] -= 1.0f;
    return 1.0f;
  }
  bool terminal() const override { return episodic_ && s_[0] <= 0.0f; }
  void reset() override {
    s_ = {float(start_)};
    ++resets;
  }
  int numActions() const override { return 1; }
  void getMinMaxFeatures(std::vector<float>* mn, std::vector<float>* mx) const override {
    *mn = {-1e6f};
    *mx = {1e6f};
  }
  void getMinMaxReward(float* mn, float* mx) const override { *mn = *mx = 1.0f; }
  bool isEpisodic() const override { return episodic_; }
  std::vector<rl_common::Experience> seedExperiences() const override {
    return {{{5.0f}, 0, 1.0f, {4.0f}, false}};
  }
  std::string name() const override { return "Countdown"; }
  bool isStochastic() const override { return false; }
  int resets = 0;

 private:
  int start_;
  bool episodic_;
  rl_common::State s_;
};

class Recorder : public rl_common::Agent {
 public:
  int firstAction(const rl_common::State&) override {
    calls += "F";
    return 0;
  }
  int nextAction(float, const rl_common::State&) override {
    calls += "N";
    return 0;
  }
  void lastAction(float) override { calls += "L"; }
  void seedExperiences(const std::vector<rl_common::Experience>& s) override { seeds += s.size(); }
  std::string calls;
  std::size_t seeds = 0;
};

class Collect : public rl_experiment::TrialObserver {
 public:
  void onStep(const rl_experiment::StepRecord& r) override { steps.push_back(r); }
  void onEpisode(const rl_experiment::EpisodeRecord& r) override { episodes.push_back(r); }
  std::vector<rl_experiment::StepRecord> steps;
  std::vector<rl_experiment::EpisodeRecord> episodes;
};

}  // namespace

TEST(TrialRunner, NonEpisodicRunsExactlyStepsAsOneEpisode) {
  Countdown env(3, false);
  Recorder agent;
  Collect log;
  rl_experiment::TrialLimits limits;
  limits.steps = 5;
  const auto s = rl_experiment::TrialRunner(limits).run(env, agent, &log);
  EXPECT_EQ(agent.calls, "FNNNN");
  EXPECT_EQ(agent.seeds, 1u);
  EXPECT_EQ(s.steps, 5);
  EXPECT_EQ(s.episodes, 1);
  EXPECT_DOUBLE_EQ(s.totalReward, 5.0);
  ASSERT_EQ(log.steps.size(), 5u);
  EXPECT_EQ(log.steps[4].step, 4);
  ASSERT_EQ(log.episodes.size(), 1u);
  EXPECT_FALSE(log.episodes[0].terminal);
}

TEST(TrialRunner, EpisodicEndsWithLastActionAndResets) {
  Countdown env(3, true);
  Recorder agent;
  Collect log;
  rl_experiment::TrialLimits limits;
  limits.episodes = 2;
  const auto s = rl_experiment::TrialRunner(limits).run(env, agent, &log);
  EXPECT_EQ(agent.calls, "FNNLFNNL");
  EXPECT_EQ(s.episodes, 2);
  EXPECT_EQ(env.resets, 3);  // construction + one per episode
  ASSERT_EQ(log.episodes.size(), 2u);
  EXPECT_TRUE(log.episodes[1].terminal);
  EXPECT_EQ(log.episodes[1].steps, 3);
  EXPECT_FLOAT_EQ(log.episodes[1].reward, 3.0f);
  EXPECT_TRUE(log.steps[2].terminal);
  EXPECT_EQ(log.steps[3].episode, 1);
}

TEST(TrialRunner, EpisodeCutOffAtMaxSteps) {
  Countdown env(100, true);
  Recorder agent;
  Collect log;
  rl_experiment::TrialLimits limits;
  limits.episodes = 1;
  limits.maxSteps = 4;
  rl_experiment::TrialRunner(limits).run(env, agent, &log);
  EXPECT_EQ(agent.calls, "FNNNN");  // the last nextAction's action is discarded
  ASSERT_EQ(log.episodes.size(), 1u);
  EXPECT_EQ(log.episodes[0].steps, 4);
  EXPECT_FALSE(log.episodes[0].terminal);
  EXPECT_THROW(rl_experiment::TrialRunner({1, 1, 0}), std::invalid_argument);
}

namespace {

// Non-episodic countdown that pays 1 on every step; records what the agent receives.
class RewardRecorder : public rl_common::Agent {
 public:
  int firstAction(const rl_common::State&) override { return 0; }
  int nextAction(float r, const rl_common::State&) override {
    received.push_back(r);
    return 0;
  }
  void lastAction(float r) override { received.push_back(r); }
  std::vector<float> received;
};

class PhaseLog : public rl_experiment::TrialObserver {
 public:
  void onPhase(rl_experiment::Phase p) override { phases.push_back(p); }
  void onStep(const rl_experiment::StepRecord& r) override { steps.push_back(r); }
  void onCheckpoint(long n, rl_experiment::Phase, const rl_common::Agent&,
                    const rl_common::Environment&) override {
    checkpoints.push_back(n);
  }
  std::vector<rl_experiment::Phase> phases;
  std::vector<rl_experiment::StepRecord> steps;
  std::vector<long> checkpoints;
};

}  // namespace

TEST(TrialRunner, ExplorePhaseHidesTheRewardTaskPhaseShowsIt) {
  Countdown env(100, false);
  RewardRecorder agent;
  PhaseLog log;
  rl_experiment::TrialLimits limits;
  limits.exploreSteps = 3;
  limits.taskSteps = 4;
  limits.checkpointEvery = 3;
  const auto s = rl_experiment::TrialRunner(limits).run(env, agent, &log);
  EXPECT_EQ(s.steps, 7);
  EXPECT_DOUBLE_EQ(s.exploreReward, 3.0);
  EXPECT_DOUBLE_EQ(s.taskReward, 4.0);
  EXPECT_DOUBLE_EQ(s.totalReward, 7.0);
  // nextAction after steps 0..5: the rewards of steps 0-2 are hidden, 3-5 shown.
  EXPECT_EQ(agent.received, (std::vector<float>{0, 0, 0, 1, 1, 1}));
  ASSERT_EQ(log.phases.size(), 2u);
  EXPECT_EQ(log.phases[0], rl_experiment::Phase::kExplore);
  EXPECT_EQ(log.phases[1], rl_experiment::Phase::kTask);
  ASSERT_EQ(log.steps.size(), 7u);
  EXPECT_EQ(log.steps[2].phase, rl_experiment::Phase::kExplore);
  EXPECT_FLOAT_EQ(log.steps[2].reward, 1.0f);
  EXPECT_FLOAT_EQ(log.steps[2].rewardSeen, 0.0f);
  EXPECT_EQ(log.steps[3].phase, rl_experiment::Phase::kTask);
  EXPECT_FLOAT_EQ(log.steps[3].rewardSeen, 1.0f);
  EXPECT_EQ(log.checkpoints, (std::vector<long>{0, 3, 6, 7}));
}

TEST(TrialRunner, EpisodicPhasesRestartEpisodesWithinTheBudget) {
  Countdown env(3, true);
  Recorder agent;
  Collect log;
  rl_experiment::TrialLimits limits;
  limits.exploreSteps = 4;
  limits.taskSteps = 3;
  const auto s = rl_experiment::TrialRunner(limits).run(env, agent, &log);
  EXPECT_EQ(s.steps, 7);
  EXPECT_EQ(agent.calls, "FNNLFNNLF");  // 3 + 3 + 1 steps; the last episode is unfinished
  EXPECT_EQ(s.episodes, 3);
  ASSERT_EQ(log.episodes.size(), 3u);
  EXPECT_FALSE(log.episodes[2].terminal);
  EXPECT_EQ(log.episodes[1].phase, rl_experiment::Phase::kExplore);  // starts at step 3
  EXPECT_EQ(log.episodes[2].phase, rl_experiment::Phase::kTask);     // starts at step 6
}

namespace {

// The reward a model-based agent's learned model predicts at the countdown state `s`.
float learnedReward(const rl_common::Agent& agent, float s) {
  const auto view = dynamic_cast<const rl_agent::ModelBasedAgent&>(agent).learnedModelView();
  return view->query({s}, 0).reward;
}

std::unique_ptr<rl_common::Agent> tabularAgent(const rl_common::Environment& env) {
  rl_agent::AgentOptions o;
  o.agent = "modelbased";
  o.model = "tabular";
  o.explore = "random";
  o.planner = "vi";
  return rl_agent::makeAgent(o, env.describe());
}

}  // namespace

TEST(TrialRunner, TaskPhaseGivesTheExplorationStepsTheirRewards) {
  for (bool given : {true, false}) {
    Countdown env(100, false);
    auto agent = tabularAgent(env);
    rl_experiment::TrialLimits limits;
    limits.exploreSteps = 5;  // states 100 .. 96, each step's reward 1 hidden
    limits.taskSteps = 3;
    limits.giveTaskRewards = given;
    rl_experiment::TrialRunner(limits).run(env, *agent, nullptr);
    const auto& mb = dynamic_cast<const rl_agent::ModelBasedAgent&>(*agent);
    EXPECT_EQ(mb.recordedSteps(), given ? 7u : 0u);  // the last task step is never learned
    // Steps 0-3 were learned while exploring; step 4's reward arrives with the first task call.
    for (float s : {100.0f, 98.0f, 96.0f}) {
      EXPECT_FLOAT_EQ(learnedReward(*agent, s), given ? 1.0f : 0.0f) << "state " << s;
    }
    EXPECT_FLOAT_EQ(learnedReward(*agent, 95.0f), 1.0f);  // a task step: seen either way
  }
}
