#include "rl_experiment/runner/experiment.h"

#include <dirent.h>
#include <sys/stat.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "rl_agent/agent/agent_registry.h"
#include "rl_agent/journal/journaling_agent.h"
#include "rl_common/random.h"
#include "rl_env/env/environment_registry.h"
#include "rl_experiment/log/csv_file.h"
#include "rl_experiment/log/trial_logger.h"
#include "rl_experiment/suite/suite_environments.h"

#ifndef RL_EXPERIMENT_SOURCE_DIR
#define RL_EXPERIMENT_SOURCE_DIR ""
#endif
#ifndef RL_EXPERIMENT_VERSION
#define RL_EXPERIMENT_VERSION "unknown"
#endif

namespace rl_experiment {

void addExperimentOptions(rl_common::OptionParser& p, ExperimentConfig* c) {
  using rl_common::atLeast;
  using rl_common::greaterThan;
  rl_agent::addAgentOptions(p, &c->agent);
  rl_env::addEnvironmentOptions(p, &c->env, suiteEnvironments());
  p.value("nepisodes", &c->nepisodes,
          "episodes per trial (steps for non-episodic tasks, as the original)", atLeast(0));
  p.value("steps", &c->steps, "steps per trial of a non-episodic task (overrides --nepisodes)",
          atLeast(0));
  p.value("maxsteps", &c->maxsteps, "actions per episode before it is cut off", greaterThan(0));
  p.value("trials", &c->trials, "number of trials", greaterThan(0));
  p.value("first-trial", &c->firstTrial,
          "number of the first trial (split a sweep over machines: same seeds per trial)",
          atLeast(0));
  p.value("explore-steps", &c->exploreSteps,
          "phase 1: steps with the external reward hidden from the agent, intrinsic rewards on",
          atLeast(0));
  p.value("task-steps", &c->taskSteps,
          "phase 2 (after --explore-steps): steps with the external reward, intrinsic rewards "
          "off",
          atLeast(0));
  p.choice("task-rewards", &c->taskRewards, {"given", "learned"},
           "at the switch to --task-steps, model-based agents are given the task's reward "
           "of their exploration steps and rebuild their model (given: the paper's "
           "\"provided with a reward function\"), or learn it from the task steps only "
           "(learned)");
  p.value("eval-every", &c->evalEvery,
          "measure the model's accuracy every this many steps (0: never)", atLeast(0));
  p.value("eval-samples", &c->evalSamples, "state-actions sampled per accuracy measurement",
          greaterThan(0));
  p.value("eval-groups", &c->evalGroups,
          "also measure the accuracy per group of states, grouped by the values of these "
          "features (comma-separated indices, e.g. 4,2: LightWorld's room and have_key); "
          "groups-NNN.csv",
          rl_common::OptionParser::Check<std::vector<int>>([](const std::vector<int>& f) {
            for (int i : f) {
              if (i < 0) return std::string("feature indices must be >= 0");
            }
            return std::string();
          }));
  p.value("out", &c->out, "folder for the logs (none: no files)");
  p.flag("force", &c->force, true, "overwrite the results in --out");
  p.flag("journal", &c->journal, true,
         "every trial's agent appends the experiences it learns from to journal-NNN.rlj in "
         "--out, flushed per record (the agent node's --journal layout)");
  p.flag("resume", &c->resume, true, "finish the unfinished trials in --out");
  p.value("jobs", &c->jobs, "trials run in parallel processes", greaterThan(0));
  p.choice("format", &c->format, {"csv", "original"},
           "csv: logs only; original: also the original's bare numbers on stderr");
  p.value("label", &c->label, "name of this run in figures (default: the agent)");
  p.choice("progress", &c->progress, {"auto", "on", "off"},
           "progress bar on stderr (auto: only on a terminal)");
}

void finishExperimentConfig(const rl_common::OptionParser& p, ExperimentConfig* c) {
  const rl_env::EnvironmentCatalog& environments = suiteEnvironments();
  rl_env::checkEnvironmentOptions(p, c->env, environments);  // an unknown --env too
  c->env.env = environments.registry().canonical(c->env.env);
  try {
    c->agent.agent = rl_agent::agentRegistry().canonical(c->agent.agent);
  } catch (const std::invalid_argument& e) {
    throw rl_common::OptionError(std::string("option --agent: ") + e.what());
  }
  if (rl_agent::agentRegistry().hasFact(c->agent.agent, rl_agent::kTrueModelPlannerFact) &&
      !environments.registry().hasFact(c->env.env, rl_env::kTrueModelFact)) {
    throw rl_common::OptionError("--agent optimal plans on the environment's true model; --env " +
                                 c->env.env + " has none (valid: " + environments.trueModelNames() +
                                 ")");
  }
  rl_agent::applyAgentDefaults(p, &c->agent);
  rl_agent::checkAgentOptions(p, c->agent);
  // Parallel trials share the cores: each real-time agent plans with its share of them unless
  // --searchthreads says otherwise (the run records the value used).
  if (c->jobs > 1 && !p.given("searchthreads")) {
    c->agent.searchthreads =
        std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / c->jobs);
  }
  if (c->force && c->resume) {
    throw rl_common::OptionError("options --force and --resume exclude each other");
  }
  if ((c->force || c->resume || c->journal) && c->out.empty()) {
    throw rl_common::OptionError("options --force, --resume and --journal need --out");
  }
  if (c->format == "original" && c->jobs > 1) {
    throw rl_common::OptionError(
        "option --format original needs --jobs 1 (the bare-number stream has no trial column)");
  }
  // A task phase alone is allowed (intrinsic rewards off from the start).
  if (p.given("task-rewards") && (c->exploreSteps == 0 || c->taskSteps == 0)) {
    throw rl_common::OptionError(
        "option --task-rewards needs both phases (--explore-steps and --task-steps > 0)");
  }
  if ((c->exploreSteps > 0 || c->taskSteps > 0) && (p.given("steps") || p.given("nepisodes"))) {
    throw rl_common::OptionError(
        "options --explore-steps/--task-steps set the trial's length; do not combine them with "
        "--steps or --nepisodes");
  }
  if (c->label.empty()) c->label = c->agent.agent;
  for (char ch : c->label) {
    if (ch == ',' || ch == '\n' || ch == '/' || ch == ' ') {
      throw rl_common::OptionError("option --label: no commas, slashes or spaces, got '" +
                                   c->label + "'");
    }
  }
}

std::string suiteVersion() {
  std::string dir = RL_EXPERIMENT_SOURCE_DIR;
  if (!dir.empty()) {
    const std::string cmd = "git -C '" + dir + "' describe --always --dirty --tags 2>/dev/null";
    if (std::FILE* pipe = ::popen(cmd.c_str(), "r")) {
      char buf[256] = {0};
      std::string out;
      while (std::fgets(buf, sizeof(buf), pipe) != nullptr) out += buf;
      const int status = ::pclose(pipe);
      while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
      if (status == 0 && !out.empty()) return "git " + out;
    }
  }
  return std::string("package ") + RL_EXPERIMENT_VERSION;
}

TrialSeeds trialSeeds(std::uint64_t runSeed, int trial) {
  const auto t = static_cast<std::uint64_t>(trial);
  return {rl_common::Random::deriveSeed(runSeed, "agent", t),
          rl_common::Random::deriveSeed(runSeed, "environment", t),
          rl_common::Random::deriveSeed(runSeed, "evaluation", t)};
}

long peakRssKb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::atol(line.c_str() + 6);
  }
  return 0;
}

void resetPeakRss() {
  std::ofstream out("/proc/self/clear_refs");
  if (out) out << "5";
}

namespace {

bool isDirectory(const std::string& p) {
  struct stat st;
  return ::stat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

bool exists(const std::string& p) {
  struct stat st;
  return ::stat(p.c_str(), &st) == 0;
}

void makeDirectories(const std::string& p) {
  std::string partial;
  std::istringstream in(p);
  std::string part;
  if (!p.empty() && p[0] == '/') partial = "/";
  while (std::getline(in, part, '/')) {
    if (part.empty()) continue;
    partial += part + "/";
    if (::mkdir(partial.c_str(), 0755) != 0 && errno != EEXIST) {
      throw std::runtime_error("Experiment::prepare(): cannot create " + partial + ": " +
                               std::strerror(errno));
    }
  }
}

// Files of a run folder written by the runner.
bool isRunnerFile(const std::string& name) {
  for (const char* exact : {"run.csv", "seeds.csv", "trials.csv"}) {
    if (name == exact) return true;
  }
  for (const char* prefix : {"steps-", "episodes-", "accuracy-", "groups-", "trial-"}) {
    if (name.rfind(prefix, 0) == 0 && name.size() > 4 &&
        name.compare(name.size() - 4, 4, ".csv") == 0) {
      return true;
    }
  }
  return name.rfind("journal-", 0) == 0 && name.size() > 4 &&
         name.compare(name.size() - 4, 4, ".rlj") == 0;
}

std::vector<std::string> listFiles(const std::string& folder) {
  std::vector<std::string> out;
  if (DIR* d = ::opendir(folder.c_str())) {
    while (const dirent* e = ::readdir(d)) out.emplace_back(e->d_name);
    ::closedir(d);
  }
  std::sort(out.begin(), out.end());
  return out;
}

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
  if (exists(config_.out) && !isDirectory(config_.out)) {
    throw std::runtime_error("Experiment::prepare(): --out " + config_.out +
                             " exists and is not a folder");
  }
  makeDirectories(config_.out);
  std::vector<std::string> results;
  for (const auto& f : listFiles(config_.out)) {
    if (isRunnerFile(f)) results.push_back(f);
  }
  if (!results.empty()) {
    if (config_.resume) {
      if (!exists(path("run.csv"))) {
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
      if (recorded != fingerprint()) {
        throw std::runtime_error("Experiment::prepare(): cannot resume " + config_.out +
                                 ": its run.csv records a different configuration");
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
    if (config_.resume && !config_.out.empty() && exists(path(TrialLogger::summaryFile(t)))) {
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
  limits.steps = config_.steps > 0 ? config_.steps : config_.nepisodes;
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

std::vector<std::pair<std::string, std::string>> parseRow(const std::string& text) {
  const auto rows = parseCsv(text);
  std::vector<std::pair<std::string, std::string>> out;
  if (rows.size() < 2) return out;
  for (std::size_t i = 0; i < rows[0].size(); ++i) {
    out.emplace_back(rows[0][i], i < rows[1].size() ? rows[1][i] : "");
  }
  return out;
}

class Bar {
 public:
  explicit Bar(bool on) : on_(on) {}
  void show(const std::string& what, long done, long total) {
    if (!on_ || total <= 0) return;
    const int pct = static_cast<int>(100 * done / total);
    if (pct == last_ && done != total) return;
    last_ = pct;
    const int width = 30;
    const int fill = static_cast<int>(width * done / total);
    std::fprintf(stderr, "\r%s [%s%s] %3d%%", what.c_str(), std::string(fill, '#').c_str(),
                 std::string(width - fill, '.').c_str(), pct);
    std::fflush(stderr);
  }
  void clear() {
    if (on_ && last_ >= 0) std::fprintf(stderr, "\r%60s\r", "");
    last_ = -1;
  }

 private:
  bool on_;
  int last_ = -1;
};

}  // namespace

int Experiment::run(std::ostream& out, std::ostream& err) {
  const bool original = config_.format == "original";
  const bool barOn = !original && (config_.progress == "on" ||
                                   (config_.progress == "auto" && ::isatty(STDERR_FILENO)));
  Bar bar(barOn);
  const std::vector<int> pending = pendingTrials();
  if (config_.resume && pending.size() < std::size_t(config_.trials)) {
    out << "resuming: " << config_.trials - int(pending.size()) << " trial(s) already finished"
        << std::endl;
  }
  int failed = 0;
  if (config_.jobs <= 1) {
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
      if (!config_.out.empty()) collect();
    }
    return failed;
  }

  // Parallel trials: one child process per trial, at most `jobs` at a time. Each child sends
  // its summary row back through a pipe (the folder may be absent).
  std::map<pid_t, std::pair<int, int>> running;  // pid -> (trial, read end)
  std::size_t next = 0;
  int done = 0;
  out.flush();
  err.flush();
  std::fflush(nullptr);
  [[maybe_unused]] const pid_t parent = ::getpid();
  while (next < pending.size() || !running.empty()) {
    while (next < pending.size() && int(running.size()) < config_.jobs) {
      int fds[2];
      if (::pipe(fds) != 0) throw std::runtime_error("Experiment::run(): pipe failed");
      const int trial = pending[next++];
      const pid_t pid = ::fork();
      if (pid < 0) throw std::runtime_error("Experiment::run(): fork failed");
      if (pid == 0) {
#ifdef __linux__
        // A trial must not outlive the runner: `kill PID` of the parent alone (not the
        // terminal's Ctrl-C, which reaches the whole group) would leave it writing on.
        ::prctl(PR_SET_PDEATHSIG, SIGTERM);
        if (::getppid() != parent) ::_exit(1);  // the runner died before the line above
#endif
        ::close(fds[0]);
        int status = 0;
        try {
          const auto row = runTrial(trial, nullptr);
          const std::string text = trialLine(row) + "\n";
          if (::write(fds[1], text.data(), text.size()) < 0) status = 1;
        } catch (const std::exception& e) {
          std::fprintf(stderr, "experiment: trial %d failed: %s\n", trial, e.what());
          status = 1;
        }
        ::close(fds[1]);
        std::fflush(nullptr);
        ::_exit(status);
      }
      ::close(fds[1]);
      running[pid] = {trial, fds[0]};
    }
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, 0);
    if (pid < 0) break;
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    std::string text;
    char buf[4096];
    ssize_t n;
    while ((n = ::read(it->second.second, buf, sizeof(buf))) > 0) text.append(buf, std::size_t(n));
    ::close(it->second.second);
    ++done;
    bar.clear();
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && !text.empty()) {
      out << text << std::flush;
    } else {
      err << "experiment: trial " << it->second.first << " failed" << std::endl;
      ++failed;
    }
    running.erase(it);
    if (!config_.out.empty()) collect();
    bar.show(std::to_string(done) + "/" + std::to_string(pending.size()) + " trials", done,
             long(pending.size()));
  }
  bar.clear();
  return failed;
}

void Experiment::collect() const {
  if (config_.out.empty()) return;
  std::string header;
  std::string body;
  for (const auto& f : listFiles(config_.out)) {
    if (f.rfind("trial-", 0) != 0 || f.size() < 4 || f.compare(f.size() - 4, 4, ".csv") != 0) {
      continue;
    }
    const auto row = parseRow(readFile(path(f)));
    if (row.empty()) continue;
    std::vector<std::string> names, values;
    for (const auto& [n, v] : row) {
      names.push_back(n);
      values.push_back(v);
    }
    if (header.empty()) header = csvLine(names);
    body += csvLine(values);
  }
  if (!header.empty()) writeFileAtomically(path("trials.csv"), header + body);
}

}  // namespace rl_experiment
