#include "rl_agent/agent/action_selector.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "rl_agent/agent/boltzmann_selector.h"

namespace rl_agent {

ActionSelector::ActionSelector(Mode mode, int numActions, double epsilon, double tau)
    : mode_(mode), numActions_(numActions), epsilon_(epsilon), tau_(tau) {
  if (numActions < 1) {
    throw std::invalid_argument("ActionSelector: " + std::to_string(numActions) + " actions");
  }
  if (mode == Mode::EpsilonGreedy && !(epsilon >= 0.0 && epsilon <= 1.0)) {
    throw std::invalid_argument("ActionSelector: epsilon " + std::to_string(epsilon) +
                                " is not in [0, 1]");
  }
  if (mode == Mode::Boltzmann && !(tau > 0.0 && std::isfinite(tau))) {
    throw std::invalid_argument("ActionSelector: Boltzmann needs tau > 0, got " +
                                std::to_string(tau));
  }
}

ActionSelector ActionSelector::forExplorer(const Explorer& explorer, int numActions,
                                           double epsilon) {
  const Mode mode = explorer.randomActions   ? Mode::Random
                    : explorer.boltzmann     ? Mode::Boltzmann
                    : explorer.epsilonGreedy ? Mode::EpsilonGreedy
                                             : Mode::Greedy;
  return ActionSelector(mode, numActions, epsilon, explorer.tau);
}

int ActionSelector::choose(int plannerAction, const std::vector<double>& q,
                           rl_common::Random& rng) const {
  switch (mode_) {
    case Mode::Greedy:
      return plannerAction;
    case Mode::Random:
      return rng.uniformInt(0, numActions_ - 1);
    case Mode::Boltzmann:
      if (static_cast<int>(q.size()) != numActions_) return plannerAction;
      return BoltzmannSelector::sample(q, tau_, rng);
    case Mode::EpsilonGreedy:
      return rng.bernoulli(epsilon_) ? rng.uniformInt(0, numActions_ - 1) : plannerAction;
  }
  return plannerAction;
}

}  // namespace rl_agent
