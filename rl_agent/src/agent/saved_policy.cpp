#include "rl_agent/agent/saved_policy.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace rl_agent {

SavedPolicy::SavedPolicy(int numActions, int numFeatures, const std::string& filename,
                         std::uint64_t seed)
    : rng_(seed) {
  if (filename.empty()) {
    throw std::invalid_argument("SavedPolicy::SavedPolicy(): savedpolicy needs --filename");
  }
  contents_ = PolicyFile::read(filename);
  if (contents_.numActions != numActions) {
    throw std::invalid_argument("SavedPolicy::SavedPolicy(): '" + filename + "' has " +
                                std::to_string(contents_.numActions) + " actions, the task has " +
                                std::to_string(numActions));
  }
  if (numFeatures >= 0 && !contents_.q.empty() && contents_.numFeatures != numFeatures) {
    throw std::invalid_argument("SavedPolicy::SavedPolicy(): '" + filename + "' has " +
                                std::to_string(contents_.numFeatures) + " features, the task has " +
                                std::to_string(numFeatures));
  }
}

int SavedPolicy::act(const rl_common::State& s) {
  const auto it = contents_.q.find(s);
  lastKnown_ = it != contents_.q.end();
  if (!lastKnown_) return rng_.uniformInt(0, contents_.numActions - 1);
  const std::vector<float>& q = it->second;
  const float best = *std::max_element(q.begin(), q.end());
  std::vector<int> ties;
  for (int a = 0; a < contents_.numActions; ++a) {
    if (q[static_cast<std::size_t>(a)] >= best - 1e-4f) ties.push_back(a);
  }
  return ties[static_cast<std::size_t>(rng_.uniformInt(0, static_cast<int>(ties.size()) - 1))];
}

void SavedPolicy::savePolicy(const std::string& filename) {
  PolicyFile::write(filename, contents_.numFeatures, contents_.numActions, contents_.q);
}

}  // namespace rl_agent
