// LightWorld against hand-computed transitions (shared/spec/ORIGINAL.md §4): room layout,
// walls, lock and door cells in the walls, key pickup, pressing the lock, leaving each room,
// light sensors; then the exact model: distributions, sampling, reachable states.
#include "rl_env/env/light_world.h"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "light_world_states.h"
#include "true_model_checks.h"

namespace {

using rl_common::Outcome;
using rl_common::State;
using rl_env::LightWorld;
using Cell = LightWorld::Cell;
using FullState = LightWorld::FullState;

using rl_env::testing::lightWorldState;

// The full state after applying `action` to `from` in a deterministic LightWorld.
FullState after(const FullState& from, int action, float* reward = nullptr) {
  LightWorld env(1, false);
  env.setFullState(from);
  const float r = env.apply(action);
  if (reward != nullptr) *reward = r;
  return env.fullState();
}

// Position and room only.
void expectAt(const FullState& s, int room, int ns, int ew) {
  EXPECT_EQ(s.room, room);
  EXPECT_EQ(s.ns, ns);
  EXPECT_EQ(s.ew, ew);
}

TEST(LightWorld, DescriptionMatchesTheOriginalWithRoomIdUpTo3) {
  LightWorld env(1, true);
  const rl_common::EnvironmentDescription d = env.describe();
  EXPECT_EQ(d.numActions, 6);
  ASSERT_EQ(d.numFeatures(), 17u);
  const std::vector<float> max = {8, 8, 1, 1, 3, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10, 10};
  EXPECT_EQ(d.maxFeatures, max);
  EXPECT_EQ(d.minFeatures, std::vector<float>(17, 0.0f));
  EXPECT_EQ(d.minReward, 0.0f);
  EXPECT_EQ(d.maxReward, 10.0f);
  EXPECT_FALSE(d.episodic);
  EXPECT_TRUE(d.stochastic);
  EXPECT_EQ(d.title, "Environment: LightWorld\n");
  EXPECT_TRUE(env.seedExperiences().empty());
}

TEST(LightWorld, RoomTableAndEntryCells) {
  EXPECT_EQ(LightWorld::room(0).height, 8);
  EXPECT_EQ(LightWorld::room(0).width, 7);
  EXPECT_EQ(LightWorld::room(0).lock, (Cell{2, 6}));
  EXPECT_EQ(LightWorld::room(0).door, (Cell{5, 6}));
  EXPECT_EQ(LightWorld::room(1).lock, (Cell{0, 3}));
  EXPECT_EQ(LightWorld::room(1).door, (Cell{0, 1}));
  EXPECT_FALSE(LightWorld::room(2).hasKey);
  EXPECT_EQ(LightWorld::room(2).lock, (Cell{3, 4}));
  EXPECT_EQ(LightWorld::room(2).door, (Cell{3, 0}));
  EXPECT_EQ(LightWorld::room(3).lock, (Cell{0, 4}));
  EXPECT_EQ(LightWorld::room(3).door, (Cell{5, 2}));
  // Entry cells: the ns = 3 hack into room 1, then the kept coordinate along the door's axis.
  EXPECT_EQ(LightWorld::entryCell(1), (Cell{3, 0}));
  EXPECT_EQ(LightWorld::entryCell(2), (Cell{7, 1}));
  EXPECT_EQ(LightWorld::entryCell(3), (Cell{3, 6}));
  EXPECT_EQ(LightWorld::entryCell(0), (Cell{0, 2}));
  EXPECT_THROW(LightWorld::room(4), std::out_of_range);
}

TEST(LightWorld, SensorsComputedByHand) {
  // Room 0, agent (3,2), key (5,4) on the floor, lock (2,6), door (5,6) closed.
  const State s = LightWorld::observe(lightWorldState(0, 3, 2, false, false, {5, 4}));
  // ns, ew, have_key, door_open, room | key N E W S | lock N E W S | door N E W S (off: closed)
  const State expected = {3, 2, 0, 0, 0, 8, 8, 0, 0, 0, 6, 0, 9, 0, 0, 0, 0};
  EXPECT_EQ(s, expected);

  // Key held and door open: key lights off, door lights on. Door (5,6) from (3,2).
  const State open = LightWorld::observe(lightWorldState(0, 3, 2, true, true));
  const State expectedOpen = {3, 2, 1, 1, 0, 0, 0, 0, 0, 0, 6, 0, 9, 8, 6, 0, 0};
  EXPECT_EQ(open, expectedOpen);

  // An object on the agent's own cell lights all four of its sensors at 10.
  const State onKey = LightWorld::observe(lightWorldState(3, 2, 3, false, false, {2, 3}));
  EXPECT_EQ((State{onKey[5], onKey[6], onKey[7], onKey[8]}), (State{10, 10, 10, 10}));
  // Room 3, lock (0,4) seen from (2,3): S = 10 - 2, E = 10 - 1.
  EXPECT_EQ((State{onKey[9], onKey[10], onKey[11], onKey[12]}), (State{0, 9, 0, 8}));
}

TEST(LightWorld, WallsBlockMovesWithoutReward) {
  float r = -1.0f;
  expectAt(after(lightWorldState(0, 1, 3, false, false, {4, 4}), LightWorld::kSouth, &r), 0, 1, 3);
  EXPECT_EQ(r, 0.0f);
  expectAt(after(lightWorldState(0, 6, 3, false, false, {4, 4}), LightWorld::kNorth), 0, 6, 3);
  expectAt(after(lightWorldState(0, 3, 1, false, false, {4, 4}), LightWorld::kWest), 0, 3, 1);
  expectAt(after(lightWorldState(0, 3, 5, false, false, {4, 4}), LightWorld::kEast), 0, 3, 5);
  // Interior moves: NORTH is ns + 1, EAST is ew + 1.
  expectAt(after(lightWorldState(0, 3, 3, false, false, {4, 4}), LightWorld::kNorth), 0, 4, 3);
  expectAt(after(lightWorldState(0, 3, 3, false, false, {4, 4}), LightWorld::kSouth), 0, 2, 3);
  expectAt(after(lightWorldState(0, 3, 3, false, false, {4, 4}), LightWorld::kEast), 0, 3, 4);
  expectAt(after(lightWorldState(0, 3, 3, false, false, {4, 4}), LightWorld::kWest), 0, 3, 2);
}

TEST(LightWorld, LockAndDoorCellsInTheWallCanBeEnteredButNotWalkedAlong) {
  const Cell key{4, 4};
  // Room 0: lock (2,6) and door (5,6) in the east wall.
  expectAt(after(lightWorldState(0, 2, 5, false, false, key), LightWorld::kEast), 0, 2, 6);
  expectAt(after(lightWorldState(0, 2, 6, false, false, key), LightWorld::kNorth), 0, 2, 6);
  expectAt(after(lightWorldState(0, 2, 6, false, false, key), LightWorld::kSouth), 0, 2, 6);
  expectAt(after(lightWorldState(0, 2, 6, false, false, key), LightWorld::kEast), 0, 2, 6);
  expectAt(after(lightWorldState(0, 2, 6, false, false, key), LightWorld::kWest), 0, 2, 5);
  expectAt(after(lightWorldState(0, 5, 5, false, false, key), LightWorld::kEast), 0, 5, 6);
  // A closed door does not let the agent out.
  float r = -1.0f;
  const FullState closed = after(lightWorldState(0, 5, 6, true, false), LightWorld::kEast, &r);
  expectAt(closed, 0, 5, 6);
  EXPECT_EQ(r, 0.0f);
  // Room 1: lock (0,3) in the south wall.
  expectAt(after(lightWorldState(1, 1, 3, false, false, {2, 2}), LightWorld::kSouth), 1, 0, 3);
  expectAt(after(lightWorldState(1, 0, 3, false, false, {2, 2}), LightWorld::kEast), 1, 0, 3);
  expectAt(after(lightWorldState(1, 0, 3, false, false, {2, 2}), LightWorld::kWest), 1, 0, 3);
  expectAt(after(lightWorldState(1, 0, 3, false, false, {2, 2}), LightWorld::kNorth), 1, 1, 3);
  // Room 3: door (5,2) in the north wall.
  expectAt(after(lightWorldState(3, 4, 2, true, false), LightWorld::kNorth), 3, 5, 2);
  // A wall cell that is neither lock nor door stays out of reach: room 3, (4,3) NORTH.
  expectAt(after(lightWorldState(3, 4, 3, true, false), LightWorld::kNorth), 3, 4, 3);
}

TEST(LightWorld, PickupOnlyOnTheKey) {
  const FullState onKey =
      after(lightWorldState(0, 3, 2, false, false, {3, 2}), LightWorld::kPickup);
  EXPECT_TRUE(onKey.haveKey);
  EXPECT_EQ(onKey.key, Cell{});
  const State s = LightWorld::observe(onKey);
  EXPECT_EQ(s[LightWorld::kHaveKey], 1.0f);
  EXPECT_EQ((State{s[5], s[6], s[7], s[8]}), (State{0, 0, 0, 0}));  // key lights off

  const FullState offKey =
      after(lightWorldState(0, 3, 3, false, false, {3, 2}), LightWorld::kPickup);
  EXPECT_FALSE(offKey.haveKey);
  EXPECT_EQ(offKey.key, (Cell{3, 2}));
}

TEST(LightWorld, PressOpensTheDoorOnlyWithTheKeyOnTheLock) {
  float r = -1.0f;
  const FullState pressed = after(lightWorldState(0, 2, 6, true, false), LightWorld::kPress, &r);
  EXPECT_TRUE(pressed.doorOpen);
  EXPECT_EQ(r, 0.0f);
  // Door lights on: door (5,6) seen from the lock (2,6): N = 10 - 3, E = W = 10, S = 0.
  const State s = LightWorld::observe(pressed);
  EXPECT_EQ((State{s[13], s[14], s[15], s[16]}), (State{7, 10, 10, 0}));

  EXPECT_FALSE(after(lightWorldState(0, 2, 6, false, false, {3, 3}), LightWorld::kPress)
                   .doorOpen);  // no key
  EXPECT_FALSE(
      after(lightWorldState(0, 2, 5, true, false), LightWorld::kPress).doorOpen);  // not on lock
  EXPECT_FALSE(
      after(lightWorldState(0, 5, 6, true, false), LightWorld::kPress).doorOpen);  // on the door
}

struct ExitCase {
  int room;
  Cell door;
  int exitAction;
  int nextRoom;
  Cell entry;
  bool keyGiven;     // the next room has no key: have_key is set on entry
  int inwardAction;  // the one move that leaves the entry cell
  Cell inward;
};

TEST(LightWorld, LeavingEachRoomEntersTheNextAtTheRightCell) {
  const std::vector<ExitCase> cases = {
      {0, {5, 6}, LightWorld::kEast, 1, {3, 0}, false, LightWorld::kEast, {3, 1}},
      {1, {0, 1}, LightWorld::kSouth, 2, {7, 1}, true, LightWorld::kSouth, {6, 1}},
      {2, {3, 0}, LightWorld::kWest, 3, {3, 6}, false, LightWorld::kWest, {3, 5}},
      {3, {5, 2}, LightWorld::kNorth, 0, {0, 2}, false, LightWorld::kNorth, {1, 2}},
  };
  for (const ExitCase& c : cases) {
    SCOPED_TRACE("room " + std::to_string(c.room));
    LightWorld env(7, false);
    env.setFullState(lightWorldState(c.room, c.door.ns, c.door.ew, true, true));
    // Any other move on the open door keeps the agent in the room.
    for (int a = 0; a < 4; ++a) {
      if (a == c.exitAction) continue;
      LightWorld other(7, false);
      other.setFullState(lightWorldState(c.room, c.door.ns, c.door.ew, true, true));
      EXPECT_EQ(other.apply(a), 0.0f);
      EXPECT_EQ(other.fullState().room, c.room);
    }
    EXPECT_EQ(env.apply(c.exitAction), 10.0f);
    const FullState s = env.fullState();
    expectAt(s, c.nextRoom, c.entry.ns, c.entry.ew);
    EXPECT_FALSE(s.doorOpen);
    EXPECT_EQ(s.haveKey, c.keyGiven);
    const LightWorld::Room& next = LightWorld::room(c.nextRoom);
    if (!c.keyGiven) {
      EXPECT_GE(s.key.ns, 1);
      EXPECT_LE(s.key.ns, next.height - 2);
      EXPECT_GE(s.key.ew, 1);
      EXPECT_LE(s.key.ew, next.width - 2);
    }
    EXPECT_EQ(env.sensation()[LightWorld::kRoomId], static_cast<float>(c.nextRoom));
    // From the entry cell (a wall cell) only the inward move works.
    for (int a = 0; a < 4; ++a) {
      LightWorld from(9, false);
      from.setFullState(s);
      from.apply(a);
      const Cell expected = a == c.inwardAction ? c.inward : c.entry;
      EXPECT_EQ((Cell{from.fullState().ns, from.fullState().ew}), expected) << "action " << a;
    }
  }
}

TEST(LightWorld, ClosedDoorWithKeyGivesNoExit) {
  float r = -1.0f;
  const FullState s = after(lightWorldState(1, 0, 1, true, false), LightWorld::kSouth, &r);
  expectAt(s, 1, 0, 1);
  EXPECT_EQ(r, 0.0f);
}

TEST(LightWorld, ObjectsOfTheCurrentRoom) {
  LightWorld env(3, true);
  env.setFullState(lightWorldState(3, 2, 3, false, false, {2, 3}));
  LightWorld::Objects o = env.objects();
  EXPECT_TRUE(o.keyPresent);
  EXPECT_EQ(o.key, (Cell{2, 3}));
  EXPECT_EQ(o.lock, (Cell{0, 4}));
  EXPECT_EQ(o.door, (Cell{5, 2}));
  env.setFullState(lightWorldState(3, 2, 3, true, false));
  o = env.objects();
  EXPECT_FALSE(o.keyPresent);
  EXPECT_EQ(o.key, Cell{});
}

TEST(LightWorld, ResetGivesTheStartStatesOfSection46) {
  LightWorld env(11, true);
  const std::vector<State> all = env.reachableStates();
  const std::set<State> reachable(all.begin(), all.end());
  std::set<std::pair<int, int>> cells;
  for (int i = 0; i < 500; ++i) {
    env.reset();
    const FullState s = env.fullState();
    EXPECT_EQ(s.room, 0);
    EXPECT_GE(s.ns, 1);
    EXPECT_LE(s.ns, 6);
    EXPECT_GE(s.ew, 1);
    EXPECT_LE(s.ew, 5);
    EXPECT_FALSE(s.haveKey);
    EXPECT_FALSE(s.doorOpen);
    EXPECT_GE(s.key.ns, 1);
    EXPECT_LE(s.key.ns, 6);
    EXPECT_GE(s.key.ew, 1);
    EXPECT_LE(s.key.ew, 5);
    EXPECT_TRUE(reachable.count(env.sensation()));
    cells.insert({s.ns, s.ew});
  }
  EXPECT_EQ(cells.size(), 30u);  // every interior cell of room 0 occurs as a start
}

TEST(LightWorld, SetStateValidatesAndRecomputesSensors) {
  LightWorld env(5, true);
  const State good = LightWorld::observe(lightWorldState(0, 3, 2, false, false, {5, 4}));
  env.setState(good);
  EXPECT_EQ(env.sensation(), good);
  EXPECT_EQ(env.fullState().key, (Cell{5, 4}));  // decoded from the key sensors

  auto rejects = [&](State s, const std::string& why) {
    EXPECT_THROW(env.setState(s), std::invalid_argument) << why;
  };
  rejects(State(16, 0.0f), "wrong size");
  State s = good;
  s[LightWorld::kRoomId] = 4;
  rejects(s, "room 4");
  rejects(LightWorld::observe(lightWorldState(0, 0, 3, false, false, {5, 4})), "a plain wall cell");
  s = good;
  s[LightWorld::kDoorOpen] = 1;
  rejects(s, "door open without the key (and door lights off)");
  s = good;
  s[LightWorld::kLockE] = 5;
  rejects(s, "lock sensor inconsistent with the position");
  s = good;
  for (int i = 5; i <= 8; ++i) s[static_cast<std::size_t>(i)] = 0;
  rejects(s, "key on the floor but key lights off");
  s = good;
  s[LightWorld::kNs] = 2.5f;
  rejects(s, "fractional row");
  rejects(LightWorld::observe(lightWorldState(2, 3, 2, false, false, {3, 2})),
          "room 2 without the key");
  rejects(LightWorld::observe(lightWorldState(1, 3, 0, true, true)), "door open on the entry cell");
  EXPECT_THROW(env.setFullState(lightWorldState(0, 3, 2, false, false, {0, 0})),
               std::invalid_argument);
  EXPECT_EQ(env.sensation(), good);  // failed calls leave the state alone
}

TEST(LightWorld, ApplyRejectsActionsOutOfRange) {
  LightWorld env(1, true);
  for (int a : {-1, 6, 100}) {
    try {
      env.apply(a);
      ADD_FAILURE() << "no exception for action " << a;
    } catch (const std::out_of_range& e) {
      EXPECT_EQ(std::string(e.what()).rfind("LightWorld::apply():", 0), 0u) << e.what();
    }
  }
  EXPECT_THROW(env.transitions(env.sensation(), 6), std::out_of_range);
}

// ---- the exact model ----

const Outcome* find(const std::vector<Outcome>& outcomes, const State& next) {
  for (const Outcome& o : outcomes) {
    if (o.next == next) return &o;
  }
  return nullptr;
}

TEST(LightWorldTrueModel, StochasticMoveHasThreeOutcomesByHand) {
  const LightWorld env(1, true);
  const Cell key{5, 4};
  const std::vector<Outcome> out = env.transitions(
      LightWorld::observe(lightWorldState(0, 3, 3, false, false, key)), LightWorld::kNorth);
  ASSERT_EQ(out.size(), 3u);
  rl_env_test::expectDistribution(out, "north");
  const Outcome* north =
      find(out, LightWorld::observe(lightWorldState(0, 4, 3, false, false, key)));
  const Outcome* east = find(out, LightWorld::observe(lightWorldState(0, 3, 4, false, false, key)));
  const Outcome* west = find(out, LightWorld::observe(lightWorldState(0, 3, 2, false, false, key)));
  ASSERT_TRUE(north && east && west);
  EXPECT_DOUBLE_EQ(north->probability, 0.9);
  EXPECT_DOUBLE_EQ(east->probability, 0.05);
  EXPECT_DOUBLE_EQ(west->probability, 0.05);
  for (const Outcome& o : out) {
    EXPECT_EQ(o.reward, 0.0f);
    EXPECT_FALSE(o.terminal);
  }
}

TEST(LightWorldTrueModel, BlockedSlipsMergeWithTheStayOutcome) {
  // On the lock (2,6), EAST is blocked and its slips NORTH/SOUTH are blocked too: one outcome.
  const LightWorld env(1, true);
  const State lock = LightWorld::observe(lightWorldState(0, 2, 6, true, false));
  const std::vector<Outcome> out = env.transitions(lock, LightWorld::kEast);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].next, lock);
  EXPECT_DOUBLE_EQ(out[0].probability, 1.0);
  // PRESS there: 0.9 opens the door, 0.1 nothing.
  const std::vector<Outcome> press = env.transitions(lock, LightWorld::kPress);
  ASSERT_EQ(press.size(), 2u);
  rl_env_test::expectDistribution(press, "press");
  const Outcome* opened = find(press, LightWorld::observe(lightWorldState(0, 2, 6, true, true)));
  ASSERT_NE(opened, nullptr);
  EXPECT_DOUBLE_EQ(opened->probability, 0.9);
}

TEST(LightWorldTrueModel, RoomExitSpreadsOverEveryKeyCell) {
  const LightWorld env(1, true);
  const State door = LightWorld::observe(lightWorldState(0, 5, 6, true, true));
  const std::vector<Outcome> out = env.transitions(door, LightWorld::kEast);
  // 12 key cells of room 1 (4 x 3 interior) for the exit, plus staying (both slips blocked).
  ASSERT_EQ(out.size(), 13u);
  rl_env_test::expectDistribution(out, "exit");
  for (const Outcome& o : out) {
    if (o.next == door) {
      EXPECT_NEAR(o.probability, 0.1, 1e-12);
      EXPECT_EQ(o.reward, 0.0f);
    } else {
      EXPECT_NEAR(o.probability, 0.9 / 12, 1e-12);
      EXPECT_EQ(o.reward, 10.0f);
      const FullState s = LightWorld::decode(o.next);
      expectAt(s, 1, 3, 0);
    }
  }
  // Into room 2 (no key): a single exit outcome.
  const std::vector<Outcome> toRoom2 = env.transitions(
      LightWorld::observe(lightWorldState(1, 0, 1, true, true)), LightWorld::kSouth);
  ASSERT_EQ(toRoom2.size(), 2u);
  const Outcome* entered =
      find(toRoom2, LightWorld::observe(lightWorldState(2, 7, 1, true, false)));
  ASSERT_NE(entered, nullptr);
  EXPECT_DOUBLE_EQ(entered->probability, 0.9);
}

TEST(LightWorldTrueModel, DeterministicModeGivesOneOutcomeExceptKeyPlacement) {
  const LightWorld env(1, false);
  for (const State& s : env.reachableStates()) {
    const FullState f = LightWorld::decode(s);
    for (int a = 0; a < LightWorld::kNumActions; ++a) {
      const std::vector<Outcome> out = env.transitions(s, a);
      const bool keyedExit = f.doorOpen && a == LightWorld::room(f.room).exitAction &&
                             Cell{f.ns, f.ew} == LightWorld::room(f.room).door &&
                             LightWorld::room((f.room + 1) % 4).hasKey;
      if (!keyedExit) {
        ASSERT_EQ(out.size(), 1u);
        EXPECT_DOUBLE_EQ(out[0].probability, 1.0);
      } else {
        const LightWorld::Room& next = LightWorld::room((f.room + 1) % 4);
        EXPECT_EQ(out.size(), static_cast<std::size_t>((next.height - 2) * (next.width - 2)));
      }
    }
  }
}

TEST(LightWorldTrueModel, EveryDistributionSumsToOne) {
  const LightWorld env(1, true);
  for (const State& s : env.reachableStates()) {
    for (int a = 0; a < LightWorld::kNumActions; ++a) {
      double sum = 0.0;
      for (const Outcome& o : env.transitions(s, a)) sum += o.probability;
      ASSERT_NEAR(sum, 1.0, 1e-9);
    }
  }
}

TEST(LightWorldTrueModel, SamplingAgreesWithTheDistribution) {
  LightWorld env(2024, true);
  const int n = 20000;
  // A move, a PICKUP on the key, a PRESS on the lock, and a room exit (13 outcomes).
  rl_env_test::expectSamplingAgrees(
      env, LightWorld::observe(lightWorldState(0, 3, 3, false, false, {5, 4})), LightWorld::kWest,
      n);
  rl_env_test::expectSamplingAgrees(
      env, LightWorld::observe(lightWorldState(0, 3, 2, false, false, {3, 2})), LightWorld::kPickup,
      n);
  rl_env_test::expectSamplingAgrees(env, LightWorld::observe(lightWorldState(2, 3, 4, true, false)),
                                    LightWorld::kPress, n);
  rl_env_test::expectSamplingAgrees(env, LightWorld::observe(lightWorldState(0, 5, 6, true, true)),
                                    LightWorld::kEast, n);
  rl_env_test::expectSamplingAgrees(env, LightWorld::observe(lightWorldState(2, 3, 0, true, true)),
                                    LightWorld::kWest, n);

  // Binomial check of the success probability of PICKUP: 0.9 within 4 standard deviations.
  int picked = 0;
  const State onKey = LightWorld::observe(lightWorldState(1, 2, 2, false, false, {2, 2}));
  for (int i = 0; i < n; ++i) {
    env.setState(onKey);
    env.apply(LightWorld::kPickup);
    picked += env.fullState().haveKey ? 1 : 0;
  }
  const double sd = std::sqrt(0.9 * 0.1 / n);
  EXPECT_NEAR(static_cast<double>(picked) / n, 0.9, 4 * sd);
}

TEST(LightWorldTrueModel, ReachableStatesAreExactlyWhatCanOccur) {
  const LightWorld stochastic(1, true);
  const std::vector<State> all = stochastic.reachableStates();
  // Hand count: room 0: 32 standable non-entry cells x 30 keys + 30 (entry) + 32 + 32 = 1054;
  // room 1: 14 x 12 + 12 + 14 + 14 = 208; room 2: 21 + 20 = 41; room 3: 22 x 20 + 20 + 22 + 22
  // = 504.
  EXPECT_EQ(all.size(), 1807u);
  for (const State& s : all) {
    EXPECT_NO_THROW(LightWorld::decode(s));
    EXPECT_EQ(LightWorld::observe(LightWorld::decode(s)), s);
  }
  LightWorld env(3, true);
  const State start = env.sensation();
  rl_env_test::expectReachableClosed(stochastic, {start});
  const LightWorld deterministic(1, false);
  rl_env_test::expectReachableClosed(deterministic, {start});
}

}  // namespace
