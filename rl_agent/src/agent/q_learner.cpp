#include "rl_agent/agent/q_learner.h"

#include <stdexcept>
#include <string>

namespace rl_agent {

namespace {

int checkedNumActions(int numActions) {
  if (numActions < 1) {
    throw std::invalid_argument("QLearner::QLearner(): numActions must be >= 1, got " +
                                std::to_string(numActions));
  }
  return numActions;
}

}  // namespace

QLearner::QLearner(const Config& config, std::uint64_t seed)
    : config_(config), rng_(seed), q_(checkedNumActions(config.numActions), config.initialValue) {
  for (float rate : {config.gamma, config.alpha, config.epsilon}) {
    if (!(rate >= 0.0f && rate <= 1.0f)) {
      throw std::invalid_argument(
          "QLearner::QLearner(): gamma, alpha and epsilon must be in "
          "[0, 1]");
    }
  }
}

float QLearner::q(const rl_common::State& s, int action) const { return q_.value(s, action); }

int QLearner::greedyAction(const rl_common::State& s) { return q_.greedyAction(s, rng_); }

void QLearner::update(const rl_common::State& s, int a, float r, const rl_common::State* next) {
  float target = r;
  if (next != nullptr) target += config_.gamma * q_.maxValue(*next);
  float& value = q_.row(s)[static_cast<std::size_t>(a)];
  value += config_.alpha * (target - value);
}

int QLearner::firstAction(const rl_common::State& s) {
  lastState_ = s;
  lastAction_ = q_.epsilonGreedyAction(s, config_.epsilon, rng_);
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

void QLearner::savePolicy(const std::string& filename) { q_.save(filename); }

}  // namespace rl_agent
