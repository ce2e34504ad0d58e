#include "rl_agent/agent/sarsa.h"

#include <stdexcept>

namespace rl_agent {

Sarsa::Sarsa(const Config& config, std::uint64_t seed)
    : config_(config), rng_(seed), q_(std::max(config.numActions, 1), config.initialValue) {
  if (config.numActions < 1) {
    throw std::invalid_argument("Sarsa::Sarsa(): numActions must be >= 1, got " +
                                std::to_string(config.numActions));
  }
  for (float rate : {config.gamma, config.alpha, config.epsilon, config.lambda}) {
    if (!(rate >= 0.0f && rate <= 1.0f)) {
      throw std::invalid_argument(
          "Sarsa::Sarsa(): gamma, alpha, epsilon and lambda must be in "
          "[0, 1]");
    }
  }
}

void Sarsa::update(float delta) {
  // Mark (s, a) with a replacing trace, then move every traced pair along delta.
  bool found = false;
  for (auto& t : traces_) {
    if (t.action == lastAction_ && t.s == lastState_) {
      t.e = 1.0f;
      found = true;
    }
  }
  if (!found) traces_.push_back({lastState_, lastAction_, 1.0f});
  const float decay = config_.gamma * config_.lambda;
  std::vector<Trace> kept;
  kept.reserve(traces_.size());
  for (auto& t : traces_) {
    q_.row(t.s)[static_cast<std::size_t>(t.action)] += config_.alpha * delta * t.e;
    t.e *= decay;
    if (t.e >= kMinTrace) kept.push_back(std::move(t));
  }
  traces_.swap(kept);
}

int Sarsa::firstAction(const rl_common::State& s) {
  traces_.clear();
  lastState_ = s;
  lastAction_ = q_.epsilonGreedyAction(s, config_.epsilon, rng_);
  return lastAction_;
}

int Sarsa::nextAction(float reward, const rl_common::State& s) {
  if (lastAction_ < 0) throw std::logic_error("Sarsa::nextAction(): called before firstAction()");
  const int next = q_.epsilonGreedyAction(s, config_.epsilon, rng_);
  const float target = reward + config_.gamma * q_.row(s)[static_cast<std::size_t>(next)];
  const float delta = target - q_.value(lastState_, lastAction_);
  update(delta);
  lastState_ = s;
  lastAction_ = next;
  return next;
}

void Sarsa::lastAction(float reward) {
  if (lastAction_ < 0) throw std::logic_error("Sarsa::lastAction(): called before firstAction()");
  update(reward - q_.value(lastState_, lastAction_));
  traces_.clear();
  lastAction_ = -1;
}

void Sarsa::seedExperiences(const std::vector<rl_common::Experience>& seeds) {
  for (const auto& e : seeds) {
    if (e.action < 0 || e.action >= config_.numActions) {
      throw std::invalid_argument("Sarsa::seedExperiences(): action " + std::to_string(e.action) +
                                  " out of range");
    }
    const float target = e.reward + (e.terminal ? 0.0f : config_.gamma * q_.maxValue(e.next));
    float& value = q_.row(e.s)[static_cast<std::size_t>(e.action)];
    value += config_.alpha * (target - value);
  }
}

}  // namespace rl_agent
