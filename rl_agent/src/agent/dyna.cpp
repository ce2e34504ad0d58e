#include "rl_agent/agent/dyna.h"

#include <stdexcept>

namespace rl_agent {

Dyna::Dyna(const Config& config, std::uint64_t seed)
    : config_(config), rng_(seed), q_(std::max(config.numActions, 1), config.initialValue) {
  if (config.numActions < 1 || config.k < 0) {
    throw std::invalid_argument("Dyna::Dyna(): need numActions >= 1 and k >= 0");
  }
  for (float rate : {config.gamma, config.alpha, config.epsilon}) {
    if (!(rate >= 0.0f && rate <= 1.0f)) {
      throw std::invalid_argument("Dyna::Dyna(): gamma, alpha and epsilon must be in [0, 1]");
    }
  }
}

void Dyna::learn(const rl_common::Experience& e) {
  const float target = e.reward + (e.terminal ? 0.0f : config_.gamma * q_.maxValue(e.next));
  float& value = q_.row(e.s)[static_cast<std::size_t>(e.action)];
  value += config_.alpha * (target - value);
}

void Dyna::replay() {
  if (memory_.empty()) return;
  const int last = static_cast<int>(memory_.size()) - 1;
  for (int i = 0; i < config_.k; ++i) {
    learn(memory_[static_cast<std::size_t>(rng_.uniformInt(0, last))]);
  }
}

int Dyna::act(const rl_common::State& s) {
  replay();
  lastState_ = s;
  lastAction_ = q_.epsilonGreedyAction(s, config_.epsilon, rng_);
  return lastAction_;
}

int Dyna::firstAction(const rl_common::State& s) { return act(s); }

int Dyna::nextAction(float reward, const rl_common::State& s) {
  if (lastAction_ < 0) throw std::logic_error("Dyna::nextAction(): called before firstAction()");
  memory_.push_back({lastState_, lastAction_, reward, s, false});
  learn(memory_.back());
  return act(s);
}

void Dyna::lastAction(float reward) {
  if (lastAction_ < 0) throw std::logic_error("Dyna::lastAction(): called before firstAction()");
  memory_.push_back({lastState_, lastAction_, reward, lastState_, true});
  learn(memory_.back());
  lastAction_ = -1;
}

void Dyna::seedExperiences(const std::vector<rl_common::Experience>& seeds) {
  for (const auto& e : seeds) {
    if (e.action < 0 || e.action >= config_.numActions) {
      throw std::invalid_argument("Dyna::seedExperiences(): action " + std::to_string(e.action) +
                                  " out of range");
    }
    memory_.push_back(e);
    learn(e);
  }
}

}  // namespace rl_agent
