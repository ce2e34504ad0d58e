/**
 * ModelBasedAgent: TEXPLORE and TEXPLORE-VANIR (`--agent texplore [--v V --n N]`) and the
 * original's `modelbased` agent.
 *
 * Hester & Stone, "TEXPLORE: real-time sample-efficient reinforcement learning for robots",
 * Machine Learning 90(3), 2013; Hester & Stone, "Intrinsically motivated model learning for
 * developing curious robots", Artificial Intelligence 247, 2017 (TEXPLORE-VANIR).
 *
 * The agent learns an ExplorationModel (random forests per feature, reward and terminal, plus
 * the visited record behind the intrinsic rewards) from every transition and plans with
 * UCT(lambda) on it. Two ways to run:
 *   - real time (the default, `--planner parallel-uct`, `--rollouts 0`): the RTMBA
 *     architecture; model learning and planning run in their own threads while the agent acts
 *     at `--actrate` Hz (each action is due 1/actrate after its state arrived);
 *   - synchronous (`--rollouts N`, or `--planner uct`): each step learns from the last
 *     transition, then plans N rollouts (or until 1/actrate passed, for `uct` without
 *     `--rollouts`) before acting. With `--rollouts` the same seed gives the same run.
 * With `--history k` the last k actions (one-hot) are appended to the model's input.
 */
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rl_agent/agent/agent_options.h"
#include "rl_agent/agent/reward_breakdown_source.h"
#include "rl_agent/model/exploration_model.h"
#include "rl_agent/planner/real_time_planner.h"
#include "rl_agent/planner/uct_planner.h"
#include "rl_common/agent.h"
#include "rl_common/environment.h"
#include "rl_common/random.h"

namespace rl_agent {

class ModelBasedAgent : public rl_common::Agent, public RewardBreakdownSource {
 public:
  /// Builds the agent for a task from the agent options (after applyAgentDefaults). Throws
  /// std::invalid_argument for a model, planner or explore type it does not offer.
  ModelBasedAgent(const AgentOptions& options, const rl_common::EnvironmentDescription& task);
  ~ModelBasedAgent() override;

  int firstAction(const rl_common::State& s) override;
  int nextAction(float reward, const rl_common::State& s) override;
  void lastAction(float reward) override;
  void seedExperiences(const std::vector<rl_common::Experience>& seeds) override;

  RewardBreakdown lastRewardBreakdown() const override { return lastBreakdown_; }

  /// Switches the intrinsic rewards on or off (off: plan on the external reward only).
  void setIntrinsicEnabled(bool enabled);
  /// The model's current view (for evaluation); thread-safe.
  std::shared_ptr<const ExplorationModel::View> modelView() const;
  /// Rollouts planned for the last action.
  long lastRollouts() const { return lastRollouts_; }
  bool realTime() const { return realTime_ != nullptr; }

 private:
  int chooseAction(const rl_common::State& s);
  void learn(const rl_common::Experience& e);
  rl_common::State modelInput(const rl_common::State& s);

  AgentOptions options_;
  rl_common::EnvironmentDescription task_;
  rl_common::Random rng_;
  bool epsilonGreedy_ = false;
  // Synchronous mode owns model and planner; real-time mode hands them to realTime_ and keeps
  // raw pointers for the few calls that need them (under RealTimePlanner's access rules).
  std::unique_ptr<ExplorationModel> model_;
  std::unique_ptr<UctPlanner> planner_;
  ExplorationModel* modelPtr_ = nullptr;
  std::unique_ptr<RealTimePlanner> realTime_;
  std::vector<int> history_;
  rl_common::State lastInput_;
  int lastAction_ = -1;
  long lastRollouts_ = 0;
  RewardBreakdown lastBreakdown_;
};

}  // namespace rl_agent
