/**
 * The Agent interface: the original package's episode protocol, ROS-free.
 *
 * An episode is `firstAction(s0)`, then `nextAction(r, s)` after every step, and
 * `lastAction(r)` when a step ends in a terminal state. Non-episodic tasks are one long
 * episode that never calls `lastAction`. Seed experiences may be given before the first action.
 * Each agent owns its random source, seeded at construction.
 */
#pragma once

#include <string>
#include <vector>

#include "rl_common/experience.h"

namespace rl_common {

class Agent {
 public:
  virtual ~Agent() = default;

  /// Starts an episode in state `s`; returns the action to take.
  virtual int firstAction(const State& s) = 0;
  /// Receives the reward of the previous action and the new state; returns the next action.
  virtual int nextAction(float reward, const State& s) = 0;
  /// Receives the reward of the action that ended the episode.
  virtual void lastAction(float reward) = 0;
  /// Learns from transitions given before acting (the original's seedExp); default: ignore.
  virtual void seedExperiences(const std::vector<Experience>& /*seeds*/) {}
  /// Writes the agent's policy to `filename` (the original policy-file format); default: none.
  virtual void savePolicy(const std::string& /*filename*/) {}
};

}  // namespace rl_common
