/**
 * LightWorld: the TEXPLORE-VANIR paper's evaluation domain (Hester & Stone, "Intrinsically
 * Motivated Model Learning for Developing Curious Robots", Artificial Intelligence 2017, §5.1;
 * after Konidaris & Barto, "Building portable options", IJCAI 2007), exactly as the original
 * package's LightWorld (shared/spec/ORIGINAL.md §4) with the HEAD fix room_id in [0, 3].
 *
 * The agent moves through a fixed cycle of 4 rooms (0 → 1 → 2 → 3 → 0). Each room has a lock
 * and a door in its walls and, except room 2, a key placed uniformly in the interior on entry.
 * The agent picks the key up (PICKUP on the key), presses the lock while holding the key (PRESS
 * on the lock) to open the door, then walks out through the open door for +10 and arrives on the
 * next room's entry cell (a wall cell). State (17 features, in the original's order): ns (row,
 * north = +1), ew (column, east = +1), have_key, door_open, room_id, then the key, lock and door
 * light sensors, each as N, E, W, S. A sensor reads 10 - (axis distance) when the object lies on
 * its side of the agent along that axis (both opposing sensors read 10 when aligned), else 0.
 * Key sensors are on only while the key is not held, door sensors only while the door is open,
 * lock sensors always. Moves go as intended with probability 0.9 and slip to either side with
 * 0.05; PRESS and PICKUP work with probability 0.9 (stochastic mode). Never terminal,
 * non-episodic, reward in [0, 10].
 *
 * Beyond the original, LightWorld is a rl_common::TrueModel: exact transition distributions,
 * the set of reachable states and setState(), for model-accuracy evaluation and planning; and
 * Renderable: an image of the current room for watching a run (render/light_world_view.h).
 */
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "rl_common/environment.h"
#include "rl_common/random.h"
#include "rl_common/true_model.h"
#include "rl_env/render/renderable.h"

namespace rl_env {

class LightWorld : public rl_common::Environment, public rl_common::TrueModel, public Renderable {
 public:
  enum Action { kNorth = 0, kEast = 1, kWest = 2, kSouth = 3, kPickup = 4, kPress = 5 };
  enum Feature {
    kNs = 0,
    kEw = 1,
    kHaveKey = 2,
    kDoorOpen = 3,
    kRoomId = 4,
    kKeyN = 5,
    kKeyE = 6,
    kKeyW = 7,
    kKeyS = 8,
    kLockN = 9,
    kLockE = 10,
    kLockW = 11,
    kLockS = 12,
    kDoorN = 13,
    kDoorE = 14,
    kDoorW = 15,
    kDoorS = 16,
  };
  static constexpr int kNumActions = 6;
  static constexpr int kNumFeatures = 17;
  static constexpr int kNumRooms = 4;
  static constexpr float kMaxSense = 10.0f;    ///< the original's MAX_SENSE
  static constexpr float kExitReward = 10.0f;  ///< reward for leaving a room
  static constexpr double kMoveSuccess = 0.9;  ///< a move goes as intended (else 0.05 per side)
  static constexpr double kActSuccess = 0.9;   ///< PRESS / PICKUP take effect (else no-op)

  /// A cell (ns, ew) of a room; (-1, -1) means "none".
  struct Cell {
    int ns = -1;
    int ew = -1;
    bool operator==(const Cell& o) const { return ns == o.ns && ew == o.ew; }
    bool operator!=(const Cell& o) const { return !(*this == o); }
  };

  /// One room of the fixed layout (§4.3). Height and width include the wall ring: the
  /// interior is rows 1..height-2 and columns 1..width-2.
  struct Room {
    int height;
    int width;
    bool hasKey;     ///< false for room 2: entering it gives the key
    Cell lock;       ///< in a wall
    Cell door;       ///< in a wall
    int exitAction;  ///< the move (kNorth, ...) that leaves through the open door
  };

  /// The complete state: the visible features plus the key's cell, which the key sensors encode
  /// while the key lies on the floor. `key` is (-1, -1) while the key is held or absent.
  struct FullState {
    int room = 0;
    int ns = 1;
    int ew = 1;
    bool haveKey = false;
    bool doorOpen = false;
    Cell key;
    bool operator==(const FullState& o) const {
      return room == o.room && ns == o.ns && ew == o.ew && haveKey == o.haveKey &&
             doorOpen == o.doorOpen && key == o.key;
    }
  };

  /// Where the objects of the current room are, so an evaluator can tell whether the agent
  /// stands on the key, the lock or the door.
  struct Objects {
    Cell key;                 ///< the key's cell, (-1, -1) unless keyPresent
    bool keyPresent = false;  ///< the key lies on the floor (the room has one, not yet held)
    Cell lock;
    Cell door;
  };

  /// Seeds the environment's own random source and resets to a start state.
  LightWorld(std::uint64_t seed, bool stochastic);

  // rl_common::Environment
  const rl_common::State& sensation() const override { return obs_; }
  /// Applies an action (kNorth .. kPress); returns 10 on leaving a room, else 0.
  float apply(int action) override;
  bool terminal() const override { return false; }
  /// Room 0, a uniform interior cell, no key, door closed, key placed uniformly.
  void reset() override;
  int numActions() const override { return kNumActions; }
  void getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const override;
  void getMinMaxReward(float* min, float* max) const override;
  bool isEpisodic() const override { return false; }
  std::string name() const override { return "LightWorld"; }
  bool isStochastic() const override { return stochastic_; }

  // rl_common::TrueModel
  /// Exact outcomes: the move noise, the PRESS/PICKUP failure, and on a room exit one outcome
  /// per interior cell of the new room for the key (uniform), if that room has a key.
  std::vector<rl_common::Outcome> transitions(const rl_common::State& s, int action) const override;
  /// Every state that can occur: per room, each cell the agent can stand on (interior, lock,
  /// door, entry cell) with each possible (have_key, door_open) and key cell.
  std::vector<rl_common::State> reachableStates() const override;
  void setState(const rl_common::State& s) override;

  // Renderable
  /// The current room from above (LightWorldView).
  RgbImage render(int lastAction) const override;

  /// The complete current state.
  const FullState& fullState() const { return state_; }
  /// Sets the complete state. Throws std::invalid_argument if it cannot occur.
  void setFullState(const FullState& state);
  /// The key, lock and door of the current room.
  Objects objects() const;

  /// The layout of room `id` (0..3). Throws std::out_of_range for another id.
  static const Room& room(int id);
  /// The wall cell where the agent arrives when it enters room `id`.
  static Cell entryCell(int id);
  /// True if the agent can stand on (ns, ew) of room `id`: interior, lock, door or entry cell.
  static bool canStand(int id, int ns, int ew);
  /// The 17 features of a complete state (sensors computed).
  static rl_common::State observe(const FullState& state);
  /// Decodes features into a complete state (the key cell from the key sensors). Throws
  /// std::invalid_argument if the features are not a state that can occur.
  static FullState decode(const rl_common::State& s);

 private:
  /// Empty if `state` can occur, else what is wrong with it.
  static std::string invalidReason(const FullState& state);
  /// Applies an effective action (-1 = no-op) to `state`; returns the reward. On a room exit
  /// sets *exited and leaves the new room's key unplaced.
  static float applyEffect(FullState* state, int effect, bool* exited);
  /// The effective actions of `action` with their probabilities.
  std::vector<std::pair<int, double>> effects(int action) const;

  rl_common::Random rng_;
  bool stochastic_;
  FullState state_;
  rl_common::State obs_;
};

}  // namespace rl_env
