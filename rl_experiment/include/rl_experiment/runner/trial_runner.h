/**
 * TrialRunner: runs one agent on one environment for one trial, in one process, following the
 * original experiment driver's loops (rl_experiment/src/rl.cc, §9 of shared/spec/ORIGINAL.md),
 * plus the TEXPLORE-VANIR paper's two-phase protocol (§5.1).
 *
 * Without phases (TrialLimits::exploreSteps == taskSteps == 0), non-episodic tasks are one long
 * episode of `steps` actions (firstAction, then nextAction after every step). Episodic tasks
 * run `episodes` episodes, each capped at `maxSteps` actions: a terminal step ends with
 * lastAction; at the cap the agent still receives nextAction (its action is discarded), then the
 * environment is reset.
 *
 * With phases, the trial is `exploreSteps` steps of the exploration phase (the external reward
 * is hidden: the agent receives 0; intrinsic rewards on), then `taskSteps` steps of the task
 * phase (the agent receives the external reward; intrinsic rewards switched off, so it acts
 * greedily on its learned model). The steps form one stream: the agent is not restarted between
 * the phases. Episodic tasks restart episodes as above until the phase budget is spent.
 * With `giveTaskRewards` (the default) a model-based agent is, at the switch, "provided with a
 * reward function for a task" (the paper, §5.1): it is given the task's reward of every
 * exploration step it learned from, and rebuilds its model as if it had seen them all along
 * (rl_agent::ModelBasedAgent::relabelRewards). Without it, or for model-free agents, the task's
 * rewards are learned from the task steps only (what the original's code allows: a reward-free
 * environment, then the task's).
 *
 * Every step and episode is reported to an observer as it happens (so logs can be written line
 * by line), and every `checkpointEvery` steps the observer may inspect the agent (model
 * accuracy).
 */
#pragma once

#include <string>

#include "rl_common/agent.h"
#include "rl_common/environment.h"

namespace rl_experiment {

/// How long a trial runs.
struct TrialLimits {
  int steps = 1000;         ///< non-episodic tasks without phases: number of actions
  int episodes = 1000;      ///< episodic tasks without phases: number of episodes
  int maxSteps = 1000;      ///< episodic tasks: actions per episode before it is cut off
  int exploreSteps = 0;     ///< phases: steps with the external reward hidden
  int taskSteps = 0;        ///< phases: steps with external reward, intrinsic rewards off
  int checkpointEvery = 0;  ///< call TrialObserver::onCheckpoint every this many steps (0: never)
  bool giveTaskRewards = true;  ///< phases: relabel the exploration steps' rewards at the switch

  bool phased() const { return exploreSteps > 0 || taskSteps > 0; }
};

/// The phase of a step.
enum class Phase { kRun = 0, kExplore = 1, kTask = 2 };
/// "run", "explore" or "task".
const char* phaseName(Phase phase);

struct StepRecord {
  long step = 0;    ///< 0-based step of the trial
  int episode = 0;  ///< 0-based episode
  Phase phase = Phase::kRun;
  int action = 0;
  float reward = 0.0f;      ///< the environment's (external) reward
  float rewardSeen = 0.0f;  ///< what the agent was given (0 in the exploration phase)
  bool terminal = false;
  bool hasBreakdown = false;  ///< the agent reports intrinsic rewards (below)
  float variance = 0.0f;      ///< intrinsic parts the agent predicted for this action
  float novelty = 0.0f;
  float other = 0.0f;
  double plannedValue = 0.0;  ///< the planner's Q of the chosen action (NaN: none)
  double valueSpread = 0.0;   ///< max − min of the planner's Q at the state (NaN: none)
};

struct EpisodeRecord {
  int episode = 0;
  Phase phase = Phase::kRun;  ///< phase of the episode's first step
  float reward = 0.0f;        ///< sum of the episode's external rewards
  int steps = 0;              ///< actions taken
  bool terminal = false;      ///< ended in a terminal state (false: cut off or non-episodic)
};

struct TrialSummary {
  long steps = 0;
  int episodes = 0;
  double totalReward = 0.0;    ///< external reward over the whole trial
  double exploreReward = 0.0;  ///< external reward of the exploration phase
  double taskReward = 0.0;     ///< external reward of the task phase
};

/// Receives the trial's records as they happen. Default: ignore.
class TrialObserver {
 public:
  virtual ~TrialObserver() = default;
  /// Before `action` is applied at `step` (the environment still shows the state it acts in).
  virtual void beforeStep(const rl_common::Environment& /*env*/, long /*step*/, int /*action*/) {}
  virtual void onStep(const StepRecord& /*record*/) {}
  virtual void onEpisode(const EpisodeRecord& /*record*/) {}
  /// After `stepsDone` steps (0, checkpointEvery, 2*checkpointEvery, ... and the last step).
  virtual void onCheckpoint(long /*stepsDone*/, Phase /*phase*/, const rl_common::Agent& /*agent*/,
                            const rl_common::Environment& /*env*/) {}
  /// The trial enters `phase` (called before its first step).
  virtual void onPhase(Phase /*phase*/) {}
};

class TrialRunner {
 public:
  /// Throws std::invalid_argument for negative budgets or maxSteps < 1.
  explicit TrialRunner(TrialLimits limits);

  /// Seeds the agent with the environment's seed experiences, then runs the trial. In the task
  /// phase the agent's intrinsic rewards are switched off (agents without them are unaffected).
  TrialSummary run(rl_common::Environment& env, rl_common::Agent& agent,
                   TrialObserver* observer = nullptr) const;

  const TrialLimits& limits() const { return limits_; }
  /// Total number of steps the trial will take (episodic without phases: an upper bound).
  long plannedSteps(bool episodic) const;

 private:
  TrialSummary runPhased(rl_common::Environment& env, rl_common::Agent& agent,
                         TrialObserver& obs) const;

  TrialLimits limits_;
};

}  // namespace rl_experiment
