#include "rl_agent/model/true_model_view.h"

#include <algorithm>

namespace rl_agent {

rl_common::StateActionInfo TrueModelView::query(const rl_common::State& input, int action) const {
  const std::vector<rl_common::Outcome> outcomes = model_.transitions(input, action);
  rl_common::StateActionInfo info;
  double reward = 0.0, term = 0.0;
  for (const auto& o : outcomes) {
    reward += o.probability * o.reward;
    if (o.terminal) term += o.probability;
  }
  const bool allTerminal = term >= 1.0 - 1e-12;
  const double norm = allTerminal ? 1.0 : 1.0 - term;
  for (const auto& o : outcomes) {
    if (o.terminal != allTerminal || o.probability <= 0.0) continue;
    auto it = std::find_if(info.transitions.begin(), info.transitions.end(),
                           [&](const auto& t) { return t.first == o.next; });
    if (it == info.transitions.end()) {
      info.transitions.emplace_back(o.next, o.probability / norm);
    } else {
      it->second += o.probability / norm;
    }
  }
  info.reward = info.externalReward = static_cast<float>(reward);
  info.termProb = static_cast<float>(std::min(term, 1.0));
  info.known = true;
  return info;
}

}  // namespace rl_agent
