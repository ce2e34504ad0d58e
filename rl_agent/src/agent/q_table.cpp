#include "rl_agent/agent/q_table.h"

#include <algorithm>
#include <stdexcept>

#include "rl_agent/agent/policy_file.h"

namespace rl_agent {

QTable::QTable(int numActions, float initialValue)
    : numActions_(numActions), initialValue_(initialValue) {
  if (numActions < 1) throw std::invalid_argument("QTable::QTable(): numActions must be >= 1");
}

std::vector<float>& QTable::row(const rl_common::State& s) {
  auto it = q_.find(s);
  if (it == q_.end()) it = q_.emplace(s, std::vector<float>(numActions_, initialValue_)).first;
  return it->second;
}

float QTable::value(const rl_common::State& s, int action) const {
  const auto it = q_.find(s);
  return it == q_.end() ? initialValue_ : it->second.at(static_cast<std::size_t>(action));
}

float QTable::maxValue(const rl_common::State& s) {
  const auto& r = row(s);
  return *std::max_element(r.begin(), r.end());
}

int QTable::greedyAction(const rl_common::State& s, rl_common::Random& rng) {
  const std::vector<float>& values = row(s);
  const float best = *std::max_element(values.begin(), values.end());
  std::vector<int> ties;
  for (int a = 0; a < numActions_; ++a) {
    if (values[static_cast<std::size_t>(a)] >= best - kTieEpsilon) ties.push_back(a);
  }
  return ties[static_cast<std::size_t>(rng.uniformInt(0, static_cast<int>(ties.size()) - 1))];
}

int QTable::epsilonGreedyAction(const rl_common::State& s, float epsilon, rl_common::Random& rng) {
  if (rng.bernoulli(epsilon)) return rng.uniformInt(0, numActions_ - 1);
  return greedyAction(s, rng);
}

void QTable::save(const std::string& filename) const {
  const int d = q_.empty() ? 0 : static_cast<int>(q_.begin()->first.size());
  PolicyFile::Table table;
  for (const auto& [s, values] : q_) {
    if (static_cast<int>(s.size()) == d) table.emplace(s, values);
  }
  PolicyFile::write(filename, d, numActions_, table);
}

}  // namespace rl_agent
