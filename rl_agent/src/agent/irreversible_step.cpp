#include "rl_agent/agent/irreversible_step.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "rl_agent/model/distribution.h"

namespace rl_agent {

namespace {

/// A feature counts as given back when some action's prediction puts at least this
/// probability on its old value: only changes the model is sure no action undoes are one-way
/// (the forest's averaged predictions rarely give a move's sensors their old value with
/// probability one half, and a move taken for one-way would be put off).
constexpr double kRestoreProbability = 0.05;

/// P(feature j of the next state == value) under one prediction.
double featureProbability(const rl_common::StateActionInfo& info, std::size_t j, float value) {
  if (!info.factored.empty()) {
    return j < info.factored.size() ? probabilityOf(info.factored[j], value) : 0.0;
  }
  double p = 0.0;
  for (const auto& [s, q] : info.transitions) {
    if (j < s.size() && s[j] == value) p += q;
  }
  return p;
}

}  // namespace

std::vector<std::size_t> unrestorableFeatures(const rl_common::ModelView& model,
                                              const rl_common::State& from,
                                              const rl_common::State& to, int numActions) {
  std::vector<std::size_t> changed;
  if (from.size() != to.size()) return changed;
  for (std::size_t j = 0; j < from.size(); ++j) {
    if (from[j] != to[j]) changed.push_back(j);
  }
  for (int b = 0; b < numActions && !changed.empty(); ++b) {
    const auto info = model.query(to, b);
    if (!info.known) return {};  // no data on some action from `to`: the model cannot tell
    changed.erase(std::remove_if(changed.begin(), changed.end(),
                                 [&](std::size_t j) {
                                   return featureProbability(info, j, from[j]) >=
                                          kRestoreProbability;
                                 }),
                  changed.end());
  }
  return changed;
}

bool OneWaySignature::matches(const rl_common::State& s) const {
  std::size_t held = 0;
  for (const Change& c : changes) {
    if (c.feature < s.size() && s[c.feature] == c.from) ++held;
  }
  return 2 * held > changes.size();
}

DeferringView::DeferringView(std::shared_ptr<const rl_common::ModelView> base,
                             std::shared_ptr<const std::vector<OneWaySignature>> signatures)
    : base_(std::move(base)), signatures_(std::move(signatures)) {
  if (!base_ || !signatures_) throw std::invalid_argument("DeferringView: null model or list");
}

rl_common::StateActionInfo DeferringView::query(const rl_common::State& input, int action) const {
  rl_common::StateActionInfo info = base_->query(input, action);
  if (applying(input, action) != nullptr) end(info);
  return info;
}

void DeferringView::refresh(const rl_common::State& input, int action,
                            rl_common::StateActionInfo& info,
                            rl_common::PredictionStamp& stamp) const {
  if (applying(input, action) != nullptr) {
    info = base_->query(input, action);
    end(info);
    stamp.clear();
    return;
  }
  base_->refresh(input, action, info, stamp);
}

const OneWaySignature* DeferringView::applying(const rl_common::State& input, int action) const {
  for (const auto& sig : *signatures_) {
    if (sig.appliesTo(input, action)) return &sig;
  }
  return nullptr;
}

void DeferringView::end(rl_common::StateActionInfo& info) {
  info.termProb = 1.0f;
  info.reward = info.externalReward = info.varianceReward = info.noveltyReward = info.otherReward =
      0.0f;
}

StepDeferral::StepDeferral(long steps, long maxRegions)
    : steps_(steps),
      maxRegions_(maxRegions),
      signatures_(std::make_shared<const std::vector<OneWaySignature>>()) {
  if (steps < 0) {
    throw std::invalid_argument("StepDeferral: steps must be >= 0, got " + std::to_string(steps));
  }
  if (maxRegions < 0) {
    throw std::invalid_argument("StepDeferral: maxRegions must be >= 0, got " +
                                std::to_string(maxRegions));
  }
}

void StepDeferral::observe(const rl_common::ModelView& model, const rl_common::State& previous,
                           int action, const rl_common::State& current, int numActions) {
  ++step_;
  ++inRegion_;
  if (previous.empty()) {
    inRegion_ = 0;
    candidates_.clear();  // a new episode: what the last one left undone says nothing
    return;
  }
  // The states before this step (previous last), for the share test below.
  past_.push_back(previous);
  if (past_.size() > kPastStates) past_.pop_front();
  // A real step that undoes most of a candidate's or signature's changes shows it was not
  // one-way: the model took it for one while it knew too little.
  const auto undone = [&](const OneWaySignature& sig) {
    std::size_t n = 0;
    for (const auto& c : sig.changes) {
      if (c.feature < previous.size() && c.feature < current.size() &&
          previous[c.feature] == c.to && current[c.feature] == c.from) {
        ++n;
      }
    }
    return 2 * n > sig.changes.size();
  };
  candidates_.erase(std::remove_if(candidates_.begin(), candidates_.end(),
                                   [&](const Candidate& c) { return undone(c.signature); }),
                    candidates_.end());
  if (std::any_of(signatures_->begin(), signatures_->end(), undone)) {
    auto kept = std::make_shared<std::vector<OneWaySignature>>();
    for (const auto& sig : *signatures_) {
      if (!undone(sig)) kept->push_back(sig);
    }
    signatures_ = std::move(kept);
  }
  // Candidates that stayed undone for the window, and that the model, which has learned more
  // since, still cannot undo, become signatures; the region behind them began at their step.
  while (!candidates_.empty() && step_ - candidates_.front().step >= kConfirmSteps) {
    Candidate c = std::move(candidates_.front());
    candidates_.pop_front();
    if (unrestorableFeatures(model, c.from, c.to, numActions).empty()) continue;
    if (step_ - c.step < inRegion_) ++regions_;  // a region begins at the confirmed step
    inRegion_ = std::min(inRegion_, step_ - c.step);
    const bool known = std::any_of(signatures_->begin(), signatures_->end(),
                                   [&](const auto& s) { return s == c.signature; });
    if (!known) {
      auto next = std::make_shared<std::vector<OneWaySignature>>(*signatures_);
      next->push_back(std::move(c.signature));
      signatures_ = std::move(next);
    }
  }
  if (oneWay(previous, action)) {  // a known one-way step just made: a new region
    inRegion_ = 0;
    ++regions_;
  }
  // Most steps change too few features to be a candidate: no model queries for them.
  std::size_t changed = 0;
  for (std::size_t j = 0; j < previous.size() && j < current.size(); ++j) {
    changed += previous[j] != current[j];
  }
  if (changed < kMinChanges) return;
  const auto features = unrestorableFeatures(model, previous, current, numActions);
  if (features.size() < kMinChanges) return;
  Candidate c{previous, current, step_, {}};
  c.signature.action = action;
  for (std::size_t j : features) c.signature.changes.push_back({j, previous[j], current[j]});
  // A pattern the agent met almost everywhere before (the step's own state excluded) does not
  // say where the step happens.
  const std::size_t held = static_cast<std::size_t>(
      std::count_if(past_.begin(), past_.end() - 1,
                    [&](const rl_common::State& p) { return c.signature.matches(p); }));
  if (static_cast<double>(held) > kMaxShare * static_cast<double>(past_.size() - 1)) return;
  candidates_.push_back(std::move(c));
  if (candidates_.size() > kMaxCandidates) candidates_.pop_front();
}

std::shared_ptr<const rl_common::ModelView> StepDeferral::planningView(
    std::shared_ptr<const rl_common::ModelView> base) const {
  if (!active()) return base;
  return std::make_shared<DeferringView>(std::move(base), signatures_);
}

std::function<
    std::shared_ptr<const rl_common::ModelView>(std::shared_ptr<const rl_common::ModelView>)>
StepDeferral::viewFilter() const {
  if (!active()) return nullptr;
  return [signatures = signatures_](std::shared_ptr<const rl_common::ModelView> base) {
    return std::shared_ptr<const rl_common::ModelView>(
        std::make_shared<DeferringView>(std::move(base), signatures));
  };
}

bool StepDeferral::oneWay(const rl_common::State& s, int action) const {
  return std::any_of(signatures_->begin(), signatures_->end(),
                     [&](const auto& sig) { return sig.appliesTo(s, action); });
}

int StepDeferral::choose(const rl_common::State& s, int chosen, const std::vector<double>& q,
                         rl_common::Random& rng) {
  const int numActions = static_cast<int>(q.size());
  if (!active() || chosen < 0 || chosen >= numActions || !oneWay(s, chosen)) return chosen;
  std::vector<int> best;
  double bestQ = 0.0;
  for (int a = 0; a < numActions; ++a) {
    if (a == chosen || oneWay(s, a)) continue;
    if (best.empty() || q[a] > bestQ) {
      best.assign(1, a);
      bestQ = q[a];
    } else if (q[a] == bestQ) {
      best.push_back(a);
    }
  }
  if (best.empty()) return chosen;
  ++deferred_;
  return best.size() == 1
             ? best[0]
             : best[static_cast<std::size_t>(rng.uniformInt(0, static_cast<int>(best.size()) - 1))];
}

}  // namespace rl_agent
