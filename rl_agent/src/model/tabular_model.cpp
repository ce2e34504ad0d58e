#include "rl_agent/model/tabular_model.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rl_agent {

namespace {
constexpr float kUnknownReward = -0.001f;  // the original's prediction for unseen pairs
}

TabularModel::TabularModel(const Config& config) : config_(config) {
  if (config.numActions < 1 || config.numFeatures < 1 || config.m < 0) {
    throw std::invalid_argument(
        "TabularModel::TabularModel(): need numActions >= 1, numFeatures >= 1 and m >= 0");
  }
}

bool TabularModel::update(const std::vector<rl_common::Experience>& experiences) {
  const int known = std::max(config_.m, 1);
  bool changed = false;
  for (const auto& e : experiences) {
    if (e.action < 0 || e.action >= config_.numActions) {
      throw std::invalid_argument("TabularModel::update(): action " + std::to_string(e.action) +
                                  " out of range");
    }
    if (!e.terminal && static_cast<int>(e.next.size()) != config_.numFeatures) {
      throw std::invalid_argument("TabularModel::update(): next state has " +
                                  std::to_string(e.next.size()) + " features, expected " +
                                  std::to_string(config_.numFeatures));
    }
    auto& slot = rows_[e.s];
    const Entry* old = slot ? &(*slot)[static_cast<std::size_t>(e.action)] : nullptr;
    if (config_.optimistic && old != nullptr && old->visits >= known) continue;  // R-MAX: frozen
    auto row = slot ? std::make_shared<Row>(*slot)
                    : std::make_shared<Row>(static_cast<std::size_t>(config_.numActions));
    Entry& entry = (*row)[static_cast<std::size_t>(e.action)];
    ++entry.visits;
    entry.rewardSum += e.reward;
    if (e.terminal) {
      ++entry.terminations;
    } else {
      auto it = std::find_if(entry.next.begin(), entry.next.end(),
                             [&](const auto& p) { return p.first == e.next; });
      if (it == entry.next.end()) {
        entry.next.emplace_back(e.next, 1);
      } else {
        ++it->second;
      }
    }
    slot = std::move(row);
    changed = true;
  }
  if (changed) snapshot_.reset();
  return changed;
}

std::shared_ptr<const TabularModel::View> TabularModel::tabularView() const {
  if (snapshot_ == nullptr) snapshot_ = std::make_shared<const Table>(rows_);
  auto v = std::make_shared<View>();
  v->table_ = snapshot_;
  v->config_ = config_;
  v->optimistic_ = config_.optimistic && optimisticOn_;
  return v;
}

int TabularModel::View::visits(const rl_common::State& input, int action) const {
  const auto it = table_->find(input);
  if (it == table_->end()) return 0;
  return (*it->second).at(static_cast<std::size_t>(action)).visits;
}

rl_common::StateActionInfo TabularModel::View::query(const rl_common::State& input,
                                                     int action) const {
  if (action < 0 || action >= config_.numActions) {
    throw std::invalid_argument("TabularModel::View::query(): action " + std::to_string(action) +
                                " out of range");
  }
  if (static_cast<int>(input.size()) < config_.numFeatures) {
    throw std::invalid_argument("TabularModel::View::query(): input has too few features");
  }
  rl_common::StateActionInfo info;
  const auto it = table_->find(input);
  const Entry* e = it == table_->end() ? nullptr : &(*it->second)[static_cast<std::size_t>(action)];
  const int n = e == nullptr ? 0 : e->visits;
  info.known = n >= std::max(config_.m, 1);
  if (n == 0) {
    info.transitions.emplace_back(
        rl_common::State(input.begin(), input.begin() + config_.numFeatures), 1.0);
    info.reward = info.externalReward = kUnknownReward;
  } else {
    const int continuing = n - e->terminations;
    for (const auto& [next, count] : e->next) {
      info.transitions.emplace_back(next, static_cast<double>(count) / continuing);
    }
    if (info.transitions.empty()) {  // always terminal so far: any successor will do
      info.transitions.emplace_back(
          rl_common::State(input.begin(), input.begin() + config_.numFeatures), 1.0);
    }
    info.reward = info.externalReward = static_cast<float>(e->rewardSum / n);
    info.termProb = static_cast<float>(e->terminations) / static_cast<float>(n);
  }
  if (optimistic_ && n < config_.m) {
    info.otherReward = config_.rmax - info.reward;
    info.reward = config_.rmax;
    info.termProb = 1.0f;
  }
  return info;
}

}  // namespace rl_agent
