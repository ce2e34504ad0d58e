/**
 * Experiment: a batch of trials of one agent on one environment, with the run folder that holds
 * their logs (the `experiment` program; the experiment node writes the same folder layout).
 *
 * Run folder (`--out`):
 *   run.csv          name,value: suite version, command line, every option's effective value,
 *                    the run seed (written atomically when the run starts)
 *   seeds.csv        trial,agent_seed,env_seed,eval_seed (atomically)
 *   steps-NNN.csv, episodes-NNN.csv, accuracy-NNN.csv, trial-NNN.csv   per trial (TrialLogger)
 *   trials.csv       every finished trial's summary row (atomically, after each trial)
 *
 * Seeds: trial k's agent, environment and evaluation streams are
 * Random::deriveSeed(seed, "agent" | "environment" | "evaluation", k), so they are distinct and
 * uncorrelated (the original gave the agent a copy of the environment's generator), and trial k
 * is the same whichever process or machine runs it (--first-trial splits a sweep).
 *
 * A folder that already holds results is never overwritten unless `force` (which deletes the
 * runner's files first) or `resume` (which keeps finished trials, those with trial-NNN.csv, and
 * reruns the others; the recorded configuration must match).
 */
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "rl_agent/agent/agent_options.h"
#include "rl_common/option_parser.h"
#include "rl_env/env/environment_options.h"
#include "rl_experiment/runner/system_info.h"
#include "rl_experiment/runner/trial_runner.h"

namespace rl_experiment {

struct ExperimentConfig {
  rl_agent::AgentOptions agent;
  rl_env::EnvironmentOptions env;  ///< env.seed is the run's seed
  int trials = 1;                  ///< --trials
  int firstTrial = 0;              ///< --first-trial: number of the first trial
  int nepisodes = 1000;            ///< --nepisodes (steps for non-episodic tasks, as the original)
  int steps = 0;                   ///< --steps: non-episodic steps (0: use nepisodes)
  int maxsteps = 1000;             ///< --maxsteps
  int exploreSteps = 0;            ///< --explore-steps
  int taskSteps = 0;               ///< --task-steps
  std::string taskRewards = "given";  ///< --task-rewards: given or learned
  int evalEvery = 25;                 ///< --eval-every (0: no accuracy evaluation)
  int evalSamples = 5000;             ///< --eval-samples
  std::vector<int> evalGroups;        ///< --eval-groups: features grouping the samples
  std::string out;                    ///< --out folder ("" : no files)
  bool force = false;                 ///< --force
  bool resume = false;                ///< --resume
  bool journal = false;               ///< --journal: journal-NNN.rlj per trial in --out
  int jobs = 1;                       ///< --jobs
  std::string format = "csv";         ///< --format csv|original
  std::string label;                  ///< --label (default: the agent's name)
  std::string progress = "auto";      ///< --progress auto|on|off
  double stepTimeout = 60.0;  ///< experiment_node --timeout: seconds without a step before a
                              ///< trial fails (the ROS mode only)

  /// Steps per trial of a non-episodic task: --steps, or --nepisodes when it is 0 (the original).
  int nonEpisodicSteps() const { return steps > 0 ? steps : nepisodes; }
};

/// Declares every runner option (agent, environment and the runner's own) on `parser`.
void addExperimentOptions(rl_common::OptionParser& parser, ExperimentConfig* config);

/// Validates and completes a parsed configuration (agent defaults, registry names, option
/// combinations). Throws rl_common::OptionError naming the option and what is valid.
void finishExperimentConfig(const rl_common::OptionParser& parser, ExperimentConfig* config);

/// Seeds of trial `trial` of a run seeded with `runSeed`.
struct TrialSeeds {
  std::uint64_t agent, env, eval;
};
TrialSeeds trialSeeds(std::uint64_t runSeed, int trial);

class Experiment {
 public:
  /// `values` are the effective option values (parser.currentValues()), recorded in run.csv.
  Experiment(ExperimentConfig config, std::vector<std::pair<std::string, std::string>> values,
             std::string commandLine);

  /// Checks and prepares the run folder (no-overwrite rule, --force, --resume) and writes
  /// run.csv and seeds.csv. Throws std::runtime_error when the folder holds results and neither
  /// force nor resume is set, or when resuming with a different configuration.
  void prepare();

  /// Trial numbers still to run (all, or the unfinished ones when resuming).
  std::vector<int> pendingTrials() const;

  /// Runs one trial in this process; returns its summary row. `original` receives the
  /// original's stream (may be null); `progress` is called with (steps done, steps planned).
  std::vector<std::pair<std::string, std::string>> runTrial(
      int trial, std::ostream* original,
      const std::function<void(long, long)>& progress = {}) const;

  /// Runs every pending trial (in `jobs` child processes if jobs > 1), printing one line per
  /// finished trial on `out` and the original stream on `err` with --format original. Returns
  /// the number of failed trials.
  int run(std::ostream& out, std::ostream& err);

  /// Rewrites trials.csv (atomically) from the finished trials' summaries in the folder.
  void collect() const;

  const ExperimentConfig& config() const { return config_; }

 private:
  std::string path(const std::string& file) const;
  std::string fingerprint() const;

  ExperimentConfig config_;
  std::vector<std::pair<std::string, std::string>> values_;
  std::string commandLine_;
};

}  // namespace rl_experiment
