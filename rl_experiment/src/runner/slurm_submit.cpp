// The runner's --slurm: the options, their rules and the hand-over to slurm_sweep.py.
#include "rl_experiment/runner/slurm_submit.h"

#include <cstdlib>
#include <filesystem>
#include <set>

namespace rl_experiment {

namespace {

const std::set<std::string>& slurmOptionNames() {
  static const std::set<std::string> names{"slurm",         "partition",       "time",
                                           "cpus-per-task", "trials-per-task", "slurm-dry-run"};
  return names;
}

// Set per task by the sweep, or meaningless for it.
const std::set<std::string>& perTaskOptionNames() {
  static const std::set<std::string> names{"out",      "trials", "first-trial",
                                           "jobs",     "resume", "force",
                                           "progress", "check",  "list-agents"};
  return names;
}

}  // namespace

void addSlurmOptions(rl_common::OptionParser& p, SlurmConfig* c) {
  using rl_common::greaterThan;
  p.flag("slurm", &c->slurm, true,
         "submit the trials to Slurm as one job array (blocks of --trials-per-task trials, "
         "each into its own folder) and a job that merges them into --out after it; rerunning "
         "resumes (needs sbatch)");
  p.value("partition", &c->partition, "with --slurm: the partition (default: the cluster's)");
  p.value("time", &c->time, "with --slurm: each array task's time limit (e.g. 2:00:00)");
  p.value("cpus-per-task", &c->cpusPerTask,
          "with --slurm: CPUs of each array task, which runs that many trials at once",
          greaterThan(0));
  p.value("trials-per-task", &c->trialsPerTask,
          "with --slurm: trials per array task (default: --cpus-per-task)", greaterThan(0));
  p.flag("slurm-dry-run", &c->dryRun, true,
         "with --slurm: write the sweep's scripts and print the sbatch commands, submit nothing");
}

void checkSlurmOptions(const rl_common::OptionParser& p, const SlurmConfig& s,
                       const ExperimentConfig& c) {
  if (!s.slurm) {
    for (const std::string& name : slurmOptionNames()) {
      if (name != "slurm" && p.given(name)) {
        throw rl_common::OptionError("option --" + name + " needs --slurm");
      }
    }
    return;
  }
  if (c.out.empty()) {
    throw rl_common::OptionError("option --slurm needs --out (the folder the merge job fills)");
  }
  if (p.given("jobs")) {
    throw rl_common::OptionError(
        "option --jobs does not combine with --slurm: each array task runs --cpus-per-task "
        "trials at once");
  }
  if (c.resume || c.force) {
    throw rl_common::OptionError(
        "options --resume and --force do not combine with --slurm: rerunning the submission "
        "resumes it (finished blocks are skipped); for a fresh run choose another --out");
  }
  if (c.format != "csv") {
    throw rl_common::OptionError("option --format original does not combine with --slurm");
  }
}

std::vector<std::string> slurmSubmitCommand(const rl_common::OptionParser& p, const SlurmConfig& s,
                                            const ExperimentConfig& c, const std::string& runner,
                                            const std::string& python, const std::string& script,
                                            const std::string& commandLine) {
  std::vector<std::string> cmd{
      python,
      script,
      "submit",
      "--exe",
      runner,
      "--out",
      c.out,
      "--first-trial",
      std::to_string(c.firstTrial),
      "--trials",
      std::to_string(c.trials),
      "--cpus-per-task",
      std::to_string(s.cpusPerTask),
      "--trials-per-task",
      std::to_string(s.trialsPerTask > 0 ? s.trialsPerTask : s.cpusPerTask),
      "--command-line",
      commandLine};
  if (!s.partition.empty()) cmd.insert(cmd.end(), {"--partition", s.partition});
  if (!s.time.empty()) cmd.insert(cmd.end(), {"--time", s.time});
  if (s.dryRun) cmd.emplace_back("--dry-run");
  cmd.emplace_back("--");
  // The given options by their canonical names, as --name=value (one token each, flags too).
  for (const auto& [name, value] : p.currentValues()) {
    if (!p.given(name) || slurmOptionNames().count(name) || perTaskOptionNames().count(name)) {
      continue;
    }
    cmd.push_back("--" + name + "=" + value);
  }
  return cmd;
}

std::string slurmSweepScript(const std::string& runner) {
  if (const char* env = std::getenv("RL_SLURM_SWEEP")) return env;
  const std::filesystem::path source = std::string(RL_EXPERIMENT_SCRIPTS_DIR) + "/slurm_sweep.py";
  if (std::filesystem::exists(source)) return source.string();
  // An installed runner: catkin installs the script beside it.
  return (std::filesystem::path(runner).parent_path() / "slurm_sweep.py").string();
}

}  // namespace rl_experiment
