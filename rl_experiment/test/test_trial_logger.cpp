#include "rl_experiment/log/trial_logger.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <sstream>

#include "rl_agent/agent/agent_options.h"
#include "rl_agent/agent/agent_registry.h"
#include "rl_common/option_parser.h"
#include "rl_env/env/light_world.h"

namespace {

std::string tempDir() {
  char tmpl[] = "/tmp/rl_logger_XXXXXX";
  return ::mkdtemp(tmpl);
}

std::vector<std::vector<std::string>> rowsOf(const std::string& path) {
  return rl_experiment::parseCsv(rl_experiment::readFile(path));
}

/// The agent of these command-line options.
std::unique_ptr<rl_common::Agent> agentOf(const std::vector<std::string>& args,
                                          const rl_common::EnvironmentDescription& d,
                                          std::uint64_t seed) {
  rl_agent::AgentOptions o;
  rl_common::OptionParser p("test", "");
  rl_agent::addAgentOptions(p, &o);
  p.parse(args);
  rl_agent::applyAgentDefaults(p, &o);
  rl_agent::checkAgentOptions(p, o);
  o.seed = seed;
  return rl_agent::makeAgent(o, d);
}

// TEXPLORE-VANIR with a small synchronous budget, for fast deterministic tests.
std::unique_ptr<rl_common::Agent> vanir(const rl_common::EnvironmentDescription& d,
                                        std::uint64_t seed) {
  return agentOf({"--agent", "texplore", "--v", "1", "--n", "3", "--rollouts", "10"}, d, seed);
}

}  // namespace

TEST(TrialLogger, WritesStepsEpisodesAccuracyAndSummary) {
  const std::string dir = tempDir();
  rl_env::LightWorld env(3, true);
  auto agent = vanir(env.describe(), 5);
  rl_experiment::TrialLimits limits;
  limits.exploreSteps = 30;
  limits.taskSteps = 20;
  limits.checkpointEvery = 25;
  std::ostringstream original;
  rl_experiment::TrialInfo info{4, "vanir", "texplore", "lightworld", 5, 3, 9};
  rl_experiment::TrialLogger logger(dir, info, rl_experiment::EvalSettings{200, {}}, true,
                                    &original);
  const auto summary = rl_experiment::TrialRunner(limits).run(env, *agent, &logger);
  const auto row = logger.finish(summary, 1.5, 2048);

  const auto steps = rowsOf(dir + "/steps-004.csv");
  ASSERT_EQ(steps.size(), 51u);  // header + 50 steps
  EXPECT_EQ(steps[0][0], "trial");
  EXPECT_EQ(steps[1][0], "4");
  EXPECT_EQ(steps[1][2], "explore");
  EXPECT_EQ(steps[31][2], "task");
  // TEXPLORE-VANIR reports its intrinsic parts: some novelty while exploring, none in the task.
  double exploreNovelty = 0.0, taskIntrinsic = 0.0;
  for (std::size_t i = 1; i < steps.size(); ++i) {
    ASSERT_EQ(steps[i].size(), 14u);
    const double v = std::stod(steps[i][7]), n = std::stod(steps[i][8]);
    if (steps[i][2] == "explore") {
      exploreNovelty += n;
    } else {
      taskIntrinsic += v + n;
    }
    // The planner's value of the chosen action and the spread of its values at the state.
    ASSERT_FALSE(steps[i][12].empty()) << "step " << i;
    EXPECT_GE(std::stod(steps[i][13]), 0.0) << "step " << i;
    const int action = std::stoi(steps[i][4]);
    // PRESS (5) and PICKUP (4) carry where they were tried; moves carry nothing.
    EXPECT_EQ(steps[i][10].empty(), action < 4) << "step " << i;
  }
  EXPECT_GT(exploreNovelty, 0.0);
  EXPECT_EQ(taskIntrinsic, 0.0);

  const auto acc = rowsOf(dir + "/accuracy-004.csv");
  ASSERT_EQ(acc.size(), 4u);  // header + steps 0, 25, 50
  EXPECT_EQ(acc[1][1], "0");
  EXPECT_EQ(acc[3][1], "50");
  EXPECT_EQ(acc[3][2], "task");
  for (std::size_t i = 1; i < acc.size(); ++i) {
    const double vd = std::stod(acc[i][3]);
    EXPECT_GE(vd, 0.0);
    EXPECT_LE(vd, 1.0);
  }
  const auto eps = rowsOf(dir + "/episodes-004.csv");
  ASSERT_EQ(eps.size(), 2u);
  EXPECT_EQ(eps[1][3], "50");

  const auto trial = rowsOf(dir + "/trial-004.csv");
  ASSERT_EQ(trial.size(), 2u);
  ASSERT_EQ(trial[0].size(), row.size());
  EXPECT_EQ(trial[0][0], "trial");
  EXPECT_EQ(trial[1][7], "50");  // steps
  // Exploration steps with the key on the floor: LightWorld starts with it there, and only the
  // 30 exploration steps count.
  EXPECT_EQ(trial[0][23], "explore_key_on_floor");
  EXPECT_GE(std::stol(trial[1][23]), 1);
  EXPECT_LE(std::stol(trial[1][23]), 30);
  EXPECT_EQ(trial[0][26], "peak_rss_mb");
  EXPECT_EQ(trial[1][26], "2");
  // The original stream: one bare reward per step (non-episodic).
  std::istringstream in(original.str());
  int lines = 0;
  for (std::string l; std::getline(in, l);) {
    ++lines;
    EXPECT_NO_THROW(std::stod(l));
  }
  EXPECT_EQ(lines, 50);
}

// The accuracy log is of every model kind, not of the tree forests alone (R-MAX's tabular model
// and the M5 regression trees logged none).
TEST(TrialLogger, EveryModelKindLogsItsAccuracy) {
  const std::vector<std::vector<std::string>> agents{
      {"--agent", "rmax"},
      {"--agent", "modelbased", "--model", "tabular", "--planner", "vi"},
      {"--agent", "modelbased", "--model", "m5tree", "--rollouts", "10"},
      {"--agent", "texplore", "--rollouts", "10"}};
  for (const auto& args : agents) {
    const std::string dir = tempDir();
    rl_env::LightWorld env(3, true);
    auto agent = agentOf(args, env.describe(), 5);
    rl_experiment::TrialLimits limits;
    limits.exploreSteps = 60;
    limits.checkpointEvery = 30;
    rl_experiment::TrialInfo info{0, args[1], args[1], "lightworld", 5, 3, 9};
    rl_experiment::TrialLogger logger(dir, info, rl_experiment::EvalSettings{200, {}}, false,
                                      nullptr);
    const auto summary = rl_experiment::TrialRunner(limits).run(env, *agent, &logger);
    logger.finish(summary, 1.0, 1024);
    const auto acc = rowsOf(dir + "/accuracy-000.csv");
    const std::string what = args[1] + (args.size() > 3 ? " " + args[3] : "");
    ASSERT_EQ(acc.size(), 4u) << what;  // header + steps 0, 30, 60
    for (std::size_t i = 1; i < acc.size(); ++i) {
      const double vd = std::stod(acc[i][3]);
      EXPECT_GE(vd, 0.0) << what;
      EXPECT_LE(vd, 1.0) << what;
    }
    // Measured on the model as it learns, not on a fixed one.
    EXPECT_NE(acc[1][3], acc[3][3]) << what;
  }
}
