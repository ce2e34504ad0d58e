#pragma once
/**
 * @file slurm_submit.h
 * The runner's Slurm backend (`experiment --slurm`): instead of running its trials, the runner
 * hands them to scripts/slurm_sweep.py, which submits one Slurm job array (one task per block
 * of --trials-per-task trials, each the ordinary runner with --first-trial/--trials into its
 * own part folder) and a job that waits for it (--dependency=afterok) and merges the parts into
 * --out. The per-trial files are then those of the same run made locally.
 */
#include <string>
#include <vector>

#include "rl_common/option_parser.h"
#include "rl_experiment/runner/experiment.h"

namespace rl_experiment {

struct SlurmConfig {
  bool slurm = false;     ///< --slurm: submit to Slurm instead of running here
  std::string partition;  ///< --partition ("" : the cluster's default)
  std::string time;       ///< --time: each task's time limit, Slurm's format ("" : default)
  int cpusPerTask = 1;    ///< --cpus-per-task: also each task's --jobs
  int trialsPerTask = 0;  ///< --trials-per-task (0: --cpus-per-task)
  bool dryRun = false;    ///< --slurm-dry-run: write the scripts, print sbatch, submit nothing
};

void addSlurmOptions(rl_common::OptionParser& parser, SlurmConfig* config);

/// The rules of --slurm: it needs --out; --partition, --time, --cpus-per-task and
/// --trials-per-task need it; --jobs and --resume do not combine with it (a task runs
/// --cpus-per-task trials at once, and rerunning a submission resumes it).
void checkSlurmOptions(const rl_common::OptionParser& parser, const SlurmConfig& slurm,
                       const ExperimentConfig& config);

/// The submitter's command line: `python script submit ... -- <runner options>`, where the
/// runner options are every option given on the command line except the Slurm ones and
/// those the sweep sets per task (--out, --trials, --first-trial, --jobs, --progress, ...).
std::vector<std::string> slurmSubmitCommand(const rl_common::OptionParser& parser,
                                            const SlurmConfig& slurm,
                                            const ExperimentConfig& config,
                                            const std::string& runner, const std::string& python,
                                            const std::string& script,
                                            const std::string& commandLine);

/// slurm_sweep.py: $RL_SLURM_SWEEP, else the package's scripts folder, else beside `runner`
/// (the install space).
std::string slurmSweepScript(const std::string& runner);

}  // namespace rl_experiment
