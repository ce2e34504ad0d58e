/**
 * EpisodeDriver: the original package's episode protocol, on the agent's side, in one place
 * (the agent node and the trial runner both drive an Agent through it).
 *
 *   act(s, r)        firstAction(s) when an episode starts, else nextAction(r, s)
 *   end(r, true, s)  the episode ended in a terminal state: lastAction(r)
 *   end(r, false, s) it was cut off (a step limit): nextAction(r, s), whose action is
 *                    discarded, as the original's experiment loop does
 *
 * and the episode's bookkeeping: its index, the actions taken, the rewards the agent was
 * given. After end() the next act() starts a new episode.
 */
#pragma once

#include <stdexcept>

#include "rl_common/agent.h"

namespace rl_common {

class EpisodeDriver {
 public:
  /// What end() returns: the episode just finished.
  struct Episode {
    int index = 0;          ///< 0-based
    long actions = 0;       ///< actions taken in it
    float reward = 0.0f;    ///< sum of the rewards the agent was given for them
    bool terminal = false;  ///< ended in a terminal state (false: cut off)
  };

  explicit EpisodeDriver(Agent& agent) : agent_(&agent) {}

  /// The agent's action in `s`; `reward` is that of the previous action (not used when an
  /// episode starts).
  int act(const State& s, float reward) {
    if (starting_) {
      starting_ = false;
      current_ = Episode{next_, 0, 0.0f, false};
      ++current_.actions;
      return agent_->firstAction(s);
    }
    current_.reward += reward;
    ++current_.actions;
    return agent_->nextAction(reward, s);
  }

  /// Ends the episode with the reward of its last action; `s` is the state it ended in (read
  /// only when cut off). Returns the finished episode. Calling it between episodes (nothing
  /// acted yet) is a logic error: the agent has no action to be rewarded.
  Episode end(float reward, bool terminal, const State& s) {
    if (starting_) throw std::logic_error("EpisodeDriver::end(): no episode is running");
    current_.reward += reward;
    current_.terminal = terminal;
    if (terminal) {
      agent_->lastAction(reward);
    } else {
      agent_->nextAction(reward, s);  // the original's cut-off: the action is discarded
    }
    starting_ = true;
    ++next_;
    return current_;
  }

  /// True when the next act() starts an episode.
  bool starting() const { return starting_; }
  /// The running episode (or the last finished one, between episodes).
  const Episode& episode() const { return current_; }
  /// Episodes ended so far.
  int episodesEnded() const { return next_; }

 private:
  Agent* agent_;
  bool starting_ = true;
  int next_ = 0;
  Episode current_;
};

}  // namespace rl_common
