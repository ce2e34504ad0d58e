#include "rl_experiment/eval/action_location.h"

#include "rl_env/env/light_world.h"

namespace rl_experiment {

const char* locationName(Location l) {
  switch (l) {
    case Location::kKey:
      return "key";
    case Location::kLock:
      return "lock";
    case Location::kLockWrong:
      return "lock_wrong";
    case Location::kDoor:
      return "door";
    case Location::kElsewhere:
      return "elsewhere";
    case Location::kNone:
      break;
  }
  return "";
}

Location locationOf(const rl_common::Environment& env, int action) {
  using rl_env::LightWorld;
  if (action != LightWorld::kPress && action != LightWorld::kPickup) return Location::kNone;
  const auto* lw = dynamic_cast<const LightWorld*>(&env);
  if (lw == nullptr) return Location::kNone;
  const LightWorld::FullState& s = lw->fullState();
  const LightWorld::Cell here{s.ns, s.ew};
  const LightWorld::Objects o = lw->objects();
  if (o.keyPresent && here == o.key) return Location::kKey;
  if (here == o.lock) return s.haveKey && !s.doorOpen ? Location::kLock : Location::kLockWrong;
  if (here == o.door) return Location::kDoor;
  return Location::kElsewhere;
}

std::optional<bool> keyOnFloor(const rl_common::Environment& env) {
  const auto* lw = dynamic_cast<const rl_env::LightWorld*>(&env);
  if (lw == nullptr) return std::nullopt;
  return lw->objects().keyPresent;
}

void LocationCounts::add(const rl_common::Environment& env, int action) {
  const Location l = locationOf(env, action);
  if (l == Location::kNone) return;
  const int kind = action == rl_env::LightWorld::kPress ? 0 : 1;
  ++counts[kind][static_cast<int>(l)];
}

}  // namespace rl_experiment
