/**
 * PyAgent: one agent of the agent registry, built by name with the agent node's option names
 * for a task, behind the episode protocol of rl_common::Agent (firstAction, nextAction,
 * lastAction) that the Python module offers.
 *
 * The options go through the agent node's own steps: addAgentOptions and --seed on one
 * OptionParser, the registry's canonical name, applyAgentDefaults (e.g. texplore with --v or
 * --n explores with variancenovelty), checkAgentOptions; then rl_agent::makeAgent. Agents that
 * plan on the environment's true model (`optimal`) get their own copy of the environment, as
 * rl_experiment's optimal_agent node builds one, so resets of the caller's environment never
 * touch it.
 *
 * The reward breakdown is the agent node's rl_reward_breakdown message: `external`, the reward
 * given with the state of the last call, and the intrinsic parts (variance, novelty, other)
 * the agent's model predicted for the action it chose (rl_agent::RewardBreakdownSource).
 */
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rl_agent/agent/agent_options.h"
#include "rl_common/agent.h"
#include "rl_common/environment.h"
#include "rl_python/option_values.h"

namespace rl_python {

/// The parts of the reward behind the agent's last action.
struct RewardParts {
  float external = 0.0f;  ///< the environment's reward given with the last call (0 at the first)
  float variance = 0.0f;  ///< VANIR's model-disagreement bonus of the chosen action
  float novelty = 0.0f;   ///< VANIR's novelty bonus
  float other = 0.0f;     ///< any other intrinsic bonus (R-MAX optimism, competence, ...)
  /// The planner's Q(s, a) of the chosen action and max_a Q - min_a Q (NaN without one).
  double plannedValue = std::numeric_limits<double>::quiet_NaN();
  double valueSpread = std::numeric_limits<double>::quiet_NaN();
  float intrinsic() const { return variance + novelty + other; }
};

class PyAgent {
 public:
  /// Makes the environment an agent that plans on the true model keeps (null: none).
  using EnvironmentFactory = std::function<std::unique_ptr<rl_common::Environment>()>;

  /// Builds agent `name` for `task` with `options` (any option of the agent node's but
  /// --agent, --seed included). `trueModelSource` may be empty (a bare description). Throws
  /// rl_common::OptionError for an unknown agent or option, a bad value or combination, or an
  /// agent that plans on a true model the task does not have; std::invalid_argument as
  /// rl_agent::makeAgent.
  PyAgent(const std::string& name, const OptionValues& options,
          const rl_common::EnvironmentDescription& task, const EnvironmentFactory& trueModelSource,
          const std::string& trueModelNames);

  int firstAction(const rl_common::State& s);
  int nextAction(float reward, const rl_common::State& s);
  void lastAction(float reward);
  void seedExperiences(const std::vector<rl_common::Experience>& seeds) {
    agent_->seedExperiences(seeds);
  }
  void savePolicy(const std::string& filename) { agent_->savePolicy(filename); }

  /// The reward's parts behind the last action, or nothing for an agent without intrinsic
  /// rewards (the model-free agents, savedpolicy, optimal).
  std::optional<RewardParts> rewardBreakdown() const;
  /// Switches exploration (intrinsic rewards) on or off, as the runner's task phase. Throws
  /// std::logic_error for an agent that is not model-based.
  void setIntrinsicEnabled(bool enabled);

  /// Canonical registry name.
  const std::string& name() const { return options_.agent; }
  std::uint64_t seed() const { return options_.seed; }
  /// The options after the agent's defaults (applyAgentDefaults).
  const rl_agent::AgentOptions& options() const { return options_; }
  /// Every option's effective value, as the agent node logs them.
  const OptionValues& effectiveOptions() const { return effective_; }
  rl_common::Agent& agent() { return *agent_; }

 private:
  rl_agent::AgentOptions options_;
  OptionValues effective_;
  std::unique_ptr<rl_common::Environment> modelEnv_;  ///< the true model's (optimal only)
  std::unique_ptr<rl_common::Agent> agent_;
  float lastReward_ = 0.0f;
};

}  // namespace rl_python
