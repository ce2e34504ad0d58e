/** Building LightWorld full states in tests (the dynamics' and the view's tests share it). */
#pragma once

#include "rl_env/env/light_world.h"

namespace rl_env::testing {

inline LightWorld::FullState lightWorldState(int room, int ns, int ew, bool haveKey, bool doorOpen,
                                             LightWorld::Cell key = {}) {
  LightWorld::FullState s;
  s.room = room;
  s.ns = ns;
  s.ew = ew;
  s.haveKey = haveKey;
  s.doorOpen = doorOpen;
  s.key = key;
  return s;
}

}  // namespace rl_env::testing
