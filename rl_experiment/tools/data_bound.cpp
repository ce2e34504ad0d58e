// How accurate TEXPLORE's forest model gets on LightWorld from scripted data (the paper's Fig. 4
// measure at a fixed step): a walk of random actions, the measure's own i.i.d. distribution,
// restarted walks, and a walk that leaves the key on the floor
// (docs/science/lightworld-curiosity.md §2.1).
//
//   rl_experiment_data_bound [--stream walk|iid|teleport|keep-key] [--period 100]
//       [--steps 1000] [--trials 20] [--seed 1] [--eval-samples 5000]
//
// Trial k uses the runner's trial seeds (trialSeeds(seed, k)): the stream draws from the
// environment seed, the model from the agent seed (`--agent texplore --explore random`'s
// model: 5 trees, average), the measure from the evaluation seed. Prints per-trial figures
// and the mean with its 95% interval; never a pass/fail verdict.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "rl_common/option_parser.h"
#include "rl_experiment/eval/scripted_stream.h"
#include "rl_experiment/runner/experiment.h"

namespace {

// Two-sided 97.5% quantiles of Student's t for df 1..30 (then the normal's).
double tQuantile975(int df) {
  static const double q[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                             2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
                             2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
  return df >= 1 && df <= 30 ? q[df - 1] : 1.960;
}

}  // namespace

int main(int argc, char** argv) {
  rl_experiment::ScriptedStreamConfig stream;
  int trials = 20;
  int samples = 5000;
  unsigned long seed = 1;
  rl_common::OptionParser p("rl_experiment_data_bound", "[options]");
  p.choice("stream", &stream.stream, rl_experiment::scriptedStreamNames(),
           "where the random actions are taken");
  p.value("period", &stream.period,
          "teleport: steps between restarts; keep-key: steps without "
          "picking up the key",
          rl_common::greaterThan(0L));
  p.value("steps", &stream.steps, "experiences learned before the measure",
          rl_common::greaterThan(0L));
  p.value("trials", &trials, "trials", rl_common::greaterThan(0));
  p.value("seed", &seed, "run seed (trial seeds derive from it as in the runner)");
  p.value("eval-samples", &samples, "state-actions drawn by the measure",
          rl_common::greaterThan(0));
  try {
    if (!p.parse(argc, argv)) {
      std::cout << p.help();
      return 0;
    }
    std::printf("stream %s, period %ld, %ld steps, %d trials, seed %lu, %d samples\n",
                stream.stream.c_str(), stream.period, stream.steps, trials, seed, samples);
    std::printf("%6s %10s %14s\n", "trial", "distance", "key on floor");
    double sum = 0.0, sumSq = 0.0;
    for (int t = 0; t < trials; ++t) {
      const rl_experiment::TrialSeeds s = rl_experiment::trialSeeds(seed, t);
      const rl_experiment::ScriptedStreamResult r =
          rl_experiment::measureScriptedStream(stream, s.env, s.agent, s.eval, samples);
      const double d = r.distance;
      sum += d;
      sumSq += d * d;
      std::printf("%6d %10.3f %14ld\n", t, d, r.keyOnFloor);
      std::fflush(stdout);
    }
    const double mean = sum / trials;
    const double sd = trials > 1 ? std::sqrt((sumSq - trials * mean * mean) / (trials - 1)) : 0.0;
    const double half = trials > 1 ? tQuantile975(trials - 1) * sd / std::sqrt(trials) : 0.0;
    std::printf("mean distance %.3f (sd %.3f, 95%% CI %.3f-%.3f)\n", mean, sd, mean - half,
                mean + half);
  } catch (const std::exception& e) {
    std::cerr << "rl_experiment_data_bound: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
