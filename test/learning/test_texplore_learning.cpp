// Seeded learning tests of TEXPLORE on the suite's environments, with honest thresholds: the
// agent really learns (an untrained agent fails them). Synchronous planning (--rollouts) so the
// same seed gives the same run.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "rl_agent/agent/agent_options.h"
#include "rl_agent/agent/agent_registry.h"
#include "rl_env/env/environment_registry.h"

namespace {

struct Episode {
  int steps = 0;
  bool terminal = false;
};

std::unique_ptr<rl_common::Agent> makeTexplore(const rl_common::Environment& env,
                                               const std::vector<std::string>& extra) {
  rl_agent::AgentOptions o;
  rl_common::OptionParser p("test", "");
  rl_agent::addAgentOptions(p, &o);
  std::vector<std::string> args{"--agent", "texplore"};
  args.insert(args.end(), extra.begin(), extra.end());
  p.parse(args);
  rl_agent::applyAgentDefaults(p, &o);
  rl_agent::checkAgentOptions(p, o);
  o.seed = 5;
  return rl_agent::makeAgent(o, env.describe());
}

std::unique_ptr<rl_common::Agent> makeNamed(const rl_common::Environment& env,
                                            const std::vector<std::string>& args) {
  rl_agent::AgentOptions o;
  rl_common::OptionParser p("test", "");
  rl_agent::addAgentOptions(p, &o);
  p.parse(args);
  rl_agent::applyAgentDefaults(p, &o);
  rl_agent::checkAgentOptions(p, o);
  o.seed = 5;
  return rl_agent::makeAgent(o, env.describe());
}

std::vector<Episode> runEpisodes(const std::string& name, int episodes, int maxSteps,
                                 const std::vector<std::string>& agentArgs, bool texplore = true) {
  rl_env::EnvironmentOptions eo;
  eo.env = name;
  eo.seed = 3;
  auto env = rl_env::makeEnvironment(eo);
  auto agent = texplore ? makeTexplore(*env, agentArgs) : makeNamed(*env, agentArgs);
  agent->seedExperiences(env->seedExperiences());
  std::vector<Episode> out;
  for (int e = 0; e < episodes; ++e) {
    env->reset();
    Episode ep;
    float r = env->apply(agent->firstAction(env->sensation()));
    ep.steps = 1;
    while (!env->terminal() && ep.steps < maxSteps) {
      r = env->apply(agent->nextAction(r, env->sensation()));
      ++ep.steps;
    }
    ep.terminal = env->terminal();
    if (ep.terminal) {
      agent->lastAction(r);
    } else {
      agent->nextAction(r, env->sensation());
    }
    out.push_back(ep);
  }
  return out;
}

}  // namespace

TEST(TexploreLearning, FindsAndThenFollowsTheWayToTheFourRoomsGoal) {
  // Greedy TEXPLORE, no seeds: it stumbles on the goal, then its model takes it back there.
  const auto eps = runEpisodes("fourrooms", 8, 300, {"--rollouts", "50"});
  int fast = 0;
  for (std::size_t e = 5; e < eps.size(); ++e) fast += eps[e].terminal && eps[e].steps <= 60;
  // Random walks need hundreds of steps from the start room to the goal (the first episodes
  // time out at 300); the last three are all short.
  EXPECT_EQ(fast, 3) << "episode lengths: " << eps[5].steps << " " << eps[6].steps << " "
                     << eps[7].steps;
}

TEST(TexploreLearning, LearnsTwoRoomsFromItsSeeds) {
  const auto eps = runEpisodes("tworooms", 6, 200, {"--rollouts", "50"});
  for (const auto& ep : eps) EXPECT_TRUE(ep.terminal);
  EXPECT_LE(eps.back().steps, 25);  // the optimal path from the far corner is 14 steps
}

TEST(TexploreLearning, VanirLeavesTheFirstLightWorldRoom) {
  // TEXPLORE-VANIR finds the key, unlocks the door and walks out (+10) from curiosity alone:
  // nothing rewards it before the first exit. Greedy TEXPLORE and random walks stay inside far
  // longer (random actions rarely complete PICKUP, PRESS and the exit in order).
  rl_env::EnvironmentOptions eo;
  eo.env = "lightworld";
  eo.seed = 3;
  auto env = rl_env::makeEnvironment(eo);
  auto agent = makeTexplore(*env, {"--v", "1", "--n", "3", "--rollouts", "300"});
  float r = env->apply(agent->firstAction(env->sensation()));
  int steps = 1;
  const int kBound = 1000;
  while (r <= 0.0f && steps < kBound) {
    r = env->apply(agent->nextAction(r, env->sensation()));
    ++steps;
  }
  EXPECT_FLOAT_EQ(r, 10.0f) << "still in the first room after " << steps << " steps";
  EXPECT_EQ(env->sensation()[4], 1.0f);  // room id
}

// The original's other agents on the suite's environments (issue 7): mean length of the last
// 10 episodes against the first 10.
double meanSteps(const std::vector<Episode>& eps, std::size_t from, std::size_t to) {
  double sum = 0;
  for (std::size_t e = from; e < to; ++e) sum += eps[e].steps;
  return sum / static_cast<double>(to - from);
}

TEST(OtherAgentsLearning, QLearningSarsaAndDynaLearnTwoRooms) {
  for (const std::string agent : {"qlearner", "sarsa", "dyna"}) {
    std::vector<std::string> args{"--agent", agent};
    if (agent == "dyna") args.insert(args.end(), {"--k", "20"});
    const auto eps = runEpisodes("tworooms", 150, 500, args, false);
    const double late = meanSteps(eps, 140, 150);
    EXPECT_LT(late, 30.0) << agent << " early " << meanSteps(eps, 0, 10);  // optimum: 6-14
    EXPECT_LT(late, 0.5 * meanSteps(eps, 0, 10)) << agent;
  }
}

TEST(OtherAgentsLearning, RmaxLearnsFourRooms) {
  const auto eps = runEpisodes("fourrooms", 40, 1000, {"--agent", "rmax"}, false);
  const double late = meanSteps(eps, 30, 40);
  EXPECT_LT(late, 40.0);
  for (std::size_t e = 30; e < 40; ++e) EXPECT_TRUE(eps[e].terminal);
}
