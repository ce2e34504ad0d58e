/**
 * ExperienceLog: the experiences a model-based agent learned, kept so that its model can be
 * rebuilt with other rewards (the paper's explore-then-task protocol: after a reward-free
 * phase the agent is "provided with a reward function for a task", TEXPLORE-VANIR paper §5.1).
 *
 * Recording must start before the first experience: a model rebuilt from a log that misses
 * some would not be the model the agent has.
 */
#pragma once

#include <cstddef>
#include <vector>

#include "rl_common/experience.h"

namespace rl_agent {

class ExperienceLog {
 public:
  /// Keeps every experience from now on (on) or stops keeping them. Throws std::logic_error,
  /// naming the count, if `on` and experiences were learned before recording started.
  void record(bool on);
  bool recording() const { return recording_; }

  /// One experience of a step (its reward can be relabelled).
  void addStep(const rl_common::Experience& e);
  /// Experiences given before the first step (seeds keep their rewards).
  void addSeeds(const std::vector<rl_common::Experience>& seeds);

  /// Step experiences recorded so far.
  std::size_t steps() const { return steps_; }

  /// Gives the i-th recorded step the reward `rewards[i]` (seeds keep theirs) and returns every
  /// recorded experience in the order learned. Throws std::logic_error unless recording was
  /// on from the start, std::invalid_argument unless there is one reward per recorded step.
  std::vector<rl_common::Experience> relabel(const std::vector<float>& rewards);

 private:
  struct Entry {
    rl_common::Experience experience;  ///< as the model learned it (binned, with history)
    bool step = false;                 ///< false for a seed
  };
  bool recording_ = false;
  std::size_t learned_ = 0;  ///< experiences seen (recorded or not)
  std::size_t steps_ = 0;
  std::vector<Entry> entries_;
};

}  // namespace rl_agent
