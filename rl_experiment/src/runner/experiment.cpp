#include "rl_experiment/runner/experiment.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>

#include "rl_agent/agent/agent_registry.h"
#include "rl_agent/journal/journaling_agent.h"
#include "rl_common/random.h"
#include "rl_experiment/log/csv_file.h"
#include "rl_experiment/log/trial_logger.h"
#include "rl_experiment/runner/progress_bar.h"
#include "rl_experiment/runner/run_folder.h"
#include "rl_experiment/runner/trial_processes.h"
#include "rl_experiment/suite/suite_environments.h"

namespace rl_experiment {

TrialSeeds trialSeeds(std::uint64_t runSeed, int trial) {
  const auto t = static_cast<std::uint64_t>(trial);
  return {rl_common::Random::deriveSeed(runSeed, "agent", t),
          rl_common::Random::deriveSeed(runSeed, "environment", t),
          rl_common::Random::deriveSeed(runSeed, "evaluation", t)};
}

namespace {

std::string sanitize(std::string v) {
  for (char& ch : v) {
    if (ch == ',' || ch == '\n') ch = ';';
  }
  return v;
}

// Options that may differ between a run and its resumption.
bool ignoredForResume(const std::string& name) {
  return name == "resume" || name == "force" || name == "jobs" || name == "trials" ||
         name == "progress" || name == "format";
}

}  // namespace

Experiment::Experiment(ExperimentConfig config,
                       std::vector<std::pair<std::string, std::string>> values,
                       std::string commandLine)
    : config_(std::move(config)),
      values_(std::move(values)),
      commandLine_(std::move(commandLine)) {}

std::string Experiment::path(const std::string& file) const { return config_.out + "/" + file; }

std::string Experiment::fingerprint() const {
  std::string f;
  for (const auto& [name, value] : values_) {
    if (!ignoredForResume(name)) f += name + "=" + sanitize(value) + "\n";
  }
  return f;
}

void Experiment::prepare() {
  if (config_.out.empty()) return;
  makeRunFolder(config_.out);
  std::vector<std::string> results;
  for (const auto& f : listFiles(config_.out)) {
    if (isRunnerFile(f)) results.push_back(f);
  }
  if (!results.empty()) {
    if (config_.resume) {
      if (!std::filesystem::exists(path("run.csv"))) {
        throw std::runtime_error("Experiment::prepare(): cannot resume " + config_.out +
                                 ": it has no run.csv");
      }
      std::string recorded;
      for (const auto& row : parseCsv(readFile(path("run.csv")))) {
        if (row.size() >= 2 && row[0].rfind("option.", 0) == 0) {
          const std::string name = row[0].substr(7);
          if (!ignoredForResume(name)) recorded += name + "=" + row[1] + "\n";
        }
      }
      const std::string now = fingerprint();
      if (recorded != now) {
        throw std::runtime_error("Experiment::prepare(): cannot resume " + config_.out +
                                 ": its run.csv records a different configuration (" +
                                 configurationDifference(recorded, now) + ")");
      }
    } else if (config_.force) {
      for (const auto& f : results) std::remove(path(f).c_str());
    } else {
      throw std::runtime_error("Experiment::prepare(): " + config_.out +
                               " already holds results (" + results.front() +
                               ", ...); use --force to overwrite them or --resume to finish the "
                               "run, or choose another --out");
    }
  }
  std::string run = csvLine({"name", "value"});
  run += csvLine({"suite_version", sanitize(suiteVersion())});
  run += csvLine({"command_line", sanitize(commandLine_)});
  run += csvLine({"run_seed", std::to_string(config_.env.seed)});
  run += csvLine({"label", config_.label});
  for (const auto& [name, value] : values_) run += csvLine({"option." + name, sanitize(value)});
  writeFileAtomically(path("run.csv"), run);

  std::string seeds = csvLine({"trial", "agent_seed", "env_seed", "eval_seed"});
  for (int t = 0; t < config_.firstTrial + config_.trials; ++t) {
    if (t < config_.firstTrial) continue;
    const TrialSeeds s = trialSeeds(config_.env.seed, t);
    seeds += csvLine({std::to_string(t), std::to_string(s.agent), std::to_string(s.env),
                      std::to_string(s.eval)});
  }
  writeFileAtomically(path("seeds.csv"), seeds);
}

std::vector<int> Experiment::pendingTrials() const {
  std::vector<int> out;
  for (int t = config_.firstTrial; t < config_.firstTrial + config_.trials; ++t) {
    if (config_.resume && !config_.out.empty() &&
        std::filesystem::exists(path(TrialLogger::summaryFile(t)))) {
      continue;
    }
    out.push_back(t);
  }
  return out;
}

namespace {

class ProgressRelay : public TrialObserver {
 public:
  ProgressRelay(const std::function<void(long, long)>& f, long planned)
      : f_(f), planned_(planned) {}
  void onStep(const StepRecord& r) override {
    if (f_) f_(r.step + 1, planned_);
  }

 private:
  const std::function<void(long, long)>& f_;
  long planned_;
};

class Tee : public TrialObserver {
 public:
  explicit Tee(std::vector<TrialObserver*> all) : all_(std::move(all)) {}
  void beforeStep(const rl_common::Environment& env, long step, int action) override {
    for (auto* o : all_) o->beforeStep(env, step, action);
  }
  void onStep(const StepRecord& r) override {
    for (auto* o : all_) o->onStep(r);
  }
  void onEpisode(const EpisodeRecord& r) override {
    for (auto* o : all_) o->onEpisode(r);
  }
  void onCheckpoint(long n, Phase p, const rl_common::Agent& a,
                    const rl_common::Environment& e) override {
    for (auto* o : all_) o->onCheckpoint(n, p, a, e);
  }
  void onPhase(Phase p) override {
    for (auto* o : all_) o->onPhase(p);
  }

 private:
  std::vector<TrialObserver*> all_;
};

}  // namespace

std::vector<std::pair<std::string, std::string>> Experiment::runTrial(
    int trial, std::ostream* original, const std::function<void(long, long)>& progress) const {
  const TrialSeeds seeds = trialSeeds(config_.env.seed, trial);
  rl_env::EnvironmentOptions eo = config_.env;
  eo.seed = seeds.env;
  rl_agent::AgentOptions ao = config_.agent;
  ao.seed = seeds.agent;
  resetPeakRss();
  const auto start = std::chrono::steady_clock::now();
  auto env = suiteEnvironments().make(eo);
  // `optimal` plans on the environment's exact dynamics (the other agents ignore them).
  auto agent = rl_agent::makeAgent(ao, env->describe(),
                                   dynamic_cast<const rl_common::TrueModel*>(env.get()));
  if (config_.journal) {
    // A trial always runs from its start (--resume reruns unfinished ones): a new journal.
    char name[32];
    std::snprintf(name, sizeof(name), "journal-%03d.rlj", trial);
    std::remove(path(name).c_str());
    auto journal = std::make_shared<rl_agent::ExperienceJournalWriter>(
        path(name), static_cast<int>(env->describe().numFeatures()),
        rl_agent::JournalHeader{{"written_by", "rl_experiment experiment"},
                                {"version", suiteVersion()},
                                {"agent", ao.agent},
                                {"seed", std::to_string(ao.seed)},
                                {"trial", std::to_string(trial)},
                                {"command_line", commandLine_}});
    agent = std::make_unique<rl_agent::JournalingAgent>(std::move(agent), std::move(journal));
  }

  TrialLimits limits;
  limits.steps = config_.nonEpisodicSteps();
  limits.episodes = config_.nepisodes;
  limits.maxSteps = config_.maxsteps;
  limits.exploreSteps = config_.exploreSteps;
  limits.taskSteps = config_.taskSteps;
  limits.checkpointEvery = config_.evalEvery;
  limits.giveTaskRewards = config_.taskRewards == "given";
  const TrialRunner runner(limits);

  TrialInfo info{trial, config_.label, ao.agent, eo.env, seeds.agent, seeds.env, seeds.eval};
  TrialLogger logger(config_.out, info, EvalSettings{config_.evalSamples, config_.evalGroups},
                     !env->isEpisodic(), original);
  ProgressRelay relay(progress, runner.plannedSteps(env->isEpisodic()));
  Tee tee({&logger, &relay});
  const TrialSummary summary = runner.run(*env, *agent, &tee);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return logger.finish(summary, seconds, peakRssKb());
}

namespace {

std::string trialLine(const std::vector<std::pair<std::string, std::string>>& row) {
  std::map<std::string, std::string> m(row.begin(), row.end());
  std::string line = "trial " + m["trial"] + ": " + m["steps"] + " steps, " + m["episodes"] +
                     " episodes, total reward " + m["total_reward"];
  if (m["explore_reward"] != "0" || m["task_reward"] != "0") {
    line += " (explore " + m["explore_reward"] + ", task " + m["task_reward"] + ")";
  }
  if (!m["final_accuracy"].empty()) line += ", model variational distance " + m["final_accuracy"];
  line += ", " + m["steps_per_second"] + " steps/s, peak memory " + m["peak_rss_mb"] + " MB";
  return line;
}

}  // namespace

int Experiment::run(std::ostream& out, std::ostream& err) {
  const bool original = config_.format == "original";
  const bool barOn = !original && (config_.progress == "on" ||
                                   (config_.progress == "auto" && ::isatty(STDERR_FILENO)));
  ProgressBar bar(barOn);
  const std::vector<int> pending = pendingTrials();
  if (config_.resume && pending.size() < std::size_t(config_.trials)) {
    out << "resuming: " << config_.trials - int(pending.size()) << " trial(s) already finished"
        << std::endl;
  }
  if (config_.jobs <= 1) {
    int failed = 0;
    for (int trial : pending) {
      const std::string what = "trial " + std::to_string(trial);
      try {
        const auto row = runTrial(trial, original ? &err : nullptr,
                                  [&](long d, long t) { bar.show(what, d, t); });
        bar.clear();
        out << trialLine(row) << std::endl;
      } catch (const std::exception& e) {
        bar.clear();
        err << "experiment: trial " << trial << " failed: " << e.what() << std::endl;
        ++failed;
      }
      collect();
    }
    return failed;
  }
  // Parallel trials: each child sends its summary line back (the folder may be absent).
  out.flush();
  err.flush();
  int done = 0;
  const int failed = runTrialsInChildProcesses(
      pending, config_.jobs, [this](int trial) { return trialLine(runTrial(trial, nullptr)); },
      [&](int trial, const std::optional<std::string>& line) {
        ++done;
        bar.clear();
        if (line) {
          out << *line << std::flush;
        } else {
          err << "experiment: trial " << trial << " failed" << std::endl;
        }
        collect();
        bar.show(std::to_string(done) + "/" + std::to_string(pending.size()) + " trials", done,
                 long(pending.size()));
      });
  bar.clear();
  return failed;
}

void Experiment::collect() const {
  if (!config_.out.empty()) collectTrialSummaries(config_.out);
}

}  // namespace rl_experiment
