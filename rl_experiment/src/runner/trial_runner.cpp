#include "rl_experiment/runner/trial_runner.h"

#include <stdexcept>

namespace rl_experiment {

TrialRunner::TrialRunner(TrialLimits limits) : limits_(limits) {
  if (limits.steps < 0 || limits.episodes < 0 || limits.maxSteps < 1) {
    throw std::invalid_argument(
        "TrialRunner::TrialRunner(): steps and episodes must be >= 0, maxSteps >= 1");
  }
}

TrialSummary TrialRunner::run(rl_common::Environment& env, rl_common::Agent& agent,
                              TrialObserver* observer) const {
  TrialObserver ignore;
  TrialObserver& obs = observer != nullptr ? *observer : ignore;
  TrialSummary summary;
  agent.seedExperiences(env.seedExperiences());

  auto step = [&](int action, int episode, EpisodeRecord& ep) {
    const float r = env.apply(action);
    const bool terminal = env.terminal();
    obs.onStep({summary.steps, episode, action, r, terminal});
    ++summary.steps;
    summary.totalReward += r;
    ep.reward += r;
    ++ep.steps;
    return r;
  };

  if (!env.isEpisodic()) {
    EpisodeRecord ep;
    if (limits_.steps > 0) {
      float r = step(agent.firstAction(env.sensation()), 0, ep);
      for (int i = 1; i < limits_.steps; ++i) {
        r = step(agent.nextAction(r, env.sensation()), 0, ep);
      }
      obs.onEpisode(ep);
      summary.episodes = 1;
    }
    return summary;
  }

  for (int e = 0; e < limits_.episodes; ++e) {
    EpisodeRecord ep;
    ep.episode = e;
    float r = step(agent.firstAction(env.sensation()), e, ep);
    while (!env.terminal() && ep.steps < limits_.maxSteps) {
      r = step(agent.nextAction(r, env.sensation()), e, ep);
    }
    if (env.terminal()) {
      agent.lastAction(r);
      ep.terminal = true;
    } else {
      agent.nextAction(r, env.sensation());  // the original's cut-off: action discarded
    }
    obs.onEpisode(ep);
    ++summary.episodes;
    env.reset();
  }
  return summary;
}

}  // namespace rl_experiment
