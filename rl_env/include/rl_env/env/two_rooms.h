/**
 * TwoRooms: a two-room gridworld navigation task with an optional action delay, as the original
 * package's TwoRooms (shared/spec/ORIGINAL.md §8; the delayed version follows Walsh, Nouri, Li
 * & Littman, "Learning and planning in environments with delayed feedback", JAAMAS 2009, and
 * Hester & Stone, "TEXPLORE", Machine Learning 2013).
 *
 * A 5×11 grid (ns = row from the south, ew = column from the west) split by a solid wall in
 * column 5 whose only opening is the doorway cell (2, 5); the left room is ew 0–4, the right
 * room ew 6–10. State [ns, ew]; actions N, S, E, W. Reward −1 per step and 0 for the step that
 * reaches the goal (1, 1), which ends the episode. Stochastic mode: moves go as intended with
 * probability 0.8 and to either perpendicular side with 0.1. Start: a uniform cell of the right
 * room. With delay k > 0 each action takes effect k steps after it is given; the first k steps
 * of an episode execute no move and cost −1 like any step (the original returned 0 for them,
 * §10.3 item 11). Two seed experiences (undelayed task only): a step into the goal and a step
 * into the doorway.
 */
#pragma once

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "rl_common/environment.h"
#include "rl_common/random.h"
#include "rl_common/true_model.h"
#include "rl_env/env/gridworld.h"

namespace rl_env {

class TwoRooms : public rl_common::Environment, public rl_common::TrueModel {
 public:
  enum Action { kNorth = 0, kSouth = 1, kEast = 2, kWest = 3 };
  static constexpr int kNumActions = 4;
  static constexpr int kHeight = 5;
  static constexpr int kWidth = 11;
  static constexpr int kGoalNs = 1;
  static constexpr int kGoalEw = 1;
  static constexpr double kMoveSuccess = 0.8;

  /// `delay` >= 0 steps between giving an action and its effect. Throws std::invalid_argument
  /// for a negative delay.
  TwoRooms(std::uint64_t seed, bool stochastic, int delay);

  // rl_common::Environment
  const rl_common::State& sensation() const override { return obs_; }
  /// Applies an action. In a terminal state nothing changes and the reward is 0.
  float apply(int action) override;
  bool terminal() const override;
  void reset() override;
  int numActions() const override { return kNumActions; }
  void getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const override;
  void getMinMaxReward(float* min, float* max) const override;
  std::vector<rl_common::Experience> seedExperiences() const override;
  std::string name() const override { return "TwoRooms"; }
  bool isStochastic() const override { return stochastic_; }

  // rl_common::TrueModel (undelayed task only: with a delay the queued actions are hidden
  // state, and these throw std::runtime_error)
  /// Exact outcomes of the move noise; the goal is absorbing (self-loop, reward 0).
  std::vector<rl_common::Outcome> transitions(const rl_common::State& s, int action) const override;
  /// Every open cell (51), the goal included.
  std::vector<rl_common::State> reachableStates() const override;
  /// Sets the position (and empties the delay queue: the next k steps execute no move).
  void setState(const rl_common::State& s) override;

  int delay() const { return delay_; }
  const Gridworld& grid() const { return grid_; }

 private:
  void requireUndelayed(const char* where) const;
  std::pair<int, int> decode(const rl_common::State& s, const char* where) const;
  /// The deterministic result of moving in `dir` from (ns, ew): (next, reward, terminal).
  rl_common::Experience step(int ns, int ew, int dir) const;

  rl_common::Random rng_;
  bool stochastic_;
  int delay_;
  Gridworld grid_;
  int ns_ = 0;
  int ew_ = 0;
  std::deque<int> pending_;  ///< actions given but not yet executed (-1 = none)
  rl_common::State obs_;
};

}  // namespace rl_env
