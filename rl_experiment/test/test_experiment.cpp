#include "rl_experiment/runner/experiment.h"

#include <dirent.h>
#include <gtest/gtest.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include "rl_agent/journal/experience_journal.h"
#include "rl_experiment/log/csv_file.h"

namespace {

std::string tempDir() {
  char tmpl[] = "/tmp/rl_experiment_XXXXXX";
  return ::mkdtemp(tmpl);
}

bool exists(const std::string& p) {
  struct stat st;
  return ::stat(p.c_str(), &st) == 0;
}

// Parses a command line into a prepared Experiment.
rl_experiment::Experiment make(const std::vector<std::string>& args) {
  rl_experiment::ExperimentConfig c;
  rl_common::OptionParser p("experiment", "");
  rl_experiment::addExperimentOptions(p, &c);
  p.parse(args);
  rl_experiment::finishExperimentConfig(p, &c);
  return rl_experiment::Experiment(c, p.currentValues(), "test");
}

int runAll(rl_experiment::Experiment& e) {
  std::ostringstream out, err;
  e.prepare();
  return e.run(out, err);
}

// Runs a shell command; returns (exit status, stdout + stderr).
std::pair<int, std::string> shell(const std::string& cmd, bool mergeStderr = true) {
  std::string out;
  std::FILE* p = ::popen((mergeStderr ? cmd + " 2>&1" : cmd).c_str(), "r");
  char buf[4096];
  while (std::fgets(buf, sizeof(buf), p) != nullptr) out += buf;
  const int status = ::pclose(p);
  return {WEXITSTATUS(status), out};
}

const std::vector<std::string> kQuick = {"--agent", "qlearner", "--env",  "lightworld",
                                         "--steps", "300",      "--seed", "11"};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& more) {
  a.insert(a.end(), more.begin(), more.end());
  return a;
}

}  // namespace

TEST(Experiment, SeedsDifferPerTrialAndComponentAndRepeat) {
  std::set<std::uint64_t> all;
  for (int t = 0; t < 30; ++t) {
    const auto s = rl_experiment::trialSeeds(1, t);
    all.insert(s.agent);
    all.insert(s.env);
    all.insert(s.eval);
    EXPECT_EQ(rl_experiment::trialSeeds(1, t).agent, s.agent);
  }
  EXPECT_EQ(all.size(), 90u);
  EXPECT_NE(rl_experiment::trialSeeds(2, 0).agent, rl_experiment::trialSeeds(1, 0).agent);
}

TEST(Experiment, SameSeedSameLogsAndParallelJobsGiveTheSameTrials) {
  const std::string a = tempDir(), b = tempDir(), c = tempDir();
  auto e1 = make(with(kQuick, {"--trials", "2", "--out", a}));
  auto e2 = make(with(kQuick, {"--trials", "2", "--out", b}));
  auto e3 = make(with(kQuick, {"--trials", "2", "--out", c, "--jobs", "2"}));
  EXPECT_EQ(runAll(e1), 0);
  EXPECT_EQ(runAll(e2), 0);
  EXPECT_EQ(runAll(e3), 0);
  for (const char* f : {"/steps-000.csv", "/steps-001.csv", "/seeds.csv"}) {
    EXPECT_EQ(rl_experiment::readFile(a + f), rl_experiment::readFile(b + f)) << f;
    EXPECT_EQ(rl_experiment::readFile(a + f), rl_experiment::readFile(c + f)) << f;
  }
  // Different trials differ.
  EXPECT_NE(rl_experiment::readFile(a + "/steps-000.csv"),
            rl_experiment::readFile(a + "/steps-001.csv"));
  const auto trials = rl_experiment::parseCsv(rl_experiment::readFile(a + "/trials.csv"));
  ASSERT_EQ(trials.size(), 3u);
  EXPECT_EQ(trials[2][0], "1");
  const auto run = rl_experiment::readFile(a + "/run.csv");
  EXPECT_NE(run.find("suite_version,"), std::string::npos);
  EXPECT_NE(run.find("run_seed,11"), std::string::npos);
  EXPECT_NE(run.find("option.agent,qlearner"), std::string::npos);
  EXPECT_NE(run.find("option.alpha,"), std::string::npos);
}

TEST(Experiment, AFixedRolloutRunResumesWithOtherJobs) {
  // --jobs sets the real-time planner's --searchthreads; a run with --rollouts does not read
  // it, so its recorded configuration does not change with --jobs.
  const std::string dir = tempDir();
  const std::vector<std::string> vanir = {
      "--agent", "texplore", "--env",      "lightworld", "--v",     "1",
      "--n",     "3",        "--rollouts", "5",          "--steps", "20",
      "--seed",  "3",        "--progress", "off",        "--out",   dir};
  auto first = make(with(vanir, {"--trials", "1", "--jobs", "2"}));
  ASSERT_EQ(runAll(first), 0);
  auto resume = make(with(vanir, {"--trials", "2", "--jobs", "1", "--resume"}));
  resume.prepare();
  EXPECT_EQ(resume.pendingTrials(), std::vector<int>{1});
}

TEST(Experiment, NeverOverwritesWithoutForceAndResumesUnfinishedTrials) {
  const std::string dir = tempDir();
  auto first = make(with(kQuick, {"--trials", "2", "--out", dir}));
  ASSERT_EQ(runAll(first), 0);
  const std::string step0 = rl_experiment::readFile(dir + "/steps-000.csv");

  auto again = make(with(kQuick, {"--trials", "2", "--out", dir}));
  EXPECT_THROW(again.prepare(), std::runtime_error);
  EXPECT_EQ(rl_experiment::readFile(dir + "/steps-000.csv"), step0);

  // A killed run: trial 1 unfinished (no summary, half a steps file).
  std::remove((dir + "/trial-001.csv").c_str());
  rl_experiment::writeFileAtomically(dir + "/steps-001.csv", "trial,step\n1,0\n");
  auto other = make(with(kQuick, {"--trials", "2", "--out", dir, "--resume", "--alpha", "0.5"}));
  try {  // a different configuration, named
    other.prepare();
    ADD_FAILURE() << "resumed with another --alpha";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("(alpha: 0.3 -> 0.5)"), std::string::npos) << e.what();
  }
  auto resume = make(with(kQuick, {"--trials", "2", "--out", dir, "--resume"}));
  resume.prepare();
  EXPECT_EQ(resume.pendingTrials(), std::vector<int>{1});
  std::ostringstream out, err;
  EXPECT_EQ(resume.run(out, err), 0);
  EXPECT_EQ(rl_experiment::readFile(dir + "/steps-000.csv"), step0);
  EXPECT_TRUE(exists(dir + "/trial-001.csv"));
  EXPECT_EQ(rl_experiment::parseCsv(rl_experiment::readFile(dir + "/steps-001.csv")).size(), 301u);

  auto force = make(with(kQuick, {"--trials", "1", "--out", dir, "--force"}));
  ASSERT_EQ(runAll(force), 0);
  EXPECT_FALSE(exists(dir + "/steps-001.csv"));  // --force removed the old results
  EXPECT_EQ(rl_experiment::readFile(dir + "/steps-000.csv"), step0);
}

TEST(Experiment, BadOptionsSayWhatIsValid) {
  EXPECT_THROW(make({"--agent", "nosuchagent"}), rl_common::OptionError);
  try {
    make({"--agent", "nosuchagent"});
  } catch (const rl_common::OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("qlearner"), std::string::npos) << e.what();
  }
  EXPECT_THROW(make({"--format", "xml"}), rl_common::OptionError);
  EXPECT_THROW(make({"--force"}), rl_common::OptionError);  // needs --out
  EXPECT_THROW(make({"--format", "original", "--jobs", "2"}), rl_common::OptionError);
  EXPECT_THROW(make({"--explore-steps", "5", "--steps", "9"}), rl_common::OptionError);
  EXPECT_THROW(make({"--label", "a,b"}), rl_common::OptionError);

  const auto [status, text] = shell(std::string(EXPERIMENT_BIN) + " --agent nosuchagent");
  EXPECT_EQ(status, 2);
  EXPECT_NE(text.find("valid agents"), std::string::npos) << text;
  const auto [s2, t2] = shell(std::string(EXPERIMENT_BIN) + " --nosuchoption 3");
  EXPECT_EQ(s2, 2);
  EXPECT_NE(t2.find("nosuchoption"), std::string::npos) << t2;
}

TEST(Experiment, JournalKeepsEveryTrialsExperiences) {
  char dir[] = "/tmp/rl_runner_journal_XXXXXX";
  ASSERT_NE(::mkdtemp(dir), nullptr);
  const std::string out = std::string(dir) + "/run";
  const std::string run = std::string(EXPERIMENT_BIN) +
                          " --agent texplore --v 1 --n 3 --rollouts 5 --env lightworld "
                          "--steps 60 --trials 2 --eval-every 0 --progress off --journal --out " +
                          out;
  ASSERT_EQ(shell(run + " > /dev/null").first, 0);
  const auto seeds = rl_experiment::parseCsv(rl_experiment::readFile(out + "/seeds.csv"));
  ASSERT_EQ(seeds.size(), 3u);
  for (int trial = 0; trial < 2; ++trial) {
    const auto j =
        rl_agent::readExperienceJournal(out + "/journal-00" + std::to_string(trial) + ".rlj");
    EXPECT_EQ(j.numFeatures, 17);
    // 60 steps: the agent learns from the 59 that a next state followed.
    ASSERT_EQ(j.records.size(), 59u);
    for (std::size_t i = 0; i + 1 < j.records.size(); ++i) {
      ASSERT_EQ(j.records[i].next, j.records[i + 1].s) << "trial " << trial << " record " << i;
    }
    std::map<std::string, std::string> header(j.header.begin(), j.header.end());
    EXPECT_EQ(header["trial"], std::to_string(trial));
    EXPECT_EQ(header["seed"], seeds[static_cast<std::size_t>(trial) + 1][1]);
    EXPECT_EQ(header["agent"], "texplore");
  }
  // --force replaces the journals with the new run's, not appends to them.
  ASSERT_EQ(shell(run + " --force > /dev/null").first, 0);
  EXPECT_EQ(rl_agent::readExperienceJournal(out + "/journal-000.rlj").records.size(), 59u);
  const auto [status, text] = shell(std::string(EXPERIMENT_BIN) + " --journal --steps 5");
  EXPECT_EQ(status, 2);
  EXPECT_NE(text.find("--journal need --out"), std::string::npos) << text;
  std::system(("rm -rf " + std::string(dir)).c_str());
}

TEST(Experiment, CheckBuildsTheAgentForTheTask) {
  // Rules that need the task or the explorer fail --check too, not only the first trial.
  const std::string check = std::string(EXPERIMENT_BIN) + " --env lightworld --agent texplore ";
  const auto [bad, badText] = shell(check + "--rollouts 5 --taskplanner vi --taskkey 0,17 --check");
  EXPECT_EQ(bad, 2);
  EXPECT_NE(badText.find("--taskkey feature 17 out of range"), std::string::npos) << badText;
  const auto [idle, idleText] =
      shell(check + "--rollouts 5 --explore random --deferregions 2 --check");
  EXPECT_EQ(idle, 2);
  EXPECT_NE(idleText.find("--deferregions needs a deferral"), std::string::npos) << idleText;
  EXPECT_EQ(shell(check + "--rollouts 5 --v 1 --n 3 --deferregions 2 --check").first, 2);
  EXPECT_EQ(shell(check + "--rollouts 5 --v 1 --n 3 --defer 300 --deferregions 2 --check").first,
            0);
}

TEST(Experiment, AgentDefaultsToTexploreAsTheAgentNodes) {
  // One default for --agent (AgentOptions): VANIR's options are valid without --agent, and a
  // model-free agent's are not.
  const std::string bin = std::string(EXPERIMENT_BIN) + " --env lightworld ";
  EXPECT_EQ(shell(bin + "--v 1 --n 3 --check").first, 0);
  const auto [status, text] = shell(bin + "--alpha 0.5 --check");
  EXPECT_EQ(status, 2);
  EXPECT_NE(text.find("not to 'texplore'"), std::string::npos) << text;
}

TEST(Experiment, OriginalFormatPrintsBareNumbersOnStderr) {
  const auto [status, text] = shell(std::string(EXPERIMENT_BIN) +
                                        " --agent qlearner --env lightworld --steps 40 --format "
                                        "original 2>&1 >/dev/null",
                                    false);
  EXPECT_EQ(status, 0);
  std::istringstream in(text);
  int n = 0;
  for (std::string line; std::getline(in, line); ++n) {
    EXPECT_NO_THROW(std::stod(line)) << line;
    EXPECT_EQ(line.find_first_not_of("-0123456789.e+"), std::string::npos) << line;
  }
  EXPECT_EQ(n, 40);
}

TEST(Experiment, FigureScriptDrawsFromAFabricatedRunFolder) {
  const std::string run = tempDir();
  const std::string figs = run + "/figs";
  rl_experiment::writeFileAtomically(run + "/run.csv", "name,value\nlabel,fake\nrun_seed,1\n");
  for (int t = 0; t < 2; ++t) {
    std::string steps =
        "trial,step,phase,episode,action,reward,reward_seen,variance,novelty,"
        "other,target,terminal\n";
    for (int i = 0; i < 6; ++i) {
      steps += std::to_string(t) + "," + std::to_string(i) + "," + (i < 3 ? "explore" : "task") +
               ",0," + (i % 2 ? "5" : "0") + "," + (i == 4 ? "10" : "0") + ",0,0,0,0," +
               (i % 2 ? "key" : "") + ",0\n";
    }
    rl_experiment::writeFileAtomically(run + "/steps-00" + std::to_string(t) + ".csv", steps);
    rl_experiment::writeFileAtomically(run + "/accuracy-00" + std::to_string(t) + ".csv",
                                       "trial,step,phase,variational_distance,samples\n" +
                                           std::to_string(t) + ",0,explore,0.5,10\n" +
                                           std::to_string(t) + ",3,explore,0.4,10\n");
    rl_experiment::writeFileAtomically(run + "/trial-00" + std::to_string(t) + ".csv",
                                       "trial,label,total_reward,task_reward,final_accuracy\n" +
                                           std::to_string(t) + ",fake,10,10,0.4\n");
  }
  const auto [status, text] =
      shell("/usr/bin/python3 " + std::string(PLOT_SCRIPT) + " --out " + figs + " " + run);
  ASSERT_EQ(status, 0) << text;
  for (const char* f : {"/reward.png", "/reward.pdf", "/accuracy.png", "/accuracy.pdf",
                        "/press.png", "/press.pdf", "/results.md"}) {
    EXPECT_TRUE(exists(figs + f)) << f << "\n" << text;
  }
  const std::string table = rl_experiment::readFile(figs + "/results.md");
  EXPECT_NE(table.find("| fake |"), std::string::npos) << table;
  EXPECT_NE(table.find("10.0"), std::string::npos) << table;
}

// The reproduction compares TEXPLORE-VANIR with the paper's comparison methods (section 5.1),
// each accepted by the runner it will call.
TEST(ReproduceScript, ListsThePapersComparisonAgents) {
  const auto [status, text] =
      shell("RL_EXPERIMENT=" + std::string(EXPERIMENT_BIN) + " /usr/bin/python3 " +
            std::string(REPRODUCE_SCRIPT) + " lightworld --list");
  ASSERT_EQ(status, 0) << text;
  for (const char* agent :
       {"texplore-vanir ", "texplore-greedy ", "texplore-random ", "texplore-competence ",
        "texplore-prederror ", "texplore-rmax-style ", "texplore-boltzmann ", "tabular-random ",
        "rmax ", "optimal ", "texplore-v0-n3 "}) {
    EXPECT_NE(text.find(agent), std::string::npos) << agent << "\n" << text;
  }
  EXPECT_NE(text.find("--explore competence"), std::string::npos) << text;
  EXPECT_NE(text.find("--model tabular --explore random --planner vi"), std::string::npos) << text;
  EXPECT_EQ(text.find("skipping agent texplore"), std::string::npos) << text;
}

// --task-planner vi (the default): the explore-task runs of the model-based agents plan their
// task phase by value iteration over LightWorld's position, key, door and room; the combined
// runs do not; --task-planner same leaves UCT in the task phase.
TEST(ReproduceScript, TaskPlannerViGoesToTheExploreTaskRunsOnly) {
  const auto [status, text] =
      shell("RL_EXPERIMENT=" + std::string(EXPERIMENT_BIN) + " /usr/bin/python3 " +
            std::string(REPRODUCE_SCRIPT) + " lightworld --list");
  ASSERT_EQ(status, 0) << text;
  const auto [sameStatus, sameText] =
      shell("RL_EXPERIMENT=" + std::string(EXPERIMENT_BIN) + " /usr/bin/python3 " +
            std::string(REPRODUCE_SCRIPT) + " lightworld --list --task-planner same");
  ASSERT_EQ(sameStatus, 0) << sameText;
  EXPECT_EQ(sameText.find("--taskplanner"), std::string::npos) << sameText;
  EXPECT_NE(sameText.find("explore-task, combined: texplore-vanir"), std::string::npos) << sameText;
  const auto line = [&](const std::string& start) {
    const auto at = text.find(start);
    return at == std::string::npos ? std::string() : text.substr(at, text.find('\n', at) - at);
  };
  EXPECT_NE(line("explore-task: texplore-vanir").find("--taskplanner vi --taskkey 0,1,2,3,4"),
            std::string::npos)
      << text;
  EXPECT_EQ(line("combined: texplore-vanir").find("--taskplanner"), std::string::npos) << text;
  EXPECT_NE(line("combined: texplore-vanir"), "") << text;
  EXPECT_EQ(line("explore-task, combined: qlearner").find("--taskplanner"), std::string::npos)
      << text;
}

namespace {

/// The runner's configuration from a command line, as experiment's main() finishes it.
rl_experiment::ExperimentConfig finishedConfig(const std::vector<std::string>& args) {
  rl_experiment::ExperimentConfig c;
  rl_common::OptionParser p("experiment", "");
  rl_experiment::addExperimentOptions(p, &c);
  p.parse(args);
  rl_experiment::finishExperimentConfig(p, &c);
  return c;
}

}  // namespace

TEST(Experiment, ParallelTrialsShareTheCoresBetweenSearchThreads) {
  const auto config = finishedConfig;
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  EXPECT_EQ(config({"--agent", "texplore"}).agent.searchthreads, 0);  // one per core
  EXPECT_EQ(config({"--agent", "texplore", "--jobs", "2"}).agent.searchthreads,
            std::max(1, cores / 2));
  EXPECT_EQ(config({"--agent", "texplore", "--jobs", "64"}).agent.searchthreads, 1);
  EXPECT_EQ(
      config({"--agent", "texplore", "--jobs", "2", "--searchthreads", "3"}).agent.searchthreads,
      3);
}

// --agent optimal on an environment without a true model is refused with the configuration,
// naming the environments that have one (from the registry's facts).
TEST(Experiment, OptimalNeedsAnEnvironmentWithATrueModel) {
  const auto finish = finishedConfig;
  EXPECT_NO_THROW(finish({"--agent", "optimal", "--env", "taxi"}));
  try {
    finish({"--agent", "optimal", "--env", "mcar"});
    FAIL() << "accepted --agent optimal --env mcar";
  } catch (const rl_common::OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("fourrooms, lightworld, taxi, tworooms"),
              std::string::npos)
        << e.what();
  }
}

namespace {

/// The pids of the processes whose parent is `parent` (from /proc/PID/stat).
std::vector<pid_t> childrenOf(pid_t parent) {
  std::vector<pid_t> out;
  DIR* proc = ::opendir("/proc");
  if (proc == nullptr) return out;
  while (const dirent* e = ::readdir(proc)) {
    const pid_t pid = static_cast<pid_t>(std::atol(e->d_name));
    if (pid <= 0) continue;
    std::ifstream f("/proc/" + std::string(e->d_name) + "/stat");
    std::string stat((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    const std::size_t close = stat.rfind(')');  // the command name may hold spaces
    if (close == std::string::npos) continue;
    std::istringstream rest(stat.substr(close + 2));
    char state = 0;
    long ppid = 0;
    rest >> state >> ppid;
    if (ppid == parent) out.push_back(pid);
  }
  ::closedir(proc);
  return out;
}

}  // namespace

TEST(Experiment, ParallelTrialsDoNotOutliveAKilledRunner) {
  // This process adopts the runner's orphans, so that it can see whether they end.
  ASSERT_EQ(::prctl(PR_SET_CHILD_SUBREAPER, 1), 0);
  char dir[] = "/tmp/rl_parent_death_XXXXXX";
  ASSERT_NE(::mkdtemp(dir), nullptr);
  const std::string out = std::string(dir) + "/run";
  const pid_t runner = ::fork();
  ASSERT_GE(runner, 0);
  if (runner == 0) {
    // Trials that take minutes: only a signal ends them within the test.
    ::execl(EXPERIMENT_BIN, EXPERIMENT_BIN, "--agent", "qlearner", "--env", "lightworld", "--steps",
            "100000000", "--trials", "2", "--jobs", "2", "--progress", "off", "--out", out.c_str(),
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  std::vector<pid_t> trials;
  for (int i = 0; i < 400 && trials.size() < 2; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    trials = childrenOf(runner);
  }
  ASSERT_EQ(trials.size(), 2u) << "the runner did not start its two trial processes";
  ASSERT_EQ(::kill(runner, SIGKILL), 0);  // the parent alone, as `kill -9 PID` does
  int status = 0;
  ASSERT_EQ(::waitpid(runner, &status, 0), runner);
  // The orphans are now this process's children; each must end within 10 s.
  std::set<pid_t> left(trials.begin(), trials.end());
  for (int i = 0; i < 200 && !left.empty(); ++i) {
    for (auto it = left.begin(); it != left.end();) {
      const pid_t done = ::waitpid(*it, &status, WNOHANG);
      if (done == *it) {
        EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << "trial pid " << *it;
        it = left.erase(it);
      } else {
        ++it;
      }
    }
    if (!left.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  EXPECT_TRUE(left.empty()) << left.size() << " trial processes outlived the runner";
  for (pid_t pid : left) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
  }
  ::prctl(PR_SET_CHILD_SUBREAPER, 0);
  std::system(("rm -rf " + std::string(dir)).c_str());
}
