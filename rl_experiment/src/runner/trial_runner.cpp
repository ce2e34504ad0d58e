#include "rl_experiment/runner/trial_runner.h"

#include <stdexcept>

#include "rl_common/episode_driver.h"
#include "rl_experiment/runner/agent_probe.h"

namespace rl_experiment {

const char* phaseName(Phase phase) {
  switch (phase) {
    case Phase::kExplore:
      return "explore";
    case Phase::kTask:
      return "task";
    case Phase::kRun:
      break;
  }
  return "run";
}

TrialRunner::TrialRunner(TrialLimits limits) : limits_(limits) {
  if (limits.steps < 0 || limits.episodes < 0 || limits.maxSteps < 1 || limits.exploreSteps < 0 ||
      limits.taskSteps < 0 || limits.checkpointEvery < 0) {
    throw std::invalid_argument(
        "TrialRunner::TrialRunner(): steps, episodes, exploreSteps, taskSteps and "
        "checkpointEvery must be >= 0, maxSteps >= 1");
  }
}

long TrialRunner::plannedSteps(bool episodic) const {
  if (limits_.phased()) return long(limits_.exploreSteps) + limits_.taskSteps;
  if (!episodic) return limits_.steps;
  return long(limits_.episodes) * limits_.maxSteps;
}

namespace {

// Fills the record's intrinsic parts from the agent, if it reports them.
void addBreakdown(const rl_common::Agent& agent, StepRecord* rec) {
  if (const auto b = rewardBreakdownOf(agent)) {
    rec->hasBreakdown = true;
    rec->variance = b->variance;
    rec->novelty = b->novelty;
    rec->other = b->other;
    rec->plannedValue = b->plannedValue;
    rec->valueSpread = b->valueSpread;
  }
}

}  // namespace

TrialSummary TrialRunner::run(rl_common::Environment& env, rl_common::Agent& agent,
                              TrialObserver* observer) const {
  TrialObserver ignore;
  TrialObserver& obs = observer != nullptr ? *observer : ignore;
  if (limits_.phased() && limits_.giveTaskRewards) recordExperiences(agent);
  agent.seedExperiences(env.seedExperiences());
  if (limits_.phased()) return runPhased(env, agent, obs);

  TrialSummary summary;
  const long every = limits_.checkpointEvery;
  obs.onPhase(Phase::kRun);
  if (every > 0) obs.onCheckpoint(0, Phase::kRun, agent, env);
  auto step = [&](int action, int episode, EpisodeRecord& ep) {
    StepRecord rec;
    rec.step = summary.steps;
    rec.episode = episode;
    rec.action = action;
    addBreakdown(agent, &rec);
    obs.beforeStep(env, rec.step, action);
    rec.reward = env.apply(action);
    rec.rewardSeen = rec.reward;
    rec.terminal = env.terminal();
    obs.onStep(rec);
    ++summary.steps;
    summary.totalReward += rec.reward;
    ep.reward += rec.reward;
    ++ep.steps;
    if (every > 0 && summary.steps % every == 0) {
      obs.onCheckpoint(summary.steps, Phase::kRun, agent, env);
    }
    return rec.reward;
  };

  rl_common::EpisodeDriver driver(agent);
  if (!env.isEpisodic()) {
    EpisodeRecord ep;
    if (limits_.steps > 0) {
      float r = 0.0f;
      for (int i = 0; i < limits_.steps; ++i) r = step(driver.act(env.sensation(), r), 0, ep);
      obs.onEpisode(ep);
      summary.episodes = 1;
    }
  } else {
    for (int e = 0; e < limits_.episodes; ++e) {
      EpisodeRecord ep;
      ep.episode = e;
      float r = step(driver.act(env.sensation(), 0.0f), e, ep);
      while (!env.terminal() && ep.steps < limits_.maxSteps) {
        r = step(driver.act(env.sensation(), r), e, ep);
      }
      ep.terminal = driver.end(r, env.terminal(), env.sensation()).terminal;
      obs.onEpisode(ep);
      ++summary.episodes;
      env.reset();
    }
  }
  if (every > 0 && summary.steps % every != 0) {
    obs.onCheckpoint(summary.steps, Phase::kRun, agent, env);
  }
  summary.exploreReward = 0.0;
  summary.taskReward = 0.0;
  return summary;
}

TrialSummary TrialRunner::runPhased(rl_common::Environment& env, rl_common::Agent& agent,
                                    TrialObserver& obs) const {
  TrialSummary summary;
  const long total = long(limits_.exploreSteps) + limits_.taskSteps;
  const long every = limits_.checkpointEvery;
  auto phaseAt = [&](long i) { return i < limits_.exploreSteps ? Phase::kExplore : Phase::kTask; };

  EpisodeRecord ep;
  rl_common::EpisodeDriver driver(agent);
  float seen = 0.0f;                  // the reward the agent receives with its next call
  std::vector<float> exploreRewards;  // the task's reward of every exploration step
  Phase current = phaseAt(0);
  setIntrinsicEnabled(agent, current == Phase::kExplore);
  obs.onPhase(current);
  if (every > 0) obs.onCheckpoint(0, current, agent, env);

  for (long i = 0; i < total; ++i) {
    const Phase phase = phaseAt(i);
    if (phase != current) {
      current = phase;
      if (limits_.giveTaskRewards) {
        const long given = giveTaskRewards(agent, exploreRewards);
        // The last exploration step, not learned yet, comes with its true reward as well.
        if (given >= 0 && !driver.starting()) seen = exploreRewards.back();
      }
      setIntrinsicEnabled(agent, false);
      obs.onPhase(current);
    }
    StepRecord rec;
    rec.step = i;
    rec.episode = summary.episodes;
    rec.phase = phase;
    if (driver.starting()) {
      ep = EpisodeRecord();
      ep.episode = summary.episodes;
      ep.phase = phase;
    }
    rec.action = driver.act(env.sensation(), seen);
    addBreakdown(agent, &rec);
    obs.beforeStep(env, i, rec.action);
    rec.reward = env.apply(rec.action);
    rec.rewardSeen = phase == Phase::kExplore ? 0.0f : rec.reward;
    if (phase == Phase::kExplore) exploreRewards.push_back(rec.reward);
    rec.terminal = env.terminal();
    seen = rec.rewardSeen;
    obs.onStep(rec);
    ++summary.steps;
    summary.totalReward += rec.reward;
    (phase == Phase::kExplore ? summary.exploreReward : summary.taskReward) += rec.reward;
    ep.reward += rec.reward;
    ++ep.steps;
    if (env.isEpisodic() && (rec.terminal || ep.steps >= limits_.maxSteps)) {
      ep.terminal = driver.end(seen, rec.terminal, env.sensation()).terminal;
      obs.onEpisode(ep);
      ++summary.episodes;
      env.reset();
    }
    if (every > 0 && summary.steps % every == 0) {
      obs.onCheckpoint(summary.steps, phase, agent, env);
    }
  }
  if (!driver.starting() && total > 0) {  // the unfinished (or non-episodic) episode
    obs.onEpisode(ep);
    ++summary.episodes;
  }
  if (every > 0 && total % every != 0) obs.onCheckpoint(total, current, agent, env);
  return summary;
}

}  // namespace rl_experiment
