// TEXPLORE-VANIR on LightWorld (--agent texplore --v 1 --n 3): what one step costs.
//
//   agent_benchmark fixed [--steps 5000] [--rollouts 100] [--seed 1]
//       synchronous mode: per-step model-update time, planning rollouts per second and peak
//       memory, reported at 1000 steps and at the end
//   agent_benchmark realtime [--steps 500] [--actrate 10] [--searchthreads 0] [--seed 1]
//       the real-time (RTMBA) agent: rollouts completed per action (median, p10, p90) and the
//       interval between actions (median, p99, max); with more than one search thread (0: one
//       per core) it runs the single-thread agent first, in the same run, and prints the ratio
//
// Prints figures only; never a pass/fail verdict.
#include <malloc.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "rl_agent/agent/agent_options.h"
#include "rl_agent/agent/model_based_agent.h"
#include "rl_common/option_parser.h"
#include "rl_env/env/environment_registry.h"
#include "rl_experiment/runner/experiment.h"
#include "rl_experiment/suite/suite_environments.h"

namespace {

using Clock = std::chrono::steady_clock;

double peakRssMb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t i = std::min(v.size() - 1, static_cast<std::size_t>(q * (v.size() - 1) + 0.5));
  return v[i];
}

struct Setup {
  std::unique_ptr<rl_common::Environment> env;
  std::unique_ptr<rl_agent::ModelBasedAgent> agent;
};

Setup makeSetup(std::uint64_t seed, long rollouts, float actrate, int searchThreads = 0) {
  rl_env::EnvironmentOptions eo;
  eo.env = "lightworld";
  eo.seed = seed;
  Setup s;
  s.env = rl_experiment::suiteEnvironments().make(eo);
  rl_agent::AgentOptions ao;
  rl_common::OptionParser p("agent_benchmark", "");
  rl_agent::addAgentOptions(p, &ao);
  p.parse({"--agent", "texplore", "--v", "1", "--n", "3"});
  rl_agent::applyAgentDefaults(p, &ao);
  ao.seed = seed + 1;
  ao.rollouts = rollouts;
  ao.actrate = actrate;
  ao.searchthreads = searchThreads;
  s.agent = std::make_unique<rl_agent::ModelBasedAgent>(ao, s.env->describe());
  s.agent->seedExperiences(s.env->seedExperiences());
  return s;
}

void fixedMode(int steps, long rollouts, std::uint64_t seed) {
  Setup s = makeSetup(seed, rollouts, 10.0f);
  std::printf("fixed mode: LightWorld, texplore v=1 n=3, %ld rollouts per step\n", rollouts);
  std::printf("%8s %14s %14s %16s %12s %10s\n", "steps", "update ms/step", "plan ms/step",
              "rollouts/s", "peak MB", "reward");
  double learn = 0, plan = 0, reward = 0;
  long done = 0;
  float r = s.env->apply(s.agent->firstAction(s.env->sensation()));
  reward += r;
  for (int i = 1; i <= steps; ++i) {
    r = s.env->apply(s.agent->nextAction(r, s.env->sensation()));
    reward += r;
    learn += s.agent->lastLearnSeconds();
    plan += s.agent->lastPlanSeconds();
    done += s.agent->lastRollouts();
    if (i == 1000 || i == steps || i % 1000 == 0) {
      std::printf("%8d %14.3f %14.3f %16.0f %12.1f %10.0f\n", i, 1000 * learn / i, 1000 * plan / i,
                  done / plan, peakRssMb(), reward);
      std::fflush(stdout);
    }
  }
}

struct RealTimeFigures {
  double medianRollouts = 0.0;
};

RealTimeFigures realTimeRun(int steps, float actrate, std::uint64_t seed, int threads) {
  // Each run's own peak: return what an earlier run freed, then restart the high-water mark.
  malloc_trim(0);
  rl_experiment::resetPeakRss();
  Setup s = makeSetup(seed, 0, actrate, threads);
  std::vector<double> rollouts, intervals;
  float r = s.env->apply(s.agent->firstAction(s.env->sensation()));
  auto last = Clock::now();
  for (int i = 1; i <= steps; ++i) {
    r = s.env->apply(s.agent->nextAction(r, s.env->sensation()));
    const auto now = Clock::now();
    intervals.push_back(std::chrono::duration<double, std::milli>(now - last).count());
    last = now;
    rollouts.push_back(static_cast<double>(s.agent->lastRollouts()));
  }
  std::printf("real-time mode: LightWorld, texplore v=1 n=3, %g Hz, %d steps, %d search thread%s\n",
              actrate, steps, threads, threads == 1 ? "" : "s");
  std::printf("rollouts per action: median %.0f  p10 %.0f  p90 %.0f\n", quantile(rollouts, 0.5),
              quantile(rollouts, 0.1), quantile(rollouts, 0.9));
  std::printf("step interval ms:    median %.1f  p99 %.1f  max %.1f\n", quantile(intervals, 0.5),
              quantile(intervals, 0.99), quantile(intervals, 1.0));
  std::printf("peak memory MB:      %.1f\n", rl_experiment::peakRssKb() / 1024.0);
  std::fflush(stdout);
  return {quantile(rollouts, 0.5)};
}

void realTimeMode(int steps, float actrate, std::uint64_t seed, int searchThreads) {
  rl_agent::AgentOptions resolved;
  resolved.searchthreads = searchThreads;
  const int threads = rl_agent::searchThreads(resolved);
  if (threads == 1) {
    realTimeRun(steps, actrate, seed, 1);
    return;
  }
  const RealTimeFigures one = realTimeRun(steps, actrate, seed, 1);
  const RealTimeFigures many = realTimeRun(steps, actrate, seed, threads);
  std::printf("rollouts per action, %d threads against 1 (median): %.2fx\n", threads,
              one.medianRollouts > 0 ? many.medianRollouts / one.medianRollouts : 0.0);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || (std::string(argv[1]) != "fixed" && std::string(argv[1]) != "realtime")) {
    std::cerr << "usage: agent_benchmark {fixed|realtime} [--steps N] [--rollouts N] "
                 "[--actrate HZ] [--searchthreads K] [--seed N]\n";
    return 2;
  }
  const bool fixed = std::string(argv[1]) == "fixed";
  int steps = fixed ? 5000 : 500;
  long rollouts = 100;
  float actrate = 10.0f;
  unsigned long seed = 1;
  int searchThreads = 0;
  rl_common::OptionParser p("agent_benchmark", "{fixed|realtime} [options]");
  p.value("steps", &steps, "steps to run", rl_common::greaterThan(0));
  p.value("rollouts", &rollouts, "rollouts per step (fixed mode)", rl_common::greaterThan(0L));
  p.value("actrate", &actrate, "actions per second (real-time mode)", rl_common::greaterThan(0.0f));
  p.value("searchthreads", &searchThreads,
          "real-time mode: search threads (0: one per core); more than 1 also runs 1 first",
          rl_common::inRange(0, rl_agent::kMaxSearchThreads));
  p.value("seed", &seed, "seed");
  try {
    if (!p.parse(argc - 1, argv + 1)) {
      std::cout << p.help();
      return 0;
    }
    if (fixed) {
      fixedMode(steps, rollouts, seed);
    } else {
      realTimeMode(steps, actrate, seed, searchThreads);
    }
  } catch (const std::exception& e) {
    std::cerr << "agent_benchmark: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
