#include "rl_agent/model/factored_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace rl_agent {

namespace {

constexpr float kUnknownReward = -0.001f;

RandomForest makeForest(const FactoredModel::Config& c, std::uint64_t seed, const char* stream,
                        std::uint64_t index, std::shared_ptr<C45Tree::InputTable> inputs) {
  return RandomForest(c.forest, rl_common::Random::deriveSeed(seed, stream, index),
                      std::move(inputs));
}

std::shared_ptr<const FactoredModel::Config> checked(const FactoredModel::Config& c) {
  if (c.numActions < 1) {
    throw std::invalid_argument("FactoredModel::FactoredModel(): numActions must be >= 1");
  }
  if (c.featMin.empty() || c.featMin.size() != c.featMax.size()) {
    throw std::invalid_argument(
        "FactoredModel::FactoredModel(): feature "
        "ranges must be non-empty and equally long");
  }
  if (c.extraInputs < 0) {
    throw std::invalid_argument("FactoredModel::FactoredModel(): extraInputs must be >= 0");
  }
  return std::make_shared<const FactoredModel::Config>(c);
}

}  // namespace

FactoredModel::FactoredModel(const Config& config, std::uint64_t seed)
    : config_(checked(config)),
      inputs_(std::make_shared<C45Tree::InputTable>()),
      reward_(makeForest(config, seed, "reward", 0, inputs_)),
      terminal_(makeForest(config, seed, "terminal", 0, inputs_)) {
  for (std::size_t j = 0; j < config.featMin.size(); ++j) {
    features_.push_back(makeForest(config, seed, "feature", j, inputs_));
  }
}

bool FactoredModel::update(const std::vector<rl_common::Experience>& experiences) {
  const std::size_t d = config_->featMin.size();
  const std::size_t inputLen = d + static_cast<std::size_t>(config_->extraInputs);
  bool changed = false;
  std::vector<float> x;
  for (const auto& e : experiences) {
    if (e.s.size() != inputLen || e.next.size() < d) {
      throw std::invalid_argument("FactoredModel::update(): experience state has " +
                                  std::to_string(e.s.size()) + " values, expected " +
                                  std::to_string(inputLen));
    }
    if (e.action < 0 || e.action >= config_->numActions) {
      throw std::invalid_argument("FactoredModel::update(): action " + std::to_string(e.action) +
                                  " out of range");
    }
    x.assign(e.s.begin(), e.s.end());
    for (int a = 0; a < config_->numActions; ++a) x.push_back(a == e.action ? 1.0f : 0.0f);
    const std::uint32_t row = inputs_->append(x);  // stored once for every forest
    if (!e.terminal) {
      for (std::size_t j = 0; j < d; ++j) {
        const float out = config_->relativeTransitions ? e.next[j] - e.s[j] : e.next[j];
        changed |= features_[j].addRow(row, out);
      }
    }
    changed |= reward_.addRow(row, e.reward);
    if (config_->episodic) changed |= terminal_.addRow(row, e.terminal ? 1.0f : 0.0f);
    ++experiences_;
  }
  return changed;
}

std::shared_ptr<const FactoredModel::View> FactoredModel::factoredView() const {
  auto v = std::make_shared<View>();
  v->config_ = config_;
  for (const auto& f : features_) v->features_.push_back(f.snapshot());
  v->reward_ = reward_.snapshot();
  v->terminal_ = terminal_.snapshot();
  v->experiences_ = experiences_;
  return v;
}

std::vector<float> FactoredModel::View::treeInput(const rl_common::State& input, int action) const {
  const std::size_t inputLen = config_->featMin.size() + config_->extraInputs;
  if (input.size() != inputLen) {
    throw std::invalid_argument("FactoredModel::View: query state has " +
                                std::to_string(input.size()) + " values, expected " +
                                std::to_string(inputLen));
  }
  if (action < 0 || action >= config_->numActions) {
    throw std::invalid_argument("FactoredModel::View: action " + std::to_string(action) +
                                " out of range");
  }
  std::vector<float> x(input.begin(), input.end());
  for (int a = 0; a < config_->numActions; ++a) x.push_back(a == action ? 1.0f : 0.0f);
  return x;
}

Distribution FactoredModel::View::featureDistribution(const rl_common::State& input, int action,
                                                      std::size_t feature) const {
  return features_.at(feature).predict(treeInput(input, action));
}

rl_common::StateActionInfo FactoredModel::View::query(const rl_common::State& input,
                                                      int action) const {
  return query(input, action, nullptr);
}

rl_common::StateActionInfo FactoredModel::View::query(const rl_common::State& input, int action,
                                                      double* variance) const {
  const std::vector<float> x = treeInput(input, action);
  if (variance != nullptr) *variance = 0.0;
  const std::size_t d = config_->featMin.size();
  rl_common::StateActionInfo info;
  const rl_common::State current(input.begin(), input.begin() + d);
  if (experiences_ == 0) {
    if (variance != nullptr) *variance = this->variance(input, action);
    info.transitions.emplace_back(current, 1.0);
    info.reward = info.externalReward = kUnknownReward;
    info.known = false;
    return info;
  }
  // One distribution per feature; their independent product is the next-state distribution
  // (never expanded here: with 17 features it can have millions of outcomes).
  // D sums in variance()'s order: the features, the reward, the terminal output.
  double sum = 0.0, part = 0.0;
  info.factored.resize(d);
  for (std::size_t j = 0; j < d; ++j) {
    Distribution dist = variance ? features_[j].predict(x, &part) : features_[j].predict(x);
    sum += part;
    if (config_->relativeTransitions) {
      for (auto& outcome : dist) outcome.first = current[j] + outcome.first;
    }
    info.factored[j] = std::move(dist);
  }
  info.reward = info.externalReward =
      static_cast<float>(expectation(variance ? reward_.predict(x, &part) : reward_.predict(x)));
  sum += part;
  if (config_->episodic) {
    double t = 0.0;
    for (const auto& [value, p] : variance ? terminal_.predict(x, &part) : terminal_.predict(x)) {
      t += std::clamp(static_cast<double>(value), 0.0, 1.0) * p;
    }
    sum += part;
    info.termProb = static_cast<float>(t);
  }
  if (variance != nullptr) *variance = sum / static_cast<double>(features_.size() + 2);
  info.known = true;
  return info;
}

double FactoredModel::View::variance(const rl_common::State& input, int action) const {
  const std::vector<float> x = treeInput(input, action);
  double sum = 0.0;
  for (const auto& f : features_) sum += f.variance(x);
  sum += reward_.variance(x);
  if (config_->episodic) sum += terminal_.variance(x);
  return sum / static_cast<double>(features_.size() + 2);
}

}  // namespace rl_agent
