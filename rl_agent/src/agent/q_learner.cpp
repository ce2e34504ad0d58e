#include "rl_agent/agent/q_learner.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "rl_agent/agent/policy_file.h"

namespace rl_agent {

namespace {
constexpr float kTieEpsilon = 1e-4f;  // values this close to the best count as ties
}

QLearner::QLearner(const Config& config, std::uint64_t seed) : config_(config), rng_(seed) {
  if (config.numActions < 1) {
    throw std::invalid_argument("QLearner::QLearner(): numActions must be >= 1, got " +
                                std::to_string(config.numActions));
  }
  for (float rate : {config.gamma, config.alpha, config.epsilon}) {
    if (!(rate >= 0.0f && rate <= 1.0f)) {
      throw std::invalid_argument(
          "QLearner::QLearner(): gamma, alpha and epsilon must be in "
          "[0, 1]");
    }
  }
}

std::vector<float>& QLearner::row(const rl_common::State& s) {
  auto it = q_.find(s);
  if (it == q_.end()) {
    it = q_.emplace(s, std::vector<float>(config_.numActions, config_.initialValue)).first;
  }
  return it->second;
}

float QLearner::q(const rl_common::State& s, int action) const {
  const auto it = q_.find(s);
  return it == q_.end() ? config_.initialValue : it->second.at(action);
}

int QLearner::greedyAction(const rl_common::State& s) {
  const std::vector<float>& values = row(s);
  const float best = *std::max_element(values.begin(), values.end());
  std::vector<int> ties;
  for (int a = 0; a < config_.numActions; ++a) {
    if (values[a] >= best - kTieEpsilon) ties.push_back(a);
  }
  return ties[rng_.uniformInt(0, static_cast<int>(ties.size()) - 1)];
}

int QLearner::chooseAction(const rl_common::State& s) {
  if (rng_.bernoulli(config_.epsilon)) return rng_.uniformInt(0, config_.numActions - 1);
  return greedyAction(s);
}

void QLearner::update(const rl_common::State& s, int a, float r, const rl_common::State* next) {
  float target = r;
  if (next != nullptr) {
    const std::vector<float>& nextValues = row(*next);
    target += config_.gamma * *std::max_element(nextValues.begin(), nextValues.end());
  }
  float& value = row(s)[a];
  value += config_.alpha * (target - value);
}

int QLearner::firstAction(const rl_common::State& s) {
  lastState_ = s;
  lastAction_ = chooseAction(s);
  return lastAction_;
}

int QLearner::nextAction(float reward, const rl_common::State& s) {
  if (lastAction_ < 0) {
    throw std::logic_error("QLearner::nextAction(): called before firstAction()");
  }
  update(lastState_, lastAction_, reward, &s);
  return firstAction(s);
}

void QLearner::lastAction(float reward) {
  if (lastAction_ < 0) {
    throw std::logic_error("QLearner::lastAction(): called before firstAction()");
  }
  update(lastState_, lastAction_, reward, nullptr);
  lastAction_ = -1;
}

void QLearner::seedExperiences(const std::vector<rl_common::Experience>& seeds) {
  for (const auto& e : seeds) {
    if (e.action < 0 || e.action >= config_.numActions) {
      throw std::invalid_argument("QLearner::seedExperiences(): action " +
                                  std::to_string(e.action) + " out of range");
    }
    update(e.s, e.action, e.reward, e.terminal ? nullptr : &e.next);
  }
}

void QLearner::savePolicy(const std::string& filename) {
  const int d = q_.empty() ? 0 : static_cast<int>(q_.begin()->first.size());
  PolicyFile::Table table;
  for (const auto& [s, values] : q_) {
    if (static_cast<int>(s.size()) == d) table.emplace(s, values);
  }
  PolicyFile::write(filename, d, config_.numActions, table);
}

}  // namespace rl_agent
