#include "rl_agent/model/factored_model.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace rl_agent {

namespace {

constexpr float kUnknownReward = -0.001f;

/// A revision no forest of any model had before (so stamps of two models never match).
std::uint64_t nextRevision() {
  static std::atomic<std::uint64_t> counter{0};
  return ++counter;
}

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
  for (std::size_t k = 0; k < features_.size() + 2; ++k) revisions_.push_back(nextRevision());
}

bool FactoredModel::update(const std::vector<rl_common::Experience>& experiences) {
  const std::size_t d = config_->featMin.size();
  const std::size_t inputLen = d + static_cast<std::size_t>(config_->extraInputs);
  // With the weighted and best combinations every instance moves the trees' accuracies.
  const Combination combination = config_->forest.combination;
  const bool anyInstance =
      combination == Combination::WeightedAverage || combination == Combination::Best;
  std::vector<char> moved(d + 2, 0);  // per forest: its predictions may have changed
  const auto add = [&](RandomForest& forest, std::size_t k, std::uint32_t row, float out) {
    if (forest.addRow(row, out) || anyInstance) moved[k] = 1;
  };
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
        add(features_[j], j, row, out);
      }
    }
    add(reward_, d, row, e.reward);
    if (config_->episodic) add(terminal_, d + 1, row, e.terminal ? 1.0f : 0.0f);
    ++experiences_;
  }
  bool changed = false;
  for (std::size_t k = 0; k < moved.size(); ++k) {
    if (moved[k]) {
      revisions_[k] = nextRevision();
      changed = true;
    }
  }
  return changed;
}

std::shared_ptr<const FactoredModel::View> FactoredModel::factoredView() const {
  auto v = std::make_shared<View>();
  v->config_ = config_;
  for (const auto& f : features_) v->features_.push_back(f.snapshot());
  v->reward_ = reward_.snapshot();
  v->terminal_ = terminal_.snapshot();
  v->revisions_ = revisions_;
  v->experiences_ = experiences_;
  return v;
}

std::shared_ptr<const FactoredModel::View> FactoredModel::View::recombined(
    Combination combination) const {
  auto v = std::make_shared<View>(*this);
  for (auto& f : v->features_) f = f.recombined(combination);
  v->reward_ = reward_.recombined(combination);
  v->terminal_ = terminal_.recombined(combination);
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
  rl_common::StateActionInfo info;
  refresh(input, action, info, nullptr, variance);
  return info;
}

void FactoredModel::View::refresh(const rl_common::State& input, int action,
                                  rl_common::StateActionInfo& info,
                                  rl_common::PredictionStamp* stamp, double* variance) const {
  const std::vector<float> x = treeInput(input, action);
  if (variance != nullptr) *variance = 0.0;
  const std::size_t d = config_->featMin.size();
  const std::size_t outputs = d + 2;
  if (experiences_ == 0) {
    if (variance != nullptr) *variance = this->variance(input, action);
    info = rl_common::StateActionInfo();
    info.transitions.emplace_back(rl_common::State(input.begin(), input.begin() + d), 1.0);
    info.reward = info.externalReward = kUnknownReward;
    info.known = false;
    if (stamp != nullptr) stamp->clear();
    return;
  }
  // The stamp's parts: parts[0] the terminal forest's expectation (a bonus may overwrite
  // termProb in `info`, so it is kept here), parts[1 + k] output k's variance when computed.
  // They hold if the stamp came from this model (its revisions) and has what is asked.
  const bool reuse = stamp != nullptr && info.known && info.transitions.empty() &&
                     info.factored.size() == d && stamp->revisions.size() == outputs &&
                     !stamp->parts.empty() &&
                     (variance == nullptr || stamp->parts.size() == 1 + outputs);
  thread_local std::vector<double> scratch;  // the parts of a query without a stamp
  std::vector<double>& parts = stamp != nullptr ? stamp->parts : scratch;
  if (!reuse) {
    info.transitions.clear();
    info.factored.resize(d);
    parts.assign(variance != nullptr ? 1 + outputs : 1, 0.0);
  }
  const bool keepVariances = parts.size() == 1 + outputs;
  const auto stale = [&](std::size_t k) { return !reuse || stamp->revisions[k] != revisions_[k]; };
  double part = 0.0;
  const auto predict = [&](const RandomForest::Snapshot& forest, std::size_t k) {
    if (!keepVariances) return forest.predict(x);
    Distribution dist = forest.predict(x, &part);
    parts[1 + k] = part;
    return dist;
  };
  // One distribution per feature; their independent product is the next-state distribution
  // (never expanded here: with 17 features it can have millions of outcomes).
  for (std::size_t j = 0; j < d; ++j) {
    if (!stale(j)) continue;
    Distribution dist = predict(features_[j], j);
    if (config_->relativeTransitions) {
      for (auto& outcome : dist) outcome.first = input[j] + outcome.first;
    }
    info.factored[j] = std::move(dist);
  }
  if (stale(d)) info.externalReward = static_cast<float>(expectation(predict(reward_, d)));
  if (config_->episodic && stale(d + 1)) {
    double t = 0.0;
    for (const auto& [value, p] : predict(terminal_, d + 1)) {
      t += std::clamp(static_cast<double>(value), 0.0, 1.0) * p;
    }
    parts[0] = t;
  }
  info.termProb = static_cast<float>(parts[0]);  // 0 when not episodic
  // The model's own reward: no bonus (a view with bonuses adds them after this).
  info.reward = info.externalReward;
  info.varianceReward = info.noveltyReward = info.otherReward = 0.0f;
  info.known = true;
  if (variance != nullptr) {
    // D sums in variance()'s order: the features, the reward, the terminal output.
    double sum = 0.0;
    for (std::size_t k = 0; k <= d; ++k) sum += parts[1 + k];
    if (config_->episodic) sum += parts[1 + d + 1];
    *variance = sum / static_cast<double>(features_.size() + 2);
  }
  if (stamp != nullptr) stamp->revisions = revisions_;
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
