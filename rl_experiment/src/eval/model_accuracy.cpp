#include "rl_experiment/eval/model_accuracy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

namespace rl_experiment {

double variationalDistance(const StateDistribution& p, const StateDistribution& q) {
  std::map<rl_common::State, double> diff;
  for (const auto& [s, prob] : p) diff[s] += prob;
  for (const auto& [s, prob] : q) diff[s] -= prob;
  double sum = 0.0;
  for (const auto& entry : diff) sum += std::fabs(entry.second);
  return 0.5 * sum;
}

double variationalDistance(const StateDistribution& p, const rl_common::StateActionInfo& q) {
  if (q.factored.empty()) return variationalDistance(p, q.transitions);
  std::map<rl_common::State, double> merged;
  for (const auto& [s, prob] : p) merged[s] += prob;
  double qTotal = 1.0;
  for (const auto& dist : q.factored) {
    double sum = 0.0;
    for (const auto& entry : dist) sum += entry.second;
    qTotal *= sum;
  }
  double inside = 0.0;  // Q's mass on P's support
  double diff = 0.0;
  for (const auto& [s, prob] : merged) {
    const double qs = rl_common::transitionProbability(q, s);
    inside += qs;
    diff += std::fabs(prob - qs);
  }
  return 0.5 * (diff + std::max(0.0, qTotal - inside));
}

double marginalDistance(const StateDistribution& p, const rl_common::StateActionInfo& q,
                        std::size_t feature) {
  std::map<float, double> diff;
  for (const auto& [s, prob] : p) {
    if (feature >= s.size()) {
      throw std::invalid_argument("marginalDistance(): feature " + std::to_string(feature) +
                                  " out of range");
    }
    diff[s[feature]] += prob;
  }
  if (!q.factored.empty()) {
    if (feature >= q.factored.size()) {
      throw std::invalid_argument("marginalDistance(): the prediction has no feature " +
                                  std::to_string(feature));
    }
    for (const auto& [v, prob] : q.factored[feature]) diff[v] -= prob;
  } else {
    for (const auto& [s, prob] : q.transitions) {
      if (feature < s.size()) diff[s[feature]] -= prob;
    }
  }
  double sum = 0.0;
  for (const auto& entry : diff) sum += std::fabs(entry.second);
  return 0.5 * sum;
}

StateDistribution nextStateDistribution(const std::vector<rl_common::Outcome>& outcomes) {
  StateDistribution out;
  out.reserve(outcomes.size());
  for (const auto& o : outcomes) out.emplace_back(o.next, o.probability);
  return out;
}

ModelAccuracy::ModelAccuracy(const rl_common::TrueModel& truth, int numActions)
    : truth_(truth), numActions_(numActions), states_(truth.reachableStates()) {
  if (states_.empty() || numActions < 1) {
    throw std::invalid_argument(
        "ModelAccuracy::ModelAccuracy(): need reachable states and at least one action");
  }
  const std::size_t pairs = states_.size() * static_cast<std::size_t>(numActions);
  if (pairs <= kMaxKept) kept_.resize(pairs);
}

const ModelAccuracy::Kept& ModelAccuracy::measure(const rl_common::ModelView& model,
                                                  std::size_t state, int action) {
  Kept& k =
      kept_.empty()
          ? scratch_
          : kept_[state * static_cast<std::size_t>(numActions_) + static_cast<std::size_t>(action)];
  if (kept_.empty()) k = Kept();  // nothing kept: measure afresh
  if (k.measured == measurement_) return k;
  const rl_common::State& s = states_[state];
  if (!k.truthKnown) {
    k.truth = nextStateDistribution(truth_.transitions(s, action));
    k.truthKnown = true;
  }
  model.refresh(s, action, k.prediction, k.stamp);
  k.joint = variationalDistance(k.truth, k.prediction);
  const std::size_t d = s.size();
  k.marginal.resize(d);
  for (std::size_t j = 0; j < d; ++j) k.marginal[j] = marginalDistance(k.truth, k.prediction, j);
  k.measured = measurement_;
  return k;
}

double ModelAccuracy::evaluate(const rl_common::ModelView& model, rl_common::Random& rng,
                               int samples) {
  if (samples < 1) {
    throw std::invalid_argument("ModelAccuracy::evaluate(): samples must be >= 1");
  }
  return evaluateDetailed(model, rng, samples).joint;
}

ModelAccuracy::Report ModelAccuracy::evaluateDetailed(const rl_common::ModelView& model,
                                                      rl_common::Random& rng, int samples,
                                                      const std::vector<int>& groupBy) {
  if (samples < 1) {
    throw std::invalid_argument("ModelAccuracy::evaluateDetailed(): samples must be >= 1");
  }
  const std::size_t d = states_.front().size();
  for (int f : groupBy) {
    if (f < 0 || static_cast<std::size_t>(f) >= d) {
      throw std::invalid_argument("ModelAccuracy::evaluateDetailed(): group feature " +
                                  std::to_string(f) + " out of range (the state has " +
                                  std::to_string(d) + " features)");
    }
  }
  Report r;
  r.marginal.assign(d, 0.0);
  std::vector<double> actionSum(static_cast<std::size_t>(numActions_), 0.0);
  std::vector<int> actionCount(static_cast<std::size_t>(numActions_), 0);
  const int last = static_cast<int>(states_.size()) - 1;
  ++measurement_;  // every kept measurement is stale now
  for (int i = 0; i < samples; ++i) {
    const auto index = static_cast<std::size_t>(rng.uniformInt(0, last));
    const rl_common::State& s = states_[index];
    const int a = rng.uniformInt(0, numActions_ - 1);
    const Kept& k = measure(model, index, a);
    const double vd = k.joint;
    r.joint += vd;
    actionSum[static_cast<std::size_t>(a)] += vd;
    ++actionCount[static_cast<std::size_t>(a)];
    for (std::size_t j = 0; j < d; ++j) r.marginal[j] += k.marginal[j];
    if (!groupBy.empty()) {
      std::string name;
      for (int f : groupBy) {
        if (!name.empty()) name += ' ';
        const float value = s[static_cast<std::size_t>(f)];
        const bool whole = value == static_cast<float>(static_cast<long>(value));
        name += "f" + std::to_string(f) + "=" +
                (whole ? std::to_string(static_cast<long>(value)) : std::to_string(value));
      }
      auto& g = r.groups[name];
      g.first += vd;
      ++g.second;
    }
  }
  r.joint /= samples;
  for (double& m : r.marginal) m /= samples;
  r.perAction.resize(actionSum.size());
  for (std::size_t a = 0; a < actionSum.size(); ++a) {
    r.perAction[a] = actionCount[a] > 0 ? actionSum[a] / actionCount[a]
                                        : std::numeric_limits<double>::quiet_NaN();
  }
  return r;
}

}  // namespace rl_experiment
