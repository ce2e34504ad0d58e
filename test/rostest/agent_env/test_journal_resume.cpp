// A SIGKILLed agent node resumes from its experience journal (agent_journal_resume.test).
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "child_process.h"
#include "rl_agent/journal/experience_journal.h"

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
  // The restarted pair goes on from the state the env held when the agent died.
  EXPECT_EQ(resumed.records[k].s, killed.records[k - 1].next);
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
