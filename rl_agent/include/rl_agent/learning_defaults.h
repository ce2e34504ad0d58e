/**
 * The defaults of the learning parameters that several configurations of this package share:
 * the command-line options (AgentOptions), each agent's own Config (QLearner, Sarsa, Dyna),
 * the explorers' settings and the models and planners they reach. Each is defined here once,
 * so that an agent built from its Config and one built from the options behave the same.
 */
#pragma once

namespace rl_agent::defaults {

inline constexpr float kGamma = 0.99f;        ///< discount factor (the original's)
inline constexpr float kAlpha = 0.3f;         ///< learning rate of the model-free agents
inline constexpr float kEpsilon = 0.1f;       ///< ε of ε-greedy action choice
inline constexpr float kInitialValue = 0.0f;  ///< initial Q-value of the model-free agents
inline constexpr float kLambda = 0.1f;        ///< UCT(λ) return mixing; Sarsa(λ) trace decay
inline constexpr float kBoltzmannTau = 0.2f;  ///< Boltzmann temperature (the paper's)
inline constexpr int kKnownVisits = 5;        ///< R-MAX: visits before a state-action is known

}  // namespace rl_agent::defaults
