#include "rl_experiment/eval/action_location.h"

#include <gtest/gtest.h>

#include "rl_env/env/light_world.h"
#include "rl_env/env/taxi.h"

using rl_env::LightWorld;
using rl_experiment::Location;
using rl_experiment::locationOf;

namespace {

LightWorld::FullState at(int ns, int ew, bool haveKey, bool doorOpen, LightWorld::Cell key) {
  LightWorld::FullState s;
  s.room = 0;
  s.ns = ns;
  s.ew = ew;
  s.haveKey = haveKey;
  s.doorOpen = doorOpen;
  s.key = key;
  return s;
}

}  // namespace

TEST(ActionLocation, PressAndPickupOnEachObject) {
  LightWorld lw(1, false);
  const LightWorld::Room& r = LightWorld::room(0);
  const LightWorld::Cell key{2, 2};
  lw.setFullState(at(key.ns, key.ew, false, false, key));
  EXPECT_EQ(locationOf(lw, LightWorld::kPickup), Location::kKey);
  EXPECT_EQ(locationOf(lw, LightWorld::kPress), Location::kKey);
  EXPECT_EQ(locationOf(lw, LightWorld::kNorth), Location::kNone);
  lw.setFullState(at(r.lock.ns, r.lock.ew, true, false, {}));
  EXPECT_EQ(locationOf(lw, LightWorld::kPress), Location::kLock);
  lw.setFullState(at(r.lock.ns, r.lock.ew, false, false, key));
  EXPECT_EQ(locationOf(lw, LightWorld::kPress), Location::kLockWrong);
  lw.setFullState(at(r.lock.ns, r.lock.ew, true, true, {}));
  EXPECT_EQ(locationOf(lw, LightWorld::kPress), Location::kLockWrong);
  lw.setFullState(at(r.door.ns, r.door.ew, true, true, {}));
  EXPECT_EQ(locationOf(lw, LightWorld::kPress), Location::kDoor);
  lw.setFullState(at(4, 4, false, false, key));
  EXPECT_EQ(locationOf(lw, LightWorld::kPress), Location::kElsewhere);

  rl_experiment::LocationCounts counts;
  counts.add(lw, LightWorld::kPress);
  counts.add(lw, LightWorld::kPickup);
  counts.add(lw, LightWorld::kSouth);
  EXPECT_EQ(counts.get(rl_experiment::ObjectAction::kPress, Location::kElsewhere), 1);
  EXPECT_EQ(counts.get(rl_experiment::ObjectAction::kPickup, Location::kElsewhere), 1);
  EXPECT_EQ(counts.get(rl_experiment::ObjectAction::kPress, Location::kKey), 0);
  EXPECT_STREQ(rl_experiment::locationName(Location::kLockWrong), "lock_wrong");
}

TEST(ActionLocation, KeyOnFloorUntilPickedUpAndOnlyForLightWorld) {
  LightWorld lw(1, false);
  const LightWorld::Cell key{2, 2};
  lw.setFullState(at(key.ns, key.ew, false, false, key));
  EXPECT_EQ(rl_experiment::keyOnFloor(lw), std::optional<bool>(true));
  lw.apply(LightWorld::kPickup);  // deterministic mode: the pickup works
  EXPECT_EQ(rl_experiment::keyOnFloor(lw), std::optional<bool>(false));
  rl_env::Taxi other(1, false);
  EXPECT_FALSE(rl_experiment::keyOnFloor(other).has_value());
}
