// A SIGKILLed agent node resumes from its experience journal (agent_journal_resume.test).
#include <gtest/gtest.h>
#include <rl_msgs/RLEnvDescription.h>
#include <rl_msgs/RLStateReward.h>
#include <ros/ros.h>
#include <ros/topic.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "child_process.h"
#include "rl_agent/agent/agent_options.h"
#include "rl_agent/agent/agent_registry.h"
#include "rl_agent/agent/model_based_agent.h"
#include "rl_agent/journal/experience_journal.h"
#include "rl_agent/model/model_predictions.h"
#include "rl_agent/ros/agent_node.h"
#include "rl_common/option_parser.h"

namespace {

/// Records in the journal now (0 while it does not exist yet).
std::size_t records(const std::string& path) {
  try {
    return rl_agent::readExperienceJournal(path).records.size();
  } catch (const std::runtime_error&) {
    return 0;
  }
}

bool waitFor(const std::function<bool()>& done, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return done();
}

/// The agent node (AGENT_BIN) with `args`, named agent.
pid_t startAgent(const std::vector<std::string>& args, const std::string& log) {
  std::vector<std::string> all{AGENT_BIN, "__name:=agent"};
  all.insert(all.end(), args.begin(), args.end());
  return test_nodes::start(all, log);
}

/// The agent options the node parses from `args` (its --seed included).
rl_agent::AgentOptions nodeOptions(const std::vector<std::string>& args) {
  rl_agent::AgentOptions o;
  rl_common::OptionParser p("test", "");
  rl_agent::addAgentOptions(p, &o);
  p.value("seed", &o.seed, "seed");
  p.parse(args);
  rl_agent::applyAgentDefaults(p, &o);
  rl_agent::checkAgentOptions(p, o);
  return o;
}

/// The env node's description, as the agent node converts it.
rl_common::EnvironmentDescription envDescription() {
  ros::NodeHandle nh;
  const auto msg = ros::topic::waitForMessage<rl_msgs::RLEnvDescription>(
      "rl_env/rl_env_description", nh, ros::Duration(30.0));
  if (!msg) throw std::runtime_error("no description from the env node in 30 s");
  return rl_agent::fromMessage(*msg);
}

std::string predictionsText(const rl_agent::ModelBasedAgent& agent,
                            const std::set<rl_common::State>& states, int numActions) {
  std::ostringstream out;
  rl_agent::writeModelPredictions(*agent.learnedModelView(), {states.begin(), states.end()},
                                  numActions, out);
  return out.str();
}

}  // namespace

TEST(AgentNode, ResumesFromItsJournalAfterAKill) {
  const std::string dir = "/tmp/rl_journal_rostest_" + std::to_string(::getpid());
  ASSERT_EQ(std::system(("rm -rf " + dir + " && mkdir -p " + dir).c_str()), 0);
  const std::string journal = dir + "/agent.journal";
  const std::vector<std::string> agent{"--agent", "texplore", "--v",        "1",
                                       "--n",     "3",        "--rollouts", "20",
                                       "--seed",  "5",        "--journal",  journal};
  const pid_t first = startAgent(agent, dir + "/first.log");
  ASSERT_GT(first, 0);
  ASSERT_TRUE(waitFor([&] { return records(journal) >= 150; }, 60.0))
      << "the agent journaled " << records(journal) << " experiences in 60 s\n"
      << test_nodes::fileText(dir + "/first.log");
  ASSERT_EQ(::kill(first, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(first, &status, 0), first);
  ASSERT_TRUE(WIFSIGNALED(status));
  // The env may be one step past the journal: the agent journals an experience when the next
  // state arrives, so a kill after it sent an action but before it heard the answer leaves
  // that last step unjournaled (lost, as it should be). The state the restarted agent must go
  // on from is the env's latched one once any action still in flight has landed.
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  const rl_msgs::RLStateReward::ConstPtr heldByEnv = [] {
    ros::NodeHandle nh;
    return ros::topic::waitForMessage<rl_msgs::RLStateReward>("rl_env/rl_state_reward", nh,
                                                              ros::Duration(30.0));
  }();
  ASSERT_NE(heldByEnv, nullptr) << "no latched state from the env node in 30 s";

  const rl_agent::JournalContents killed = rl_agent::readExperienceJournal(journal);
  const std::size_t k = killed.records.size();
  ASSERT_GE(k, 150u);
  EXPECT_EQ(killed.numFeatures, 17);
  bool seeded = false;
  for (const auto& [key, value] : killed.header) seeded |= key == "seed" && value == "5";
  EXPECT_TRUE(seeded) << "the header names the agent's seed";
  // One unbroken walk through LightWorld (never terminal): each step starts where the last
  // ended, up to the kill.
  for (std::size_t i = 0; i + 1 < k; ++i) {
    ASSERT_EQ(killed.records[i].next, killed.records[i + 1].s) << "record " << i;
    ASSERT_FALSE(killed.records[i].terminal);
  }

  // The model rebuilt from the journal predicts exactly as one that learned the same
  // experiences without the kill. The reference is the killed run replayed in this process:
  // the same options, seed and description, acting on the journal's states; that it chose
  // every recorded action shows it is the same run. A probe node rebuilt from the journal
  // hears no states (so learns nothing more) and writes its model when stopped.
  const rl_common::EnvironmentDescription description = envDescription();
  const std::vector<std::string> optionArgs(agent.begin(), agent.end() - 2);  // not --journal
  auto replayed = rl_agent::makeAgent(nodeOptions(optionArgs), description);
  ASSERT_EQ(replayed->firstAction(killed.records[0].s), killed.records[0].action);
  for (std::size_t i = 1; i < k; ++i) {
    ASSERT_EQ(replayed->nextAction(killed.records[i - 1].reward, killed.records[i].s),
              killed.records[i].action)
        << "step " << i << ": the replay is not the killed run";
  }
  replayed->nextAction(killed.records[k - 1].reward, killed.records[k - 1].next);
  std::set<rl_common::State> states;
  for (const auto& e : killed.records) {
    states.insert(e.s);
    states.insert(e.next);
  }
  const auto* online = dynamic_cast<const rl_agent::ModelBasedAgent*>(replayed.get());
  ASSERT_NE(online, nullptr);
  const std::string expected = predictionsText(*online, states, description.numActions);
  const auto empty = rl_agent::makeAgent(nodeOptions(optionArgs), description);
  ASSERT_NE(predictionsText(dynamic_cast<const rl_agent::ModelBasedAgent&>(*empty), states,
                            description.numActions),
            expected)
      << "the comparison is of learned models, not of empty ones";

  const std::string predictions = dir + "/resumed-predictions.csv";
  std::vector<std::string> probeArgs = optionArgs;
  probeArgs.insert(probeArgs.end(),
                   {"--resume-journal", journal, "--model-predictions", predictions,
                    "rl_env/rl_state_reward:=rl_env/probe_no_states"});
  const pid_t probe = startAgent(probeArgs, dir + "/probe.log");
  ASSERT_GT(probe, 0);
  const std::string rebuilt = "rebuilt the model from the " + std::to_string(k) + " experiences";
  const bool built = waitFor(
      [&] { return test_nodes::fileText(dir + "/probe.log").find(rebuilt) != std::string::npos; },
      30.0);
  ::kill(probe, SIGINT);
  ASSERT_EQ(::waitpid(probe, &status, 0), probe);
  const std::string probeLog = test_nodes::fileText(dir + "/probe.log");
  ASSERT_TRUE(built) << probeLog;
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << probeLog;
  const std::string written = test_nodes::fileText(predictions);
  EXPECT_EQ(std::count(written.begin(), written.end(), '\n'),
            1 + static_cast<long>(states.size()) * description.numActions);
  EXPECT_TRUE(written == expected)
      << "the resumed node's model differs from the one that learned without the kill\n"
      << probeLog;

  std::vector<std::string> resume = agent;
  resume.insert(resume.end(), {"--resume-journal", journal});
  const pid_t second = startAgent(resume, dir + "/second.log");
  ASSERT_GT(second, 0);
  const bool stepping = waitFor([&] { return records(journal) >= k + 100; }, 60.0);
  ::kill(second, SIGINT);
  ::waitpid(second, &status, 0);
  const std::string log = test_nodes::fileText(dir + "/second.log");
  ASSERT_TRUE(stepping) << "after the restart the journal grew to " << records(journal) << "\n"
                        << log;
  EXPECT_NE(log.find("rebuilt the model from the " + std::to_string(k) + " experiences"),
            std::string::npos)
      << log;
  const rl_agent::JournalContents resumed = rl_agent::readExperienceJournal(journal);
  ASSERT_GE(resumed.records.size(), k + 100);
  // The restarted pair goes on from the state the env held when the agent died: the journal's
  // last state, or the one after it when the last action was sent but its answer not heard.
  EXPECT_EQ(resumed.records[k].s,
            rl_common::State(heldByEnv->state.begin(), heldByEnv->state.end()));
  for (std::size_t i = 0; i < k; ++i) {
    ASSERT_EQ(resumed.records[i].s, killed.records[i].s) << "the kept records were rewritten";
  }
  std::system(("rm -rf " + dir).c_str());
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_journal_resume");
  return RUN_ALL_TESTS();
}
