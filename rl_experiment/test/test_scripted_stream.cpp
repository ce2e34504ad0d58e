#include "rl_experiment/eval/scripted_stream.h"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

#include "rl_env/env/light_world.h"

namespace {

using rl_env::LightWorld;
using rl_experiment::scriptedLightWorldStream;
using rl_experiment::ScriptedStreamConfig;

ScriptedStreamConfig config(const std::string& stream, long steps, long period = 100) {
  ScriptedStreamConfig c;
  c.stream = stream;
  c.steps = steps;
  c.period = period;
  return c;
}

bool keyOnFloor(const rl_common::State& s) {
  return s[LightWorld::kKeyN] + s[LightWorld::kKeyE] + s[LightWorld::kKeyW] + s[LightWorld::kKeyS] >
         0.0f;
}

TEST(ScriptedStream, RejectsUnknownStreamsAndBadSizes) {
  try {
    scriptedLightWorldStream(config("spiral", 10), 1);
    FAIL() << "an unknown stream was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("walk, iid, teleport, keep-key"), std::string::npos);
  }
  EXPECT_THROW(scriptedLightWorldStream(config("walk", 0), 1), std::invalid_argument);
  EXPECT_THROW(scriptedLightWorldStream(config("teleport", 10, 0), 1), std::invalid_argument);
}

TEST(ScriptedStream, AWalkIsOneContinuousTrajectoryFromRoomZero) {
  const auto d = scriptedLightWorldStream(config("walk", 500), 3);
  ASSERT_EQ(d.size(), 500u);
  EXPECT_EQ(d.front().s[LightWorld::kRoomId], 0.0f);
  for (std::size_t i = 1; i < d.size(); ++i) ASSERT_EQ(d[i].s, d[i - 1].next) << "step " << i;
  const auto again = scriptedLightWorldStream(config("walk", 500), 3);
  for (std::size_t i = 0; i < d.size(); ++i) {
    ASSERT_EQ(again[i].s, d[i].s) << "same seed, same stream";
    ASSERT_EQ(again[i].action, d[i].action);
  }
}

TEST(ScriptedStream, TeleportRestartsOnlyAtItsPeriodAndIidCoversTheRooms) {
  const auto t = scriptedLightWorldStream(config("teleport", 400, 50), 4);
  int breaks = 0;
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (t[i].s != t[i - 1].next) {
      ++breaks;
      EXPECT_EQ(i % 50, 0u) << "a restart off the period at step " << i;
    }
  }
  EXPECT_GE(breaks, 5);
  std::set<float> rooms;
  int holding = 0;
  for (const auto& e : scriptedLightWorldStream(config("iid", 400), 4)) {
    rooms.insert(e.s[LightWorld::kRoomId]);
    holding += e.s[LightWorld::kHaveKey] > 0.5f ? 1 : 0;
  }
  EXPECT_EQ(rooms.size(), 4u);
  EXPECT_GT(holding, 0);
  EXPECT_LT(holding, 400);
}

TEST(ScriptedStream, KeepKeyLeavesTheKeyOnTheFloorForItsPeriod) {
  // The plain walk of the same seed picks the key up within 600 steps; keep-key does not.
  bool walkPicked = false;
  for (std::uint64_t seed = 1; seed <= 3 && !walkPicked; ++seed) {
    for (const auto& e : scriptedLightWorldStream(config("walk", 600), seed)) {
      walkPicked = walkPicked || !keyOnFloor(e.next);
    }
  }
  EXPECT_TRUE(walkPicked);
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const auto d = scriptedLightWorldStream(config("keep-key", 800, 600), seed);
    for (std::size_t i = 0; i < 600; ++i) ASSERT_TRUE(keyOnFloor(d[i].next)) << "step " << i;
  }
}

double distanceAfter(const std::string& stream, std::uint64_t seed) {
  return rl_experiment::measureScriptedStream(config(stream, 400, 400), seed, seed + 100,
                                              seed + 200, 1000)
      .distance;
}

TEST(ScriptedStream, TheMeasuresOwnDistributionTeachesTheForestMoreThanAWalk) {
  // docs/science/lightworld-curiosity.md §2.1: i.i.d. data bounds what exploration can buy.
  double walk = 0.0, iid = 0.0;
  for (std::uint64_t seed = 11; seed <= 13; ++seed) {
    walk += distanceAfter("walk", seed) / 3.0;
    iid += distanceAfter("iid", seed) / 3.0;
  }
  EXPECT_LT(iid, walk - 0.05) << "iid " << iid << " walk " << walk;
}

}  // namespace
