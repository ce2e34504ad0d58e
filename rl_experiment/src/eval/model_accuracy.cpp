#include "rl_experiment/eval/model_accuracy.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

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
}

double ModelAccuracy::evaluate(const rl_common::ModelView& model, rl_common::Random& rng,
                               int samples) const {
  if (samples < 1) {
    throw std::invalid_argument("ModelAccuracy::evaluate(): samples must be >= 1");
  }
  double sum = 0.0;
  const int last = static_cast<int>(states_.size()) - 1;
  for (int i = 0; i < samples; ++i) {
    const rl_common::State& s = states_[static_cast<std::size_t>(rng.uniformInt(0, last))];
    const int a = rng.uniformInt(0, numActions_ - 1);
    const StateDistribution truth = nextStateDistribution(truth_.transitions(s, a));
    sum += variationalDistance(truth, model.query(s, a));
  }
  return sum / samples;
}

}  // namespace rl_experiment
