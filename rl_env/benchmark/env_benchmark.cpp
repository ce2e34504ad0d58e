// Environment throughput: steps per second of every registered environment under uniformly
// random actions (fixed seeds, reset on terminal states), with each environment's speed
// relative to taxi measured in the same run. Prints a table; never fails on time.
//
//   rl_env_benchmark [--seconds S]   (default 0.5 s of stepping per environment)
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "rl_common/random.h"
#include "rl_env/env/environment_registry.h"

namespace {

struct Result {
  std::string name;
  double stepsPerSecond = 0.0;
  long steps = 0;
  long episodes = 0;
};

Result measure(const std::string& name, double seconds) {
  rl_env::EnvironmentOptions options;
  options.env = name;
  options.seed = 1;
  std::unique_ptr<rl_common::Environment> env = rl_env::builtinEnvironments().make(options);
  rl_common::Random actions(2);
  const int numActions = env->numActions();
  Result r;
  r.name = name;
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  double elapsed = 0.0;
  constexpr long kBatch = 4096;
  while (elapsed < seconds) {
    for (long i = 0; i < kBatch; ++i) {
      env->apply(actions.uniformInt(0, numActions - 1));
      if (env->terminal()) {
        env->reset();
        ++r.episodes;
      }
    }
    r.steps += kBatch;
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  }
  r.stepsPerSecond = static_cast<double>(r.steps) / elapsed;
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  double seconds = 0.5;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if ((arg == "--seconds" || arg == "-seconds") && i + 1 < argc) {
      seconds = std::atof(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: %s [--seconds S]\n", argv[0]);
      return 2;
    }
  }
  if (!(seconds > 0.0)) {
    std::fprintf(stderr, "rl_env_benchmark: --seconds must be > 0\n");
    return 2;
  }
  try {
    std::vector<Result> results;
    for (const std::string& name : rl_env::builtinEnvironments().registry().names()) {
      results.push_back(measure(name, seconds));
    }
    double taxi = 0.0;
    for (const Result& r : results) {
      if (r.name == "taxi") taxi = r.stepsPerSecond;
    }
    std::printf("Environment steps per second (random actions, seed 1, %.2f s each)\n", seconds);
    std::printf("%-12s %14s %10s %12s %10s\n", "environment", "steps/s", "vs taxi", "steps",
                "episodes");
    for (const Result& r : results) {
      std::printf("%-12s %14.0f %9.2fx %12ld %10ld\n", r.name.c_str(), r.stepsPerSecond,
                  taxi > 0.0 ? r.stepsPerSecond / taxi : 0.0, r.steps, r.episodes);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rl_env_benchmark: %s\n", e.what());
    return 1;
  }
  return 0;
}
