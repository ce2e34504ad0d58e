/**
 * Where a LightWorld agent tries its object actions (the TEXPLORE-VANIR paper §5.1, Fig. 6):
 * for PRESS and PICKUP, whether the agent stands on the key, on the lock (with the key and the
 * door still closed: the press that opens the door; or otherwise), on the door, or elsewhere.
 * A curious agent tries its actions on the objects; a random one mostly elsewhere.
 */
#pragma once

#include <array>
#include <optional>
#include <string>

#include "rl_common/environment.h"

namespace rl_experiment {

enum class Location { kNone = 0, kKey, kLock, kLockWrong, kDoor, kElsewhere };
constexpr int kNumLocations = 6;

/// "", "key", "lock", "lock_wrong", "door", "elsewhere".
const char* locationName(Location l);

/// The kinds of object actions counted.
enum class ObjectAction { kPress = 0, kPickup = 1 };

/// Where `action` is taken in `env`'s current state: kNone unless `env` is a LightWorld and
/// `action` is PRESS or PICKUP. kLock means on the lock holding the key with the door closed
/// (the press that opens the door); kLockWrong on the lock otherwise.
Location locationOf(const rl_common::Environment& env, int action);

/// Whether `env` is a LightWorld whose key lies on the floor. Only then do the key sensors
/// read anything, so only those steps teach a model the key lights' dynamics (most of the
/// model distance, docs/science/lightworld-curiosity.md §2); nullopt for other environments.
std::optional<bool> keyOnFloor(const rl_common::Environment& env);

/// Counts of PRESS and PICKUP per location.
struct LocationCounts {
  std::array<std::array<long, kNumLocations>, 2> counts{};  ///< [ObjectAction][Location]
  /// Counts `action` at `location` (ignores kNone and actions other than PRESS/PICKUP).
  void add(const rl_common::Environment& env, int action);
  long get(ObjectAction a, Location l) const {
    return counts[static_cast<int>(a)][static_cast<int>(l)];
  }
};

}  // namespace rl_experiment
