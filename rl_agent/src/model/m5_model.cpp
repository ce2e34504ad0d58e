#include "rl_agent/model/m5_model.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rl_agent {

namespace {

constexpr double kTreeRangePct = 1e-4;  // the original's treeRangePct

M5Tree::Config treeConfig(double range) {
  M5Tree::Config c;
  c.allFeatures = true;  // M5ALLMULTI
  c.minSdr = kTreeRangePct * std::max(range, 1e-6);
  c.rebuildTolerance = kTreeRangePct * std::max(range, 1e-6);
  return c;
}

int inputSize(const M5Model::Config& c) {
  return static_cast<int>(c.featMin.size()) + c.extraInputs + c.numActions;
}

}  // namespace

M5Model::M5Model(const Config& config)
    : config_(std::make_shared<const Config>(config)),
      reward_(std::max(inputSize(config), 1), treeConfig(config.rewardRange)),
      terminal_(std::max(inputSize(config), 1), treeConfig(1.0)) {
  if (config.numActions < 1 || config.featMin.empty() ||
      config.featMin.size() != config.featMax.size() || config.extraInputs < 0) {
    throw std::invalid_argument("M5Model::M5Model(): need actions, features and ranges");
  }
  for (std::size_t j = 0; j < config.featMin.size(); ++j) {
    const double range = config.featMax[j] - config.featMin[j];
    features_.emplace_back(inputSize(config), treeConfig(range));
  }
}

std::vector<float> M5Model::treeInput(const rl_common::State& s, int action) const {
  const std::size_t n = config_->featMin.size() + static_cast<std::size_t>(config_->extraInputs);
  if (s.size() != n) {
    throw std::invalid_argument("M5Model: input has " + std::to_string(s.size()) +
                                " features, expected " + std::to_string(n));
  }
  if (action < 0 || action >= config_->numActions) {
    throw std::invalid_argument("M5Model: action " + std::to_string(action) + " out of range");
  }
  std::vector<float> x(s);
  x.resize(n + static_cast<std::size_t>(config_->numActions), 0.0f);
  x[n + static_cast<std::size_t>(action)] = 1.0f;
  return x;
}

bool M5Model::update(const std::vector<rl_common::Experience>& experiences) {
  bool changed = false;
  const std::size_t d = config_->featMin.size();
  for (const auto& e : experiences) {
    const std::vector<float> x = treeInput(e.s, e.action);
    if (!e.terminal) {
      if (e.next.size() != d) {
        throw std::invalid_argument("M5Model::update(): next state has the wrong size");
      }
      for (std::size_t j = 0; j < d; ++j) {
        const double target = config_->relativeTransitions ? e.next[j] - e.s[j] : e.next[j];
        changed |= features_[j].add(x, target);
      }
    }
    changed |= reward_.add(x, e.reward);
    if (config_->episodic) changed |= terminal_.add(x, e.terminal ? 1.0 : 0.0);
    ++experiences_;
  }
  return changed || !experiences.empty();
}

std::shared_ptr<const rl_common::ModelView> M5Model::view() const {
  auto v = std::make_shared<View>();
  v->config_ = config_;
  for (const auto& t : features_) v->features_.push_back(t.snapshot());
  v->reward_ = reward_.snapshot();
  v->terminal_ = terminal_.snapshot();
  v->experiences_ = experiences_;
  return v;
}

rl_common::StateActionInfo M5Model::View::query(const rl_common::State& input, int action) const {
  const Config& c = *config_;
  const std::size_t d = c.featMin.size();
  const std::size_t n = d + static_cast<std::size_t>(c.extraInputs);
  if (input.size() != n || action < 0 || action >= c.numActions) {
    throw std::invalid_argument("M5Model::View::query(): bad input size or action");
  }
  rl_common::StateActionInfo info;
  rl_common::State next(input.begin(), input.begin() + static_cast<std::ptrdiff_t>(d));
  if (experiences_ == 0) {
    info.transitions.emplace_back(next, 1.0);
    info.reward = info.externalReward = -0.001f;
    return info;
  }
  std::vector<float> x(input);
  x.resize(n + static_cast<std::size_t>(c.numActions), 0.0f);
  x[n + static_cast<std::size_t>(action)] = 1.0f;
  for (std::size_t j = 0; j < d; ++j) {
    if (features_[j].root() == nullptr) continue;  // no non-terminal data yet: unchanged
    const double p = features_[j].predict(x);
    const double v = c.relativeTransitions ? input[j] + p : p;
    next[j] = static_cast<float>(
        std::clamp(v, static_cast<double>(c.featMin[j]), static_cast<double>(c.featMax[j])));
  }
  info.transitions.emplace_back(std::move(next), 1.0);
  info.reward = info.externalReward = static_cast<float>(reward_.predict(x));
  info.termProb =
      c.episodic ? static_cast<float>(std::clamp(terminal_.predict(x), 0.0, 1.0)) : 0.0f;
  info.known = true;
  return info;
}

}  // namespace rl_agent
