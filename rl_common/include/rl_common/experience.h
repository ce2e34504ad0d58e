/**
 * State and experience types shared by every environment, agent and model of the suite.
 *
 * A state is a vector of float features, as in the original package (rl_common/core.hh): the
 * environment declares each feature's range, and agents see nothing else about it.
 */
#pragma once

#include <vector>

namespace rl_common {

/// A state: one float per feature, in the order the environment declares.
using State = std::vector<float>;

/// One transition (s, a, r, s', terminal), as the original's `experience` struct.
struct Experience {
  State s;                ///< state before the action
  int action = 0;         ///< action taken, 0 .. numActions-1
  float reward = 0.0f;    ///< reward received
  State next;             ///< state after the action
  bool terminal = false;  ///< true if `next` ends the episode
};

}  // namespace rl_common
