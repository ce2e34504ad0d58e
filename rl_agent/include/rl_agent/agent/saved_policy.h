/**
 * SavedPolicy: acts greedily on Q-values loaded from a policy file (the original's
 * `savedpolicy` agent, `--filename`; format in PolicyFile). It does not learn. A state the file
 * does not contain gets a uniformly random action (seeded); greedy ties are broken at random.
 */
#pragma once

#include <cstdint>
#include <string>

#include "rl_agent/agent/policy_file.h"
#include "rl_common/agent.h"
#include "rl_common/random.h"

namespace rl_agent {

class SavedPolicy : public rl_common::Agent {
 public:
  /// Loads `filename`. Throws std::invalid_argument if the file's number of actions or
  /// features does not match the task (numFeatures < 0 skips the feature check),
  /// std::runtime_error if the file cannot be read.
  SavedPolicy(int numActions, int numFeatures, const std::string& filename, std::uint64_t seed);

  int firstAction(const rl_common::State& s) override { return act(s); }
  int nextAction(float /*reward*/, const rl_common::State& s) override { return act(s); }
  void lastAction(float /*reward*/) override {}
  /// Writes the loaded policy back (the same format).
  void savePolicy(const std::string& filename) override;

  std::size_t numStates() const { return contents_.q.size(); }
  /// True if the last action came from the file (false: the state was unknown).
  bool lastActionKnown() const { return lastKnown_; }

 private:
  int act(const rl_common::State& s);

  PolicyFile::Contents contents_;
  rl_common::Random rng_;
  bool lastKnown_ = false;
};

}  // namespace rl_agent
