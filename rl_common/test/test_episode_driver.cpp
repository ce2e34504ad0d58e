// EpisodeDriver: which Agent call each protocol event makes, and the episode's bookkeeping.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "rl_common/episode_driver.h"

namespace {

using rl_common::EpisodeDriver;
using rl_common::State;

// Records every call as text; returns the call's number as the action.
class RecordingAgent : public rl_common::Agent {
 public:
  int firstAction(const State& s) override { return note("first " + str(s)); }
  int nextAction(float r, const State& s) override {
    return note("next " + std::to_string(int(r)) + " " + str(s));
  }
  void lastAction(float r) override { note("last " + std::to_string(int(r))); }
  std::vector<std::string> calls;

 private:
  static std::string str(const State& s) { return std::to_string(int(s.at(0))); }
  int note(const std::string& c) {
    calls.push_back(c);
    return static_cast<int>(calls.size());
  }
};

TEST(EpisodeDriver, TerminalEpisodesCallLastActionAndStartAgain) {
  RecordingAgent agent;
  EpisodeDriver d(agent);
  EXPECT_TRUE(d.starting());
  EXPECT_EQ(d.act({0}, 99.0f), 1);  // the start's reward is not given to the agent
  EXPECT_FALSE(d.starting());
  EXPECT_EQ(d.act({1}, 2.0f), 2);
  EXPECT_EQ(d.act({2}, 3.0f), 3);
  const EpisodeDriver::Episode e = d.end(4.0f, true, {3});
  EXPECT_EQ(e.index, 0);
  EXPECT_EQ(e.actions, 3);
  EXPECT_FLOAT_EQ(e.reward, 9.0f);
  EXPECT_TRUE(e.terminal);
  EXPECT_TRUE(d.starting());
  EXPECT_EQ(d.act({5}, 7.0f), 5);
  EXPECT_EQ(d.episode().index, 1);
  EXPECT_EQ(d.episode().actions, 1);
  EXPECT_FLOAT_EQ(d.episode().reward, 0.0f);
  EXPECT_EQ(agent.calls,
            (std::vector<std::string>{"first 0", "next 2 1", "next 3 2", "last 4", "first 5"}));
  EXPECT_EQ(d.episodesEnded(), 1);
}

TEST(EpisodeDriver, ACutOffEpisodeGivesTheLastRewardThroughADiscardedNextAction) {
  RecordingAgent agent;
  EpisodeDriver d(agent);
  d.act({0}, 0.0f);
  const EpisodeDriver::Episode e = d.end(-1.0f, false, {4});
  EXPECT_FALSE(e.terminal);
  EXPECT_EQ(e.actions, 1);
  EXPECT_FLOAT_EQ(e.reward, -1.0f);
  d.act({0}, 0.0f);
  EXPECT_EQ(agent.calls, (std::vector<std::string>{"first 0", "next -1 4", "first 0"}));
}

TEST(EpisodeDriver, EndingWithoutAnEpisodeIsALogicError) {
  RecordingAgent agent;
  EpisodeDriver d(agent);
  EXPECT_THROW(d.end(0.0f, true, {0}), std::logic_error);
  d.act({0}, 0.0f);
  d.end(0.0f, true, {0});
  EXPECT_THROW(d.end(0.0f, true, {0}), std::logic_error);  // twice
  EXPECT_EQ(agent.calls.size(), 2u);
}

}  // namespace
