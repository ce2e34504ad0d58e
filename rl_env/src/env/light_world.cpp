#include "rl_env/env/light_world.h"

#include <array>
#include <stdexcept>
#include <utility>

#include "env_detail.h"
#include "rl_env/render/light_world_view.h"

namespace rl_env {

namespace {

using Cell = LightWorld::Cell;
using Room = LightWorld::Room;

// The fixed layout of §4.3: (height, width) with the wall ring, key?, lock, door, exit move.
const std::array<Room, LightWorld::kNumRooms> kRooms = {{
    {8, 7, true, {2, 6}, {5, 6}, LightWorld::kEast},   // room 0: lock and door in the east wall
    {6, 5, true, {0, 3}, {0, 1}, LightWorld::kSouth},  // room 1: both in the south wall
    {8, 5, false, {3, 4}, {3, 0}, LightWorld::kWest},  // room 2: no key; lock east, door west
    {6, 7, true, {0, 4}, {5, 2}, LightWorld::kNorth},  // room 3: lock south, door north
}};

bool interior(const Room& r, int ns, int ew) {
  return ns >= 1 && ns <= r.height - 2 && ew >= 1 && ew <= r.width - 2;
}

// One light sensor group (N, E, W, S) for an object at `o` seen from (ns, ew) (§4.5).
void sense(const Cell& o, int ns, int ew, rl_common::State* s, int first) {
  const float m = LightWorld::kMaxSense;
  (*s)[first + 0] = o.ns >= ns ? m - static_cast<float>(o.ns - ns) : 0.0f;  // N
  (*s)[first + 1] = o.ew >= ew ? m - static_cast<float>(o.ew - ew) : 0.0f;  // E
  (*s)[first + 2] = o.ew <= ew ? m - static_cast<float>(ew - o.ew) : 0.0f;  // W
  (*s)[first + 3] = o.ns <= ns ? m - static_cast<float>(ns - o.ns) : 0.0f;  // S
}

}  // namespace

LightWorld::LightWorld(std::uint64_t seed, bool stochastic) : rng_(seed), stochastic_(stochastic) {
  reset();
}

const LightWorld::Room& LightWorld::room(int id) {
  if (id < 0 || id >= kNumRooms) {
    throw std::out_of_range("LightWorld::room(): room id " + std::to_string(id) +
                            " out of range [0, " + std::to_string(kNumRooms - 1) + "]");
  }
  return kRooms[static_cast<std::size_t>(id)];
}

LightWorld::Cell LightWorld::entryCell(int id) {
  const Room& here = room(id);
  const Room& prev = room((id + kNumRooms - 1) % kNumRooms);
  // The agent keeps the coordinate along the door's axis and lands on the opposite wall.
  switch (prev.exitAction) {
    case kEast:
      // The original forces ns = 3 on entering room 1 (the kept ns = 5 would be a corner).
      return {id == 1 ? 3 : prev.door.ns, 0};
    case kWest:
      return {prev.door.ns, here.width - 1};
    case kSouth:
      return {here.height - 1, prev.door.ew};
    default:  // kNorth
      return {0, prev.door.ew};
  }
}

bool LightWorld::canStand(int id, int ns, int ew) {
  if (id < 0 || id >= kNumRooms) return false;
  const Room& r = room(id);
  const Cell c{ns, ew};
  return interior(r, ns, ew) || c == r.lock || c == r.door || c == entryCell(id);
}

rl_common::State LightWorld::observe(const FullState& st) {
  rl_common::State s(kNumFeatures, 0.0f);
  s[kNs] = static_cast<float>(st.ns);
  s[kEw] = static_cast<float>(st.ew);
  s[kHaveKey] = st.haveKey ? 1.0f : 0.0f;
  s[kDoorOpen] = st.doorOpen ? 1.0f : 0.0f;
  s[kRoomId] = static_cast<float>(st.room);
  const Room& r = room(st.room);
  if (!st.haveKey) sense(st.key, st.ns, st.ew, &s, kKeyN);
  sense(r.lock, st.ns, st.ew, &s, kLockN);
  if (st.doorOpen) sense(r.door, st.ns, st.ew, &s, kDoorN);
  return s;
}

std::string LightWorld::invalidReason(const FullState& st) {
  if (st.room < 0 || st.room >= kNumRooms) return "room_id " + std::to_string(st.room);
  const Room& r = room(st.room);
  if (!canStand(st.room, st.ns, st.ew)) {
    return "the agent cannot stand on (" + std::to_string(st.ns) + ", " + std::to_string(st.ew) +
           ") of room " + std::to_string(st.room);
  }
  if (st.doorOpen && !st.haveKey) return "the door is open but the key is not held";
  if (!r.hasKey && !st.haveKey) return "room 2 has no key: have_key must be 1";
  if (Cell{st.ns, st.ew} == entryCell(st.room) && (st.doorOpen || st.haveKey == r.hasKey)) {
    return "on the entry cell the room's key cannot be held nor the door open";
  }
  if (st.haveKey) {
    if (st.key != Cell{}) return "the key is held but has a floor cell";
  } else if (!interior(r, st.key.ns, st.key.ew)) {
    return "the key is not in the room's interior";
  }
  return {};
}

LightWorld::FullState LightWorld::decode(const rl_common::State& s) {
  const char* where = "LightWorld::decode()";
  detail::checkStateSize(s, kNumFeatures, where);
  FullState st;
  st.ns = detail::integerFeature(s, kNs, 0, 8, where);
  st.ew = detail::integerFeature(s, kEw, 0, 8, where);
  st.haveKey = detail::integerFeature(s, kHaveKey, 0, 1, where) == 1;
  st.doorOpen = detail::integerFeature(s, kDoorOpen, 0, 1, where) == 1;
  st.room = detail::integerFeature(s, kRoomId, 0, kNumRooms - 1, where);
  for (int i = kKeyN; i < kNumFeatures; ++i) {
    detail::integerFeature(s, static_cast<std::size_t>(i), 0, 10, where);
  }
  if (!st.haveKey) {
    // Invert the key sensors (what the original's setKey() did).
    const int n = static_cast<int>(s[kKeyN]);
    const int so = static_cast<int>(s[kKeyS]);
    const int e = static_cast<int>(s[kKeyE]);
    const int w = static_cast<int>(s[kKeyW]);
    st.key.ns = n > 0 ? st.ns + (10 - n) : (so > 0 ? st.ns - (10 - so) : -1);
    st.key.ew = e > 0 ? st.ew + (10 - e) : (w > 0 ? st.ew - (10 - w) : -1);
  }
  const std::string why = invalidReason(st);
  if (!why.empty()) throw std::invalid_argument(std::string(where) + ": invalid state: " + why);
  if (observe(st) != s) {
    throw std::invalid_argument(std::string(where) +
                                ": invalid state: light sensors do not match the positions");
  }
  return st;
}

void LightWorld::setFullState(const FullState& state) {
  const std::string why = invalidReason(state);
  if (!why.empty()) throw std::invalid_argument("LightWorld::setFullState(): " + why);
  state_ = state;
  obs_ = observe(state_);
}

void LightWorld::setState(const rl_common::State& s) {
  try {
    state_ = decode(s);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("LightWorld::setState(): ") + e.what());
  }
  obs_ = observe(state_);
}

LightWorld::Objects LightWorld::objects() const {
  const Room& r = room(state_.room);
  Objects o;
  o.keyPresent = !state_.haveKey;
  o.key = o.keyPresent ? state_.key : Cell{};
  o.lock = r.lock;
  o.door = r.door;
  return o;
}

RgbImage LightWorld::render(int lastAction) const {
  return LightWorldView::render(state_, lastAction);
}

void LightWorld::reset() {
  const Room& r = room(0);
  state_ = FullState{};
  state_.room = 0;
  state_.ns = rng_.uniformInt(1, r.height - 2);
  state_.ew = rng_.uniformInt(1, r.width - 2);
  state_.haveKey = false;
  state_.doorOpen = false;
  state_.key = {rng_.uniformInt(1, r.height - 2), rng_.uniformInt(1, r.width - 2)};
  obs_ = observe(state_);
}

float LightWorld::applyEffect(FullState* st, int effect, bool* exited) {
  *exited = false;
  const Room& r = room(st->room);
  const Cell here{st->ns, st->ew};
  if (effect == kPickup) {
    if (!st->haveKey && here == st->key) {
      st->haveKey = true;
      st->key = Cell{};
    }
    return 0.0f;
  }
  if (effect == kPress) {
    if (st->haveKey && here == r.lock) st->doorOpen = true;
    return 0.0f;
  }
  if (effect < 0) return 0.0f;  // a failed PRESS / PICKUP

  // A move stays inside the interior, or steps onto the lock or door cell in the wall; moving
  // along a wall is impossible (§4.4).
  Cell target = here;
  bool crossAxisInterior = false;
  switch (effect) {
    case kNorth:
      target.ns += 1;
      crossAxisInterior = st->ew > 0 && st->ew < r.width - 1 && st->ns < r.height - 1;
      break;
    case kSouth:
      target.ns -= 1;
      crossAxisInterior = st->ew > 0 && st->ew < r.width - 1 && st->ns > 0;
      break;
    case kEast:
      target.ew += 1;
      crossAxisInterior = st->ns > 0 && st->ns < r.height - 1 && st->ew < r.width - 1;
      break;
    case kWest:
      target.ew -= 1;
      crossAxisInterior = st->ns > 0 && st->ns < r.height - 1 && st->ew > 0;
      break;
    default:
      break;
  }
  if (crossAxisInterior &&
      (interior(r, target.ns, target.ew) || target == r.lock || target == r.door)) {
    st->ns = target.ns;
    st->ew = target.ew;
    return 0.0f;
  }
  if (st->doorOpen && here == r.door && effect == r.exitAction) {
    const int next = (st->room + 1) % kNumRooms;
    const Cell entry = entryCell(next);
    st->room = next;
    st->ns = entry.ns;
    st->ew = entry.ew;
    st->doorOpen = false;
    st->haveKey = !room(next).hasKey;
    st->key = Cell{};
    *exited = true;
    return kExitReward;
  }
  return 0.0f;  // blocked
}

std::vector<std::pair<int, double>> LightWorld::effects(int action) const {
  if (!stochastic_) return {{action, 1.0}};
  if (action == kPickup || action == kPress) return {{action, kActSuccess}, {-1, 1 - kActSuccess}};
  const double slip = 0.5 * (1.0 - kMoveSuccess);
  if (action == kNorth || action == kSouth) {
    return {{action, kMoveSuccess}, {kEast, slip}, {kWest, slip}};
  }
  return {{action, kMoveSuccess}, {kNorth, slip}, {kSouth, slip}};
}

float LightWorld::apply(int action) {
  detail::checkAction(action, kNumActions, "LightWorld::apply()");
  // One uniform draw picks the effective action, in the order effects() lists them.
  int effect = action;
  if (stochastic_) {
    const double u = rng_.uniform();
    double acc = 0.0;
    for (const auto& [e, p] : effects(action)) {
      acc += p;
      effect = e;
      if (u < acc) break;
    }
  }
  bool exited = false;
  const float reward = applyEffect(&state_, effect, &exited);
  if (exited && room(state_.room).hasKey) {
    const Room& r = room(state_.room);
    state_.key = {rng_.uniformInt(1, r.height - 2), rng_.uniformInt(1, r.width - 2)};
  }
  obs_ = observe(state_);
  return reward;
}

std::vector<rl_common::Outcome> LightWorld::transitions(const rl_common::State& s,
                                                        int action) const {
  detail::checkAction(action, kNumActions, "LightWorld::transitions()");
  FullState from;
  try {
    from = decode(s);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("LightWorld::transitions(): ") + e.what());
  }
  std::vector<rl_common::Outcome> out;
  for (const auto& [effect, p] : effects(action)) {
    FullState to = from;
    bool exited = false;
    const float reward = applyEffect(&to, effect, &exited);
    const Room& r = room(to.room);
    if (exited && r.hasKey) {
      const int cells = (r.height - 2) * (r.width - 2);
      for (int ns = 1; ns <= r.height - 2; ++ns) {
        for (int ew = 1; ew <= r.width - 2; ++ew) {
          to.key = {ns, ew};
          detail::addOutcome(&out, observe(to), reward, false, p / cells);
        }
      }
    } else {
      detail::addOutcome(&out, observe(to), reward, false, p);
    }
  }
  return out;
}

std::vector<rl_common::State> LightWorld::reachableStates() const {
  std::vector<rl_common::State> out;
  const std::array<std::pair<bool, bool>, 3> flags = {
      {{false, false}, {true, false}, {true, true}}};
  for (int id = 0; id < kNumRooms; ++id) {
    const Room& r = room(id);
    for (int ns = 0; ns < r.height; ++ns) {
      for (int ew = 0; ew < r.width; ++ew) {
        if (!canStand(id, ns, ew)) continue;
        for (const auto& [haveKey, doorOpen] : flags) {
          FullState st;
          st.room = id;
          st.ns = ns;
          st.ew = ew;
          st.haveKey = haveKey;
          st.doorOpen = doorOpen;
          if (haveKey) {
            st.key = Cell{};
            if (invalidReason(st).empty()) out.push_back(observe(st));
            continue;
          }
          for (int kns = 1; kns <= r.height - 2; ++kns) {
            for (int kew = 1; kew <= r.width - 2; ++kew) {
              st.key = {kns, kew};
              if (invalidReason(st).empty()) out.push_back(observe(st));
            }
          }
        }
      }
    }
  }
  return out;
}

void LightWorld::getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const {
  min->assign(kNumFeatures, 0.0f);
  max->assign(kNumFeatures, kMaxSense);
  (*max)[kNs] = 8.0f;
  (*max)[kEw] = 8.0f;
  (*max)[kHaveKey] = 1.0f;
  (*max)[kDoorOpen] = 1.0f;
  (*max)[kRoomId] = static_cast<float>(kNumRooms - 1);  // the HEAD fix (the original had 2)
}

void LightWorld::getMinMaxReward(float* min, float* max) const {
  *min = 0.0f;
  *max = kExitReward;
}

}  // namespace rl_env
