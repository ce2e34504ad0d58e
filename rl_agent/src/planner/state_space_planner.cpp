#include "rl_agent/planner/state_space_planner.h"

#include <algorithm>
#include <deque>
#include <stdexcept>
#include <string>

#include "rl_agent/planner/feature_ranges.h"
#include "rl_common/stop_request.h"

namespace rl_agent {

StateSpacePlanner::StateSpacePlanner(const Config& config, std::uint64_t seed)
    : config_(config), rng_(seed) {
  if (config.numActions < 1) {
    throw std::invalid_argument("StateSpacePlanner::StateSpacePlanner(): numActions must be >= 1");
  }
  if (!(config.gamma >= 0.0 && config.gamma < 1.0)) {
    throw std::invalid_argument("StateSpacePlanner::StateSpacePlanner(): gamma must be in [0, 1)");
  }
  if (!(config.tolerance > 0.0) || config.maxSteps < 0 || config.maxStates < 1 ||
      config.maxIterations < 1 ||
      !(config.minTransitionProbability >= 0.0 && config.minTransitionProbability < 1.0)) {
    throw std::invalid_argument(
        "StateSpacePlanner::StateSpacePlanner(): need tolerance > 0, maxSteps >= 0, "
        "maxStates >= 1, maxIterations >= 1 and minTransitionProbability in [0, 1)");
  }
  if (config.featMin.size() != config.featMax.size()) {
    throw std::invalid_argument(
        "StateSpacePlanner::StateSpacePlanner(): featMin and featMax must have the same size");
  }
  const auto& bins = config.statesPerDim;
  if (!bins.empty() &&
      (config.featMin.empty() || (bins.size() != 1 && bins.size() != config.featMin.size()))) {
    throw std::invalid_argument(
        "StateSpacePlanner::StateSpacePlanner(): statesPerDim needs the feature ranges and "
        "one entry, or one per feature");
  }
  grid_ = StateGrid(bins, config.featMin, config.featMax);
  for (int f : config.keyFeatures) {
    if (f < 0 || (!config.featMin.empty() && f >= static_cast<int>(config.featMin.size()))) {
      throw std::invalid_argument("StateSpacePlanner::StateSpacePlanner(): key feature " +
                                  std::to_string(f) + " out of range");
    }
    if (static_cast<std::size_t>(f) >= isKey_.size())
      isKey_.resize(static_cast<std::size_t>(f) + 1, 0);
    isKey_[static_cast<std::size_t>(f)] = 1;
  }
}

std::vector<std::pair<rl_common::State, double>> StateSpacePlanner::outcomes(
    const rl_common::StateActionInfo& info) const {
  if (!config_.keyMarginal || isKey_.empty() || info.factored.empty()) {
    return rl_common::expandTransitions(info, config_.minTransitionProbability);
  }
  // Marginalise the non-key features out: each keeps only its most likely value (first of
  // equals, so deterministic), with probability 1.
  rl_common::StateActionInfo keyed;
  keyed.factored = info.factored;
  for (std::size_t j = 0; j < keyed.factored.size(); ++j) {
    auto& dist = keyed.factored[j];
    if ((j < isKey_.size() && isKey_[j]) || dist.size() <= 1) continue;
    auto best = dist.front();
    for (const auto& vq : dist) {
      if (vq.second > best.second) best = vq;
    }
    dist.assign(1, {best.first, 1.0});
  }
  return rl_common::expandTransitions(keyed, config_.minTransitionProbability);
}

rl_common::State StateSpacePlanner::binned(const rl_common::State& s) const {
  return grid_.apply(s);
}

void StateSpacePlanner::setModel(std::shared_ptr<const rl_common::ModelView> model) {
  if (model == nullptr) throw std::invalid_argument("StateSpacePlanner::setModel(): null model");
  model_ = std::move(model);
  ++version_;
}

rl_common::State StateSpacePlanner::keyOf(const rl_common::State& s) const {
  if (config_.keyFeatures.empty()) return s;
  rl_common::State key;
  key.reserve(config_.keyFeatures.size());
  for (int f : config_.keyFeatures) {
    if (static_cast<std::size_t>(f) >= s.size()) {
      throw std::invalid_argument("StateSpacePlanner: key feature " + std::to_string(f) +
                                  " of a state with " + std::to_string(s.size()) + " features");
    }
    key.push_back(s[static_cast<std::size_t>(f)]);
  }
  return key;
}

int StateSpacePlanner::indexOf(const rl_common::State& raw) {
  const rl_common::State s = binned(raw);
  rl_common::State key = keyOf(s);
  const auto it = index_.find(key);
  if (it != index_.end()) return it->second;
  if (states_.size() >= config_.maxStates) return -1;
  const int i = static_cast<int>(states_.size());
  Node n;
  n.key = key;
  n.rep = s;
  n.q.assign(static_cast<std::size_t>(config_.numActions), 0.0);
  if (warm_ != nullptr) {
    const auto w = warm_->index_.find(key);
    if (w != warm_->index_.end() &&
        warm_->states_[static_cast<std::size_t>(w->second)].q.size() == n.q.size()) {
      n.q = warm_->states_[static_cast<std::size_t>(w->second)].q;
    }
  }
  n.depth = config_.maxSteps + 1;
  states_.push_back(std::move(n));
  isRoot_.push_back(0);
  index_.emplace(std::move(key), i);
  return i;
}

bool StateSpacePlanner::inRange(const rl_common::State& s) const {
  constexpr float kEps = 1e-5f;  // as UctPlanner::Config::rangeEpsilon
  return withinFeatureRanges(s, config_.featMin, config_.featMax, kEps);
}

void StateSpacePlanner::addStates(const std::vector<rl_common::State>& states) {
  for (const auto& s : states) {
    const int i = indexOf(s);
    if (i < 0) continue;
    Node& n = states_[static_cast<std::size_t>(i)];
    if (!config_.keyFeatures.empty() && n.rep != binned(s)) {
      n.rep = binned(s);  // a root is its own representative
      n.expanded = false;
      newRoots_ = true;
    }
    if (isRoot_[static_cast<std::size_t>(i)]) continue;
    isRoot_[static_cast<std::size_t>(i)] = 1;
    roots_.push_back(i);
    newRoots_ = true;
  }
}

std::vector<int> StateSpacePlanner::refresh() {
  // Breadth-first from the roots: depths, then predictions for states within maxSteps.
  const bool newVersion = refreshedVersion_ != version_;
  if (!newVersion && !newRoots_) return {};
  for (auto& n : states_) {
    n.depth = config_.maxSteps + 1;
    if (newVersion) n.expanded = false;
  }
  std::deque<int> queue;
  for (int r : roots_) {
    states_[static_cast<std::size_t>(r)].depth = 0;
    queue.push_back(r);
  }
  std::vector<int> changed;
  const auto A = static_cast<std::size_t>(config_.numActions);
  while (!queue.empty()) {
    const int i = queue.front();
    queue.pop_front();
    if (states_[static_cast<std::size_t>(i)].depth >= config_.maxSteps + 1) continue;
    if (!states_[static_cast<std::size_t>(i)].expanded) {
      std::vector<std::vector<Successor>> next(A);
      std::vector<double> reward(A), cont(A);
      const rl_common::State rep = states_[static_cast<std::size_t>(i)].rep;
      for (std::size_t a = 0; a < A; ++a) {
        const auto info = model_->query(rep, static_cast<int>(a));
        reward[a] = info.reward;
        cont[a] = 1.0 - std::clamp(static_cast<double>(info.termProb), 0.0, 1.0);
        double stay = 0.0;  // mass of successors outside the feature ranges
        for (const auto& [s2, p] : outcomes(info)) {
          if (p <= 0.0) continue;
          if (!inRange(s2)) {
            stay += p;
            continue;
          }
          const int j = indexOf(s2);  // may reallocate states_
          if (j >= 0) next[a].push_back({j, p});
        }
        if (stay > 0.0) next[a].push_back({i, stay});
      }
      Node& n = states_[static_cast<std::size_t>(i)];
      n.next = std::move(next);
      n.reward = std::move(reward);
      n.continueProb = std::move(cont);
      n.expanded = true;
      changed.push_back(i);
    }
    const int d = states_[static_cast<std::size_t>(i)].depth;
    if (d >= config_.maxSteps) continue;
    for (const auto& succ : states_[static_cast<std::size_t>(i)].next) {
      for (const auto& s : succ) {
        Node& m = states_[static_cast<std::size_t>(s.state)];
        if (m.depth > d + 1) {
          m.depth = d + 1;
          queue.push_back(s.state);
        }
      }
    }
  }
  refreshedVersion_ = version_;
  newRoots_ = false;
  return changed;
}

long StateSpacePlanner::plan(const rl_common::State& s, const rl_common::PlanningBudget& budget) {
  if (model_ == nullptr) throw std::runtime_error("StateSpacePlanner::plan(): no model");
  addStates({s});
  const std::vector<int> changed = refresh();
  if (!changed.empty()) solved_ = false;
  if (solved_) return 0;  // nothing changed since a solve to convergence
  const long iterations = solve(budget, changed);
  solved_ = budget.rollouts == 0 && budget.deadline == std::chrono::steady_clock::time_point::max();
  return iterations;
}

double StateSpacePlanner::maxQ(int s) const {
  const auto& q = states_[static_cast<std::size_t>(s)].q;
  return *std::max_element(q.begin(), q.end());
}

double StateSpacePlanner::backup(int s, int a) const {
  return backupWith(s, a, [this](int j) { return maxQ(j); });
}

bool StateSpacePlanner::allows(const rl_common::PlanningBudget& budget, long done) const {
  if (done >= config_.maxIterations) return false;
  if (rl_common::stopRequested()) return false;  // SIGINT: end the step now
  if (budget.rollouts > 0 && done >= budget.rollouts) return false;
  if (budget.deadline != std::chrono::steady_clock::time_point::max() && done > 0 &&
      std::chrono::steady_clock::now() >= budget.deadline) {
    return false;
  }
  return true;
}

int StateSpacePlanner::bestAction(const rl_common::State& s) {
  const auto it = index_.find(keyOf(binned(s)));
  if (it == index_.end() || !states_[static_cast<std::size_t>(it->second)].expanded) {
    return rng_.uniformInt(0, config_.numActions - 1);
  }
  const auto& q = states_[static_cast<std::size_t>(it->second)].q;
  const double best = *std::max_element(q.begin(), q.end());
  std::vector<int> ties;
  for (int a = 0; a < config_.numActions; ++a) {
    if (q[static_cast<std::size_t>(a)] >= best - kTieTolerance) ties.push_back(a);
  }
  return ties[static_cast<std::size_t>(rng_.uniformInt(0, static_cast<int>(ties.size()) - 1))];
}

std::vector<double> StateSpacePlanner::qValues(const rl_common::State& s) const {
  const auto it = index_.find(keyOf(binned(s)));
  if (it == index_.end()) return {};
  return states_[static_cast<std::size_t>(it->second)].q;
}

double StateSpacePlanner::value(const rl_common::State& s) const {
  const auto it = index_.find(keyOf(binned(s)));
  return it == index_.end() ? 0.0 : maxQ(it->second);
}

std::vector<rl_common::State> StateSpacePlanner::expandedStates() const {
  std::vector<rl_common::State> out;
  for (const auto& n : states_) {
    if (n.expanded) out.push_back(n.key);
  }
  return out;
}

std::size_t StateSpacePlanner::numExpanded() const {
  return static_cast<std::size_t>(
      std::count_if(states_.begin(), states_.end(), [](const Node& n) { return n.expanded; }));
}

}  // namespace rl_agent
