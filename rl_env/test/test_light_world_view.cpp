// The LightWorld view: the same canvas for every room; the agent, key, lock and door where the
// state puts them (north up, east right); the door's colour with door_open; the key drawn only
// while on the floor; the header names the action; a bad action is refused.
#include "rl_env/render/light_world_view.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "light_world_states.h"
#include "rl_env/render/renderable.h"

namespace {

using rl_env::LightWorld;
using rl_env::LightWorldView;
using rl_env::Rgb;
using rl_env::RgbImage;

using rl_env::testing::lightWorldState;

// The pixel at the centre of cell (ns, ew); a quarter cell in from its top-left corner.
Rgb centre(const RgbImage& image, int room, int ns, int ew) {
  int x = 0, y = 0;
  LightWorldView::cellOrigin(room, ns, ew, &x, &y);
  return image.at(x + LightWorldView::kCell / 2, y + LightWorldView::kCell / 2);
}
Rgb nearCorner(const RgbImage& image, int room, int ns, int ew) {
  int x = 0, y = 0;
  LightWorldView::cellOrigin(room, ns, ew, &x, &y);
  return image.at(x + LightWorldView::kCell / 4, y + LightWorldView::kCell / 4);
}

TEST(LightWorldView, EveryRoomOnTheSameCanvas) {
  for (int room = 0; room < LightWorld::kNumRooms; ++room) {
    const LightWorld::Room& r = LightWorld::room(room);
    const bool key = r.hasKey;
    const RgbImage image = LightWorldView::render(
        lightWorldState(room, 1, 1, !key, false, key ? LightWorld::Cell{2, 2} : LightWorld::Cell{}),
        -1);
    EXPECT_EQ(image.width(), LightWorldView::kWidth) << room;
    EXPECT_EQ(image.height(), LightWorldView::kHeight) << room;
    // The whole room lies on the canvas: its corner cells are walls.
    EXPECT_EQ(centre(image, room, 0, 0), LightWorldView::kWall) << room;
    EXPECT_EQ(centre(image, room, r.height - 1, r.width - 1), LightWorldView::kWall) << room;
  }
}

TEST(LightWorldView, ObjectsWhereTheStatePutsThem) {
  // Room 0 (8 x 7): lock (2, 6) and door (5, 6) in the east wall; the key at (4, 3).
  const RgbImage image = LightWorldView::render(lightWorldState(0, 1, 1, false, false, {4, 3}), -1);
  EXPECT_EQ(centre(image, 0, 1, 1), LightWorldView::kAgent);
  EXPECT_EQ(centre(image, 0, 4, 3), LightWorldView::kKey);
  EXPECT_EQ(centre(image, 0, 2, 6), LightWorldView::kLock);
  EXPECT_EQ(centre(image, 0, 5, 6), LightWorldView::kDoorClosed);
  EXPECT_EQ(centre(image, 0, 3, 3), LightWorldView::kFloor);
  EXPECT_EQ(centre(image, 0, 7, 3), LightWorldView::kWall);
  const LightWorld::Cell entry = LightWorld::entryCell(0);
  EXPECT_EQ(centre(image, 0, entry.ns, entry.ew), LightWorldView::kEntry);
  // North is up: a larger ns is drawn higher on the image.
  int x1 = 0, y1 = 0, x2 = 0, y2 = 0;
  LightWorldView::cellOrigin(0, 1, 1, &x1, &y1);
  LightWorldView::cellOrigin(0, 2, 2, &x2, &y2);
  EXPECT_LT(y2, y1);
  EXPECT_GT(x2, x1);
}

TEST(LightWorldView, KeyHeldAndDoorOpen) {
  const RgbImage image =
      LightWorldView::render(lightWorldState(0, 3, 3, true, true), LightWorld::kPress);
  EXPECT_EQ(centre(image, 0, 5, 6), LightWorldView::kDoorOpen);
  // The held key is a dot on the agent, and no key lies anywhere on the floor.
  EXPECT_EQ(centre(image, 0, 3, 3), LightWorldView::kKey);
  EXPECT_EQ(nearCorner(image, 0, 3, 3), LightWorldView::kFloor);  // outside the agent's disc
  const LightWorld::Room& r = LightWorld::room(0);
  for (int ns = 1; ns < r.height - 1; ++ns) {
    for (int ew = 1; ew < r.width - 1; ++ew) {
      if (ns == 3 && ew == 3) continue;
      EXPECT_EQ(centre(image, 0, ns, ew), LightWorldView::kFloor) << ns << "," << ew;
    }
  }
}

TEST(LightWorldView, HeaderNamesTheLastAction) {
  const auto s = lightWorldState(1, 2, 2, false, false, {3, 3});
  const RgbImage north = LightWorldView::render(s, LightWorld::kNorth);
  const RgbImage press = LightWorldView::render(s, LightWorld::kPress);
  EXPECT_NE(north.bytes(), press.bytes());
  // Only the header differs: every row below it is the same.
  const int from = LightWorldView::kHeader * north.rowBytes();
  EXPECT_TRUE(
      std::equal(north.bytes().begin() + from, north.bytes().end(), press.bytes().begin() + from));
  EXPECT_STREQ(LightWorldView::actionName(LightWorld::kPickup), "PICKUP");
  EXPECT_THROW(LightWorldView::render(s, 6), std::invalid_argument);
  EXPECT_THROW(LightWorldView::render(lightWorldState(4, 1, 1, false, false), -1),
               std::out_of_range);
}

TEST(LightWorldView, TheEnvironmentRendersItsCurrentState) {
  LightWorld env(3, false);
  const rl_env::Renderable& view = env;
  const RgbImage image = view.render(-1);
  EXPECT_EQ(image.bytes(), LightWorldView::render(env.fullState(), -1).bytes());
  const auto& s = env.fullState();
  EXPECT_EQ(centre(image, s.room, s.ns, s.ew), LightWorldView::kAgent);
}

}  // namespace
