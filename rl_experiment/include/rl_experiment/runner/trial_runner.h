/**
 * TrialRunner: runs one agent on one environment for one trial, in one process, following the
 * original experiment driver's loops (rl_experiment/src/rl.cc, §9 of shared/spec/ORIGINAL.md).
 *
 * Non-episodic tasks are one long episode of `steps` actions (firstAction, then nextAction
 * after every step). Episodic tasks run `episodes` episodes, each capped at `maxSteps`
 * actions: a terminal step ends with lastAction; at the cap the agent still receives
 * nextAction (its action is discarded), then the environment is reset. Every step and every
 * episode is reported to an observer as it happens, so logs can be written line by line.
 */
#pragma once

#include "rl_common/agent.h"
#include "rl_common/environment.h"

namespace rl_experiment {

/// How long a trial runs.
struct TrialLimits {
  int steps = 1000;     ///< non-episodic tasks: number of actions
  int episodes = 1000;  ///< episodic tasks: number of episodes
  int maxSteps = 1000;  ///< episodic tasks: actions per episode before it is cut off
};

struct StepRecord {
  long step = 0;    ///< 0-based step of the trial
  int episode = 0;  ///< 0-based episode
  int action = 0;
  float reward = 0.0f;
  bool terminal = false;
};

struct EpisodeRecord {
  int episode = 0;
  float reward = 0.0f;    ///< sum of the episode's rewards
  int steps = 0;          ///< actions taken
  bool terminal = false;  ///< ended in a terminal state (false: cut off or non-episodic)
};

struct TrialSummary {
  long steps = 0;
  int episodes = 0;
  double totalReward = 0.0;
};

/// Receives the trial's records as they happen. Default: ignore.
class TrialObserver {
 public:
  virtual ~TrialObserver() = default;
  virtual void onStep(const StepRecord& /*record*/) {}
  virtual void onEpisode(const EpisodeRecord& /*record*/) {}
};

class TrialRunner {
 public:
  explicit TrialRunner(TrialLimits limits);

  /// Seeds the agent with the environment's seed experiences, then runs the trial.
  TrialSummary run(rl_common::Environment& env, rl_common::Agent& agent,
                   TrialObserver* observer = nullptr) const;

 private:
  TrialLimits limits_;
};

}  // namespace rl_experiment
