#include "rl_env/render/light_world_view.h"

#include <stdexcept>
#include <string>

namespace rl_env {

const char* LightWorldView::actionName(int action) {
  switch (action) {
    case -1:
      return "NONE";
    case LightWorld::kNorth:
      return "NORTH";
    case LightWorld::kEast:
      return "EAST";
    case LightWorld::kWest:
      return "WEST";
    case LightWorld::kSouth:
      return "SOUTH";
    case LightWorld::kPickup:
      return "PICKUP";
    case LightWorld::kPress:
      return "PRESS";
    default:
      throw std::invalid_argument("LightWorldView: action " + std::to_string(action) +
                                  " is not a LightWorld action (0..5, or -1 for none)");
  }
}

void LightWorldView::cellOrigin(int room, int ns, int ew, int* x, int* y) {
  const LightWorld::Room& r = LightWorld::room(room);
  // The room is centred in the 7 x 8 grid area; ns grows northwards, so row 0 is at the bottom.
  const int left = kMargin + (7 - r.width) * kCell / 2;
  const int top = kHeader + kMargin + (8 - r.height) * kCell / 2;
  *x = left + ew * kCell;
  *y = top + (r.height - 1 - ns) * kCell;
}

RgbImage LightWorldView::render(const LightWorld::FullState& state, int lastAction) {
  const LightWorld::Room& r = LightWorld::room(state.room);
  const std::string action = actionName(lastAction);
  RgbImage image(kWidth, kHeight, kBackground);

  const auto cell = [&](int ns, int ew, int inset, Rgb colour) {
    int x = 0, y = 0;
    cellOrigin(state.room, ns, ew, &x, &y);
    image.fillRect(x + inset, y + inset, kCell - 2 * inset, kCell - 2 * inset, colour);
  };
  for (int ns = 0; ns < r.height; ++ns) {
    for (int ew = 0; ew < r.width; ++ew) {
      const bool inside = ns >= 1 && ns <= r.height - 2 && ew >= 1 && ew <= r.width - 2;
      cell(ns, ew, 0, inside ? kGrid : kWall);
      if (inside) cell(ns, ew, 1, kFloor);  // a thin grid line around each floor cell
    }
  }
  const LightWorld::Cell entry = LightWorld::entryCell(state.room);
  cell(entry.ns, entry.ew, 1, kEntry);
  cell(r.lock.ns, r.lock.ew, 1, kLock);
  cell(r.door.ns, r.door.ew, 1, state.doorOpen ? kDoorOpen : kDoorClosed);
  if (!state.haveKey && state.key != LightWorld::Cell{}) {
    cell(state.key.ns, state.key.ew, kCell / 8, kKey);
  }
  int x = 0, y = 0;
  cellOrigin(state.room, state.ns, state.ew, &x, &y);
  const double cx = x + kCell / 2.0, cy = y + kCell / 2.0;
  image.fillDisc(cx, cy, kCell * 0.3, kAgent);
  if (state.haveKey) image.fillDisc(cx, cy, kCell * 0.12, kKey);

  image.drawText(kMargin, kMargin,
                 "ROOM " + std::to_string(state.room) + (state.haveKey ? " KEY HELD" : ""), 2,
                 kText);
  image.drawText(kMargin, kMargin + 18, "LAST: " + action, 2, kText);
  return image;
}

}  // namespace rl_env
