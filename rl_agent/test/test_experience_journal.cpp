// The experience journal: the original's record layout behind a header, a record cut by a
// kill, and a model rebuilt from a journal that predicts as the one that learned online.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "corridor.h"
#include "rl_agent/agent/model_based_agent.h"
#include "rl_agent/journal/experience_journal.h"
#include "rl_agent/journal/journaling_agent.h"

using namespace rl_agent;
using rl_common::Experience;

namespace {

std::string tempPath(const std::string& name) {
  return "/tmp/rl_journal_test_" + std::to_string(::getpid()) + "_" + name;
}

std::string bytesOf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void expectSame(const Experience& a, const Experience& b) {
  EXPECT_EQ(a.s, b.s);
  EXPECT_EQ(a.action, b.action);
  EXPECT_EQ(a.reward, b.reward);
  EXPECT_EQ(a.next, b.next);
  EXPECT_EQ(a.terminal, b.terminal);
}

const std::vector<Experience> kThree = {{{1.0f, 2.0f}, 0, 0.5f, {1.0f, 3.0f}, false},
                                        {{1.0f, 3.0f}, 2, -1.0f, {0.0f, 3.0f}, false},
                                        {{0.0f, 3.0f}, 1, 10.0f, {0.0f, 3.0f}, true}};
constexpr std::size_t kRecord = 2 * 2 * sizeof(float) + 4 + 4 + 1;  // 2 features

}  // namespace

TEST(ExperienceJournal, RecordsInTheOriginalLayoutBehindAHeader) {
  const std::string path = tempPath("layout");
  std::remove(path.c_str());
  {
    ExperienceJournalWriter w(path, 2, {{"version", "test"}, {"seed", "7"}, {"config", "a=1\nb"}});
    for (const auto& e : kThree) w.append(e);
    EXPECT_EQ(w.records(), 3);
    EXPECT_THROW(w.append({{1.0f}, 0, 0.0f, {1.0f}, false}), std::invalid_argument);
  }
  const std::string bytes = bytesOf(path);
  const std::string head = "RL_EXPERIENCE_JOURNAL 1\nversion test\nseed 7\nconfig a=1 b\nend\n";
  ASSERT_EQ(bytes.substr(0, head.size()), head);
  ASSERT_EQ(bytes.size(), head.size() + 4 + 3 * kRecord);
  // After the header: int nfeats, then float s[n], float next[n], int act, float reward,
  // bool terminal per record.
  std::int32_t n = 0;
  std::memcpy(&n, bytes.data() + head.size(), 4);
  EXPECT_EQ(n, 2);
  const char* third = bytes.data() + head.size() + 4 + 2 * kRecord;
  float next1 = 0.0f, reward = 0.0f;
  std::int32_t action = 0;
  std::memcpy(&next1, third + 3 * sizeof(float), sizeof(float));
  std::memcpy(&action, third + 4 * sizeof(float), 4);
  std::memcpy(&reward, third + 4 * sizeof(float) + 4, 4);
  EXPECT_EQ(next1, 3.0f);
  EXPECT_EQ(action, 1);
  EXPECT_EQ(reward, 10.0f);
  EXPECT_EQ(third[kRecord - 1], 1);
  const JournalContents c = readExperienceJournal(path);
  EXPECT_EQ(c.numFeatures, 2);
  EXPECT_EQ(c.droppedBytes, 0u);
  ASSERT_EQ(c.header.size(), 3u);
  EXPECT_EQ(c.header[1], (std::pair<std::string, std::string>{"seed", "7"}));
  ASSERT_EQ(c.records.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) expectSame(c.records[i], kThree[i]);
  std::remove(path.c_str());
}

TEST(ExperienceJournal, ARecordCutByAKillIsDroppedAndTheJournalGoesOn) {
  const std::string path = tempPath("cut");
  std::remove(path.c_str());
  {
    ExperienceJournalWriter w(path, 2, {{"seed", "1"}});
    for (const auto& e : kThree) w.append(e);
  }
  const auto size = bytesOf(path).size();
  ASSERT_EQ(::truncate(path.c_str(), static_cast<off_t>(size - 5)), 0);  // mid-record
  JournalContents c = readExperienceJournal(path);
  ASSERT_EQ(c.records.size(), 2u);
  EXPECT_EQ(c.droppedBytes, kRecord - 5);
  expectSame(c.records[1], kThree[1]);
  {
    ExperienceJournalWriter w(path, 2, {{"seed", "ignored: the file has its header"}});
    EXPECT_EQ(w.records(), 2);
    w.append(kThree[0]);
  }
  c = readExperienceJournal(path);
  EXPECT_EQ(c.droppedBytes, 0u);
  ASSERT_EQ(c.records.size(), 3u);
  expectSame(c.records[2], kThree[0]);
  EXPECT_EQ(c.header, (JournalHeader{{"seed", "1"}}));
  std::remove(path.c_str());
}

TEST(ExperienceJournal, WhatIsNotAJournalOfThisTaskIsNeverOverwritten) {
  const std::string path = tempPath("other");
  EXPECT_THROW(readExperienceJournal(path + ".missing"), std::runtime_error);
  {
    std::ofstream out(path, std::ios::binary);
    out << "results,1,2,3\n";
  }
  try {
    readExperienceJournal(path);
    ADD_FAILURE() << "read a CSV file as a journal";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not an experience journal"), std::string::npos);
  }
  EXPECT_THROW(ExperienceJournalWriter(path, 2, {}), std::runtime_error);
  EXPECT_EQ(bytesOf(path), "results,1,2,3\n");
  std::remove(path.c_str());
  { ExperienceJournalWriter w(path, 2, {}); }
  try {
    ExperienceJournalWriter(path, 3, {});
    ADD_FAILURE() << "appended 3-feature records to a 2-feature journal";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("2-feature"), std::string::npos) << e.what();
  }
  std::remove(path.c_str());
}

TEST(ExperienceJournal, AModelRebuiltFromTheJournalPredictsAsTheOneThatLearnedOnline) {
  // TEXPLORE-VANIR on the corridor, journaling every step; then a new agent of the same
  // options and seed rebuilt from the journal (what --resume-journal does after a kill).
  const std::string path = tempPath("resume");
  std::remove(path.c_str());
  auto options = test_corridor::parseOptions(
      "texplore", {"--rollouts", "10", "--explore", "variancenovelty", "--v", "1", "--n", "3"});
  options.seed = 11;
  auto online = std::make_unique<ModelBasedAgent>(options, test_corridor::corridorTask());
  ModelBasedAgent* model = online.get();
  JournalingAgent agent(std::move(online),
                        std::make_shared<ExperienceJournalWriter>(path, 1, JournalHeader{}));
  long steps = 0;
  for (int episode = 0; episode < 4; ++episode) {
    int x = 0;
    int a = agent.firstAction({float(x)});
    for (int n = 0; n < 40; ++n, ++steps) {
      x = test_corridor::step(x, a);
      if (x == 7) {
        agent.lastAction(1.0f);
        ++steps;
        break;
      }
      a = agent.nextAction(0.0f, {float(x)});
    }
  }
  const JournalContents journal = readExperienceJournal(path);
  ASSERT_EQ(static_cast<long>(journal.records.size()), steps);
  EXPECT_GE(std::count_if(journal.records.begin(), journal.records.end(),
                          [](const Experience& e) { return e.terminal; }),
            1);
  ModelBasedAgent resumed(options, test_corridor::corridorTask());
  resumed.seedExperiences(journal.records);
  const auto before = ModelBasedAgent(options, test_corridor::corridorTask()).learnedModelView();
  const auto a = model->learnedModelView();
  const auto b = resumed.learnedModelView();
  int differsFromEmpty = 0;
  for (int x = 0; x < 8; ++x) {
    for (int act = 0; act < 3; ++act) {
      const auto pa = a->query({float(x)}, act);
      const auto pb = b->query({float(x)}, act);
      EXPECT_EQ(pa.reward, pb.reward) << x << " " << act;
      EXPECT_EQ(pa.termProb, pb.termProb) << x << " " << act;
      EXPECT_EQ(pa.factored, pb.factored) << x << " " << act;
      const auto p0 = before->query({float(x)}, act);
      differsFromEmpty += p0.factored != pa.factored || p0.reward != pa.reward;
    }
  }
  EXPECT_GT(differsFromEmpty, 0);  // the comparison is of learned models, not of empty ones
  std::remove(path.c_str());
}
