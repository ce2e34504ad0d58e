/**
 * PolicyFile: reads and writes the original package's policy-file format, so that a policy
 * saved by one agent (`--filename` at shutdown) can be replayed by `savedpolicy`, and files of
 * the original's agents can be read (shared/spec/ORIGINAL.md §1.3).
 *
 * Format (binary, native byte order and sizes as the original's fwrite of int and float):
 *   int nfeats, int nact, then for each state: float s[nfeats], float Q[nact]
 * until the end of the file. States are written in ascending lexicographic order.
 */
#pragma once

#include <map>
#include <string>
#include <vector>

#include "rl_common/experience.h"

namespace rl_agent {

class PolicyFile {
 public:
  /// Q-values per state, as an agent's table.
  using Table = std::map<rl_common::State, std::vector<float>>;

  struct Contents {
    int numFeatures = 0;
    int numActions = 0;
    Table q;
  };

  /// Writes `q` (every row must have `numActions` values and every state `numFeatures`
  /// features). Throws std::invalid_argument for inconsistent rows, std::runtime_error if the
  /// file cannot be written.
  static void write(const std::string& filename, int numFeatures, int numActions, const Table& q);

  /// Reads a policy file. Throws std::runtime_error if the file cannot be opened or is
  /// truncated or malformed.
  static Contents read(const std::string& filename);
};

}  // namespace rl_agent
