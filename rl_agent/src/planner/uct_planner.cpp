#include "rl_agent/planner/uct_planner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "rl_agent/planner/feature_ranges.h"
#include "rl_common/stop_request.h"

namespace rl_agent {

using rl_common::State;
using rl_common::StateActionInfo;

namespace {

std::invalid_argument badConfig(const std::string& what) {
  return std::invalid_argument("UctPlanner::UctPlanner(): " + what);
}

bool allFinite(const State& s) {
  return std::all_of(s.begin(), s.end(), [](float x) { return std::isfinite(x); });
}

// ln(n) for a visit count: a table for the counts UCB meets most (the same values as
// std::log, which each selection would otherwise call).
double logOfCount(long n) {
  constexpr long kTable = 4096;
  static const std::vector<double> table = [] {
    std::vector<double> t(kTable);
    for (long k = 1; k < kTable; ++k)
      t[static_cast<std::size_t>(k)] = std::log(static_cast<double>(k));
    return t;
  }();
  return n > 0 && n < kTable ? table[static_cast<std::size_t>(n)]
                             : std::log(static_cast<double>(n));
}

}  // namespace

UctPlanner::UctPlanner(const Config& config, std::uint64_t seed) : config_(config), rng_(seed) {
  const Config& c = config_;
  if (c.numActions < 1) {
    throw badConfig("numActions must be at least 1 (got " + std::to_string(c.numActions) + ")");
  }
  if (!(c.gamma >= 0.0 && c.gamma < 1.0)) {
    throw badConfig("gamma must be in [0, 1) (got " + std::to_string(c.gamma) + ")");
  }
  if (!(c.lambda >= 0.0 && c.lambda <= 1.0)) {
    throw badConfig("lambda must be in [0, 1] (got " + std::to_string(c.lambda) + ")");
  }
  if (!std::isfinite(c.rewardRange)) {
    throw badConfig("rewardRange must be finite");
  }
  if (c.maxDepth < 1) {
    throw badConfig("maxDepth must be at least 1 (got " + std::to_string(c.maxDepth) + ")");
  }
  if (c.featMin.size() != c.featMax.size()) {
    throw badConfig("featMin and featMax must have the same size (got " +
                    std::to_string(c.featMin.size()) + " and " + std::to_string(c.featMax.size()) +
                    ")");
  }
  for (std::size_t i = 0; i < c.featMin.size(); ++i) {
    if (!std::isfinite(c.featMin[i]) || !std::isfinite(c.featMax[i]) ||
        c.featMin[i] > c.featMax[i]) {
      throw badConfig("featMin/featMax of feature " + std::to_string(i) +
                      " must be finite with min <= max");
    }
  }
  if (!c.statesPerDim.empty()) {
    if (c.featMin.empty()) {
      throw badConfig("statesPerDim needs featMin and featMax");
    }
    if (c.statesPerDim.size() != 1 && c.statesPerDim.size() != c.featMin.size()) {
      throw badConfig("statesPerDim must have one entry or one per feature (got " +
                      std::to_string(c.statesPerDim.size()) + " for " +
                      std::to_string(c.featMin.size()) + " features)");
    }
    for (int n : c.statesPerDim) {
      if (n < 0) {
        throw badConfig("statesPerDim entries must be >= 0 (got " + std::to_string(n) + ")");
      }
    }
    if (config_.statesPerDim.size() == 1) {
      config_.statesPerDim.assign(c.featMin.size(), config_.statesPerDim.front());
    }
    grid_ = StateGrid(config_.statesPerDim, c.featMin, c.featMax);
    discretising_ = grid_.bins();
  }
  if (c.history < 0) {
    throw badConfig("history must be >= 0 (got " + std::to_string(c.history) + ")");
  }
  if (!(c.rangeEpsilon >= 0.0f)) {
    throw badConfig("rangeEpsilon must be >= 0");
  }
  if (c.maxStates < 1) {
    throw badConfig("maxStates must be at least 1");
  }
  if (c.maxCachedPredictions < 1) {
    throw badConfig("maxCachedPredictions must be at least 1");
  }
  if (!(c.minOutcomeProbability >= 0.0 && c.minOutcomeProbability <= 1.0)) {
    throw badConfig("minOutcomeProbability must be in [0, 1]");
  }
  if (!(c.ucbC >= 0.0) || !std::isfinite(c.ucbC)) {
    throw badConfig("ucbC must be finite and >= 0 (got " + std::to_string(c.ucbC) + ")");
  }
  ucbConstant_ = 2.0 * std::max(c.rewardRange, 1.0) / (1.0 - c.gamma);
  trackPath_ = c.countPathVisits || c.bonusOncePerPath;
  rootHistory_.assign(static_cast<std::size_t>(c.history), -1);
}

void UctPlanner::setUcbBound(UcbBound bound, double c) {
  if (!(c >= 0.0) || !std::isfinite(c)) {
    throw std::invalid_argument("UctPlanner::setUcbBound(): c must be finite and >= 0 (got " +
                                std::to_string(c) + ")");
  }
  config_.ucbBound = bound;
  config_.ucbC = c;
}

void UctPlanner::setModel(std::shared_ptr<const rl_common::ModelView> model) {
  if (!model) {
    throw std::invalid_argument("UctPlanner::setModel(): model is null");
  }
  model_ = std::move(model);
  ++modelVersion_;
}

long UctPlanner::plan(const State& s, const rl_common::PlanningBudget& budget) {
  if (!model_) {
    throw std::runtime_error("UctPlanner::plan(): no model; call setModel() first");
  }
  validateState(s, "UctPlanner::plan()");
  const auto noDeadline = std::chrono::steady_clock::time_point::max();
  if (budget.rollouts < 0) {
    throw std::invalid_argument("UctPlanner::plan(): negative rollout budget " +
                                std::to_string(budget.rollouts));
  }
  if (budget.rollouts == 0 && budget.deadline == noDeadline) {
    throw std::invalid_argument("UctPlanner::plan(): budget has neither rollouts nor deadline");
  }
  long done = 0;
  while (true) {
    rollout(s);
    ++done;
    if (budget.rollouts > 0 && done >= budget.rollouts) {
      break;
    }
    if (budget.deadline != noDeadline && std::chrono::steady_clock::now() >= budget.deadline) {
      break;
    }
    if (rl_common::stopRequested()) break;  // SIGINT: end the step now, not after the budget
  }
  return done;
}

int UctPlanner::bestAction(const State& s) {
  const Record* found = find(s, "UctPlanner::bestAction()");
  if (found == nullptr) {
    return rng_.uniformInt(0, config_.numActions - 1);
  }
  const std::vector<double>& q = found->q;
  const double best = *std::max_element(q.begin(), q.end());
  int ties = 0;
  for (double v : q) {
    ties += v >= best - kTieTolerance ? 1 : 0;
  }
  int pick = ties > 1 ? rng_.uniformInt(0, ties - 1) : 0;
  for (int a = 0; a < config_.numActions; ++a) {
    if (q[a] >= best - kTieTolerance && pick-- == 0) {
      return a;
    }
  }
  return 0;  // not reached
}

void UctPlanner::setActionHistory(const std::vector<int>& lastActions) {
  if (lastActions.size() > rootHistory_.size()) {
    throw std::invalid_argument(
        "UctPlanner::setActionHistory(): " + std::to_string(lastActions.size()) +
        " actions for a history of " + std::to_string(rootHistory_.size()));
  }
  for (int a : lastActions) {
    if (a < -1 || a >= config_.numActions) {
      throw std::invalid_argument("UctPlanner::setActionHistory(): action " + std::to_string(a) +
                                  " out of range [0, " + std::to_string(config_.numActions) + ")");
    }
  }
  const std::size_t missing = rootHistory_.size() - lastActions.size();
  std::fill(rootHistory_.begin(), rootHistory_.begin() + static_cast<long>(missing), -1);
  std::copy(lastActions.begin(), lastActions.end(),
            rootHistory_.begin() + static_cast<long>(missing));
}

State UctPlanner::discretize(const State& s) const {
  validateState(s, "UctPlanner::discretize()");
  State out;
  appendDiscretized(s, out);
  return out;
}

State UctPlanner::modelInput(const State& s) const {
  validateState(s, "UctPlanner::modelInput()");
  State key;
  buildKey(s, rootHistory_, key);
  return key;
}

std::vector<double> UctPlanner::qValues(const State& s) const {
  const Record* r = find(s, "UctPlanner::qValues()");
  return r ? r->q : std::vector<double>();
}

void UctPlanner::forEachRecord(
    const std::function<void(const State& key, const std::vector<double>& q, long visits)>& f)
    const {
  for (const Record& r : records_) {
    if (r.live) f(r.key, r.q, cappedVisits(r));
  }
}

long UctPlanner::stateVisits(const State& s) const {
  const Record* r = find(s, "UctPlanner::stateVisits()");
  return r ? cappedVisits(*r) : 0;
}

long UctPlanner::actionVisits(const State& s, int action) const {
  if (action < 0 || action >= config_.numActions) {
    throw std::invalid_argument("UctPlanner::actionVisits(): action " + std::to_string(action) +
                                " out of range");
  }
  const Record* r = find(s, "UctPlanner::actionVisits()");
  return r ? cappedActionVisits(*r, action) : 0;
}

// ---- rollouts ----

void UctPlanner::rollout(const State& root) {
  ++stamp_;
  actual_ = root;
  history_ = rootHistory_;
  path_.clear();
  double g = 0.0;  // the value returned to the parent
  try {
    for (int depth = 0;; ++depth) {
      buildKey(actual_, history_, key_);
      Record& rec = touch(key_);
      if (depth >= config_.maxDepth) {
        g = maxQ(rec);
        break;
      }
      const int a = selectUcbAction(rec);
      if (trackPath_) ++rec.pathChosen[a];
      const double alpha = 10.0 / (static_cast<double>(rec.actionVisits[a]) + 10.0);
      const StateActionInfo& info = prediction(rec, key_, a);
      const double p = info.termProb;
      const bool terminal = p >= 1.0 || (p > 0.0 && rng_.bernoulli(p));
      double reward = info.reward;
      if (config_.bonusOncePerPath && rec.pathChosen[a] > 1) {
        // This state-action was tried earlier on this rollout: what it had to teach was
        // learned then, so only its external reward counts now.
        reward -= static_cast<double>(info.varianceReward) + info.noveltyReward + info.otherReward;
      }
      path_.push_back(Step{&rec, a, reward, alpha, terminal, rec.onPath == 0});
      if (terminal) {
        break;
      }
      ++rec.onPath;
      sampleSuccessor(info);  // into next_, from actual_ and key_
      if (!history_.empty()) {
        std::rotate(history_.begin(), history_.begin() + 1, history_.end());
        history_.back() = a;
      }
      actual_.swap(next_);
    }
  } catch (...) {
    clearPath();
    throw;
  }

  const double lambda = config_.lambda;
  for (std::size_t i = path_.size(); i-- > 0;) {
    const Step& st = path_[i];
    Record& rec = *st.record;
    double& q = rec.q[st.action];
    if (st.terminal) {
      ++rec.visits;
      ++rec.actionVisits[st.action];
      q += st.alpha * (st.reward - q);
      g = st.reward;
      continue;
    }
    const double target = st.reward + config_.gamma * g;
    if (st.first) {
      ++rec.visits;
      ++rec.actionVisits[st.action];
      q += st.alpha * (target - q);
    }
    g = lambda < 1.0 ? lambda * target + (1.0 - lambda) * maxQ(rec) : target;
  }
  clearPath();
}

void UctPlanner::clearPath() {
  for (const Step& st : path_) {
    st.record->onPath = 0;
    if (trackPath_) st.record->pathChosen[st.action] = 0;
  }
}

void UctPlanner::sampleSuccessor(const StateActionInfo& info) {
  const auto& tr = info.transitions;
  const std::size_t n = actual_.size();
  if (!info.factored.empty()) {
    // Factored prediction: sample each feature from its own distribution.
    if (info.factored.size() < n) {
      throw std::runtime_error("UctPlanner::plan(): the model predicted " +
                               std::to_string(info.factored.size()) +
                               " feature distributions for a state of " + std::to_string(n));
    }
    next_.resize(n);
    for (std::size_t j = 0; j < n; ++j) {
      const auto& dist = info.factored[j];
      float value = actual_[j];  // an empty distribution keeps the feature
      if (dist.size() == 1) {
        value = dist.front().first;
      } else if (!dist.empty() && config_.minOutcomeProbability > 0.0) {
        value = samplePlausible(dist);
      } else if (!dist.empty()) {
        double u = rng_.uniform();
        for (const auto& [v, p] : dist) {
          value = v;
          u -= p;
          if (u < 0.0) break;
        }
      }
      next_[j] = value;
    }
    if (config_.trackActual && discretising_) {
      for (std::size_t j = 0; j < n; ++j) next_[j] = actual_[j] + (next_[j] - key_[j]);
    }
    if (!inRange(next_)) next_ = actual_;
    return;
  }
  const State* chosen = nullptr;
  if (tr.size() == 1) {
    chosen = &tr.front().first;
  } else if (tr.size() > 1) {
    double total = 0.0;
    for (const auto& t : tr) {
      total += std::max(t.second, 0.0);
    }
    if (total > 0.0) {
      double u = rng_.uniform() * total;
      for (const auto& t : tr) {
        if (t.second <= 0.0) {
          continue;
        }
        chosen = &t.first;
        u -= t.second;
        if (u < 0.0) {
          break;
        }
      }
    }
  }
  if (chosen == nullptr) {  // no prediction: stay
    next_ = actual_;
    return;
  }
  if (chosen->size() < n) {
    throw std::runtime_error("UctPlanner::plan(): the model predicted a next state of " +
                             std::to_string(chosen->size()) + " features for a state of " +
                             std::to_string(n));
  }
  next_.assign(chosen->begin(), chosen->begin() + static_cast<long>(n));
  if (config_.trackActual && discretising_) {
    // key_ starts with disc(actual_): carry the continuous offset along.
    for (std::size_t j = 0; j < n; ++j) {
      next_[j] = actual_[j] + (next_[j] - key_[j]);
    }
  }
  if (!inRange(next_)) {
    next_ = actual_;
  }
}

float UctPlanner::samplePlausible(const rl_common::FeatureDistribution& dist) {
  const double cut = config_.minOutcomeProbability;
  double total = 0.0;
  const std::pair<float, double>* best = &dist.front();
  for (const auto& entry : dist) {
    if (entry.second >= cut) total += entry.second;
    if (entry.second > best->second) best = &entry;
  }
  double u = rng_.uniform() * total;  // one draw, as without the cut
  if (total <= 0.0) return best->first;
  float value = best->first;
  for (const auto& [v, p] : dist) {
    if (p < cut) continue;
    value = v;
    u -= p;
    if (u < 0.0) break;
  }
  return value;
}

bool UctPlanner::inRange(const State& s) const {
  if (!allFinite(s)) {
    return false;
  }
  return withinFeatureRanges(s, config_.featMin, config_.featMax, config_.rangeEpsilon);
}

void UctPlanner::appendDiscretized(const State& s, State& out) const {
  if (!discretising_) {
    out.insert(out.end(), s.begin(), s.end());
    return;
  }
  for (std::size_t i = 0; i < s.size(); ++i) out.push_back(grid_.bin(i, s[i]));
}

void UctPlanner::buildKey(const State& actual, const std::vector<int>& history, State& key) const {
  key.clear();
  appendDiscretized(actual, key);
  for (int h : history) {
    const std::size_t start = key.size();
    key.resize(start + static_cast<std::size_t>(config_.numActions), 0.0f);
    if (h >= 0) {
      key[start + static_cast<std::size_t>(h)] = 1.0f;
    }
  }
}

UctPlanner::Record& UctPlanner::touch(const State& key) {
  const std::uint64_t h = StateHash()(key);
  const std::uint32_t found =
      index_.find(h, [&](std::uint32_t slot) { return records_[slot].key == key; });
  Record* rp = nullptr;
  if (found == StateIndex::kNone) {
    // Make room: evict least recently touched records, but none touched by this rollout.
    while (index_.size() >= config_.maxStates && recent_.tail != nullptr &&
           recent_.tail->lastTouched != stamp_) {
      evictRecord(*recent_.tail);
    }
    if (freeSlots_.empty()) {
      records_.emplace_back();
      records_.back().slot = static_cast<std::uint32_t>(records_.size() - 1);
      rp = &records_.back();
    } else {
      rp = &records_[freeSlots_.back()];
      freeSlots_.pop_back();
    }
    Record& r = *rp;
    r.q.resize(static_cast<std::size_t>(config_.numActions));
    for (double& q : r.q) {
      q = rng_.uniform(0.0, 0.01);
    }
    r.actionVisits.assign(static_cast<std::size_t>(config_.numActions), 1);
    if (trackPath_) {
      r.pathChosen.assign(static_cast<std::size_t>(config_.numActions), 0);
    }
    r.visits = 1;
    r.version = modelVersion_;
    r.onPath = 0;
    r.key = key;
    r.hash = h;
    r.live = true;
    index_.insert(h, r.slot);
  } else {
    Record& r = records_[found];
    rp = &r;
    if (r.version != modelVersion_) {
      r.visits = cappedVisits(r);
      for (int a = 0; a < config_.numActions; ++a) {
        r.actionVisits[a] = cappedActionVisits(r, a);
      }
      r.version = modelVersion_;
    }
    unlink(recent_, &Record::recent, r);
  }
  Record& r = *rp;
  r.lastTouched = stamp_;
  pushFront(recent_, &Record::recent, r);
  return r;
}

const UctPlanner::Record* UctPlanner::find(const State& s, const char* where) const {
  validateState(s, where);
  State key;
  buildKey(s, rootHistory_, key);
  const std::uint32_t slot =
      index_.find(StateHash()(key), [&](std::uint32_t i) { return records_[i].key == key; });
  return slot == StateIndex::kNone ? nullptr : &records_[slot];
}

int UctPlanner::selectUcbAction(const Record& r) {
  // Choices made at this state earlier on the rollout's path count as visits (0 on the first).
  long onPath = 0;
  if (r.onPath > 0 && config_.countPathVisits) {
    for (int k : r.pathChosen) onPath += k;
  }
  const double logN = logOfCount(r.visits + onPath);
  values_.resize(static_cast<std::size_t>(config_.numActions));
  double best = -std::numeric_limits<double>::infinity();
  int ties = 0;
  // Normalized bound: Q rescaled to [0, 1] by this state's own Q range, so the bonus term
  // weighs against the returns the planner really sees, whatever their scale.
  double qLow = 0.0, qScale = 1.0, c = ucbConstant_;
  if (config_.ucbBound == UcbBound::Normalized) {
    const auto [lo, hi] = std::minmax_element(r.q.begin(), r.q.end());
    qLow = *lo;
    qScale = *hi - *lo > 1e-12 ? 1.0 / (*hi - *lo) : 0.0;
    c = config_.ucbC;
  }
  for (int a = 0; a < config_.numActions; ++a) {
    const long n = r.actionVisits[a] + (onPath > 0 ? r.pathChosen[a] : 0);
    const double v = (r.q[a] - qLow) * qScale + c * std::sqrt(logN / static_cast<double>(n));
    values_[a] = v;
    if (v > best) {
      best = v;
      ties = 1;
    } else if (v == best) {
      ++ties;
    }
  }
  // Unlike the original (std::max_element: the first maximum), exact ties go to a random one.
  int pick = ties > 1 ? rng_.uniformInt(0, ties - 1) : 0;
  for (int a = 0; a < config_.numActions; ++a) {
    if (values_[a] == best && pick-- == 0) {
      return a;
    }
  }
  // Only NaN values (an invalid model reward) get here.
  throw std::runtime_error("UctPlanner::plan(): no action has a valid UCB value (NaN reward?)");
}

const StateActionInfo& UctPlanner::prediction(Record& r, const State& key, int action) {
  const bool isNew = r.predictions.empty() || r.predictions[action].version == 0;
  if (isNew || r.predictions[action].version != modelVersion_) {
    if (isNew) {
      // Make room: drop the predictions used least recently (possibly r's own others).
      while (cachedPredictions_ >= config_.maxCachedPredictions && cachedRecent_.tail != nullptr) {
        dropPredictions(*cachedRecent_.tail);
      }
    }
    if (r.predictions.empty()) {
      r.predictions.resize(static_cast<std::size_t>(config_.numActions));
    }
    Prediction& p = r.predictions[action];
    // Across model versions only what changed is recomputed (the view's refresh()).
    model_->refresh(key, action, p.info, p.stamp);
    if (p.version == 0) {
      ++r.cached;
      ++cachedPredictions_;
    }
    p.version = modelVersion_;
  }
  // r is in cachedRecent_ exactly when it holds predictions: move it (back) to the front.
  if (r.cachedRecent.prev != nullptr || cachedRecent_.head == &r) {
    unlink(cachedRecent_, &Record::cachedRecent, r);
  }
  pushFront(cachedRecent_, &Record::cachedRecent, r);
  return r.predictions[action].info;
}

void UctPlanner::evictRecord(Record& r) {
  dropPredictions(r);
  unlink(recent_, &Record::recent, r);
  index_.erase(r.hash, r.slot);
  r.live = false;
  freeSlots_.push_back(r.slot);
}

void UctPlanner::dropPredictions(Record& r) {
  if (r.cached == 0) {
    return;
  }
  unlink(cachedRecent_, &Record::cachedRecent, r);
  cachedPredictions_ -= static_cast<std::size_t>(r.cached);
  r.cached = 0;
  std::vector<Prediction>().swap(r.predictions);  // frees the transitions
}

void UctPlanner::unlink(List& list, Links Record::*links, Record& r) {
  Links& l = r.*links;
  (l.prev ? (l.prev->*links).next : list.head) = l.next;
  (l.next ? (l.next->*links).prev : list.tail) = l.prev;
  l.prev = l.next = nullptr;
}

void UctPlanner::pushFront(List& list, Links Record::*links, Record& r) {
  Links& l = r.*links;
  l.prev = nullptr;
  l.next = list.head;
  (list.head ? (list.head->*links).prev : list.tail) = &r;
  list.head = &r;
}

void UctPlanner::validateState(const State& s, const char* where) const {
  if (s.empty()) {
    throw std::invalid_argument(std::string(where) + ": empty state");
  }
  if (!config_.featMin.empty() && s.size() != config_.featMin.size()) {
    throw std::invalid_argument(std::string(where) + ": state has " + std::to_string(s.size()) +
                                " features, the configuration " +
                                std::to_string(config_.featMin.size()));
  }
  if (!allFinite(s)) {
    throw std::invalid_argument(std::string(where) + ": state has a non-finite feature");
  }
}

long UctPlanner::cappedVisits(const Record& r) const {
  return r.version == modelVersion_ ? r.visits : std::min(r.visits, kVisitCap * config_.numActions);
}

long UctPlanner::cappedActionVisits(const Record& r, int action) const {
  return r.version == modelVersion_ ? r.actionVisits[action]
                                    : std::min(r.actionVisits[action], kVisitCap);
}

double UctPlanner::maxQ(const Record& r) { return *std::max_element(r.q.begin(), r.q.end()); }

}  // namespace rl_agent
