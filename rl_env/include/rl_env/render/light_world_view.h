/**
 * The LightWorld view: one room of LightWorld (light_world.h) drawn from above, north up,
 * east right, for watching the agent explore. Walls are dark grey, the floor light, the
 * entry cell (where the agent arrives from the previous room) pale blue; the lock is red, the
 * door brown while closed and green once open, the key a yellow square while it lies on the
 * floor, the agent a blue disc (with a yellow dot while it holds the key). A header names the
 * room, whether the key is held, and the last action. Every room is drawn on the same canvas
 * (kWidth x kHeight), so a viewer's window keeps its size through the run.
 */
#pragma once

#include "rl_env/env/light_world.h"
#include "rl_env/render/rgb_image.h"

namespace rl_env {

struct LightWorldView {
  static constexpr int kCell = 32;    ///< pixels per grid cell
  static constexpr int kHeader = 40;  ///< pixels above the grid for the two text lines
  static constexpr int kMargin = 8;
  static constexpr int kWidth = 7 * kCell + 2 * kMargin;             ///< the widest room: 7
  static constexpr int kHeight = kHeader + 8 * kCell + 2 * kMargin;  ///< the tallest: 8

  static constexpr Rgb kWall{70, 70, 70};
  static constexpr Rgb kFloor{236, 236, 226};
  static constexpr Rgb kGrid{206, 206, 196};
  static constexpr Rgb kEntry{196, 218, 240};
  static constexpr Rgb kLock{200, 40, 40};
  static constexpr Rgb kDoorClosed{130, 84, 40};
  static constexpr Rgb kDoorOpen{60, 176, 80};
  static constexpr Rgb kKey{240, 196, 0};
  static constexpr Rgb kAgent{40, 90, 220};
  static constexpr Rgb kBackground{255, 255, 255};
  static constexpr Rgb kText{20, 20, 20};

  /// Draws `state` (throws std::out_of_range for a room id outside 0..3); `lastAction` is a
  /// LightWorld::Action or -1 for none (throws std::invalid_argument otherwise).
  static RgbImage render(const LightWorld::FullState& state, int lastAction);
  /// The pixel rectangle's top-left corner of cell (ns, ew) of room `room` on the canvas.
  static void cellOrigin(int room, int ns, int ew, int* x, int* y);
  /// The action's name as the header shows it ("NORTH" ... "PRESS"; "NONE" for -1).
  static const char* actionName(int action);
};

}  // namespace rl_env
