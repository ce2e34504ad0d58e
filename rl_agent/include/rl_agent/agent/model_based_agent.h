/**
 * ModelBasedAgent: TEXPLORE and TEXPLORE-VANIR (`--agent texplore [--v V --n N]`), R-MAX
 * (`--agent rmax`) and the original's `modelbased` agent with any model and planner.
 *
 * Hester & Stone, "TEXPLORE: real-time sample-efficient reinforcement learning for robots",
 * Machine Learning 90(3), 2013; Hester & Stone, "Intrinsically motivated model learning for
 * developing curious robots", Artificial Intelligence 247, 2017 (TEXPLORE-VANIR); Brafman &
 * Tennenholtz, "R-MAX", JMLR 3, 2002.
 *
 * The agent learns a model from every transition and plans on it:
 *   --model tree (c45tree, texplore): an ExplorationModel (random forests per feature, reward
 *       and terminal, plus the visited record behind the intrinsic rewards); every --explore;
 *   --model tabular: a TabularModel (R-MAX optimism for --explore unknown); explore greedy,
 *       epsilongreedy, random, boltzmann or unknown;
 *   --model m5tree: an M5Model (regression trees with linear leaves); explore greedy,
 *       epsilongreedy, random or boltzmann.
 *   --planner uct / delayed-uct: UCT(λ) planned synchronously each step; parallel-uct /
 *       delayed-parallel-uct: the RTMBA real-time architecture (synchronous with --rollouts).
 *       Our UctPlanner keys its values by state and action history, which is what the
 *       original's delayed (PO_) variants added, so the delayed names are the same planners.
 *   --planner vi / pi / sweeping: value iteration, policy iteration or prioritized sweeping,
 *       solved to convergence after every model update (StateSpacePlanner).
 *   --taskplanner vi: once intrinsic rewards are off (the paper's task phase), value iteration
 *       on the learned model instead, afresh at every step: the states the model's most likely
 *       outcomes reach within --taskdepth steps of the current one (at most 20000), told apart
 *       by the --taskkey features, the last --taskrecent observed states serving as their
 *       entries' representatives. UCT's rollouts from one state rarely reach a reward three
 *       subgoals away (key, lock, door); a sweep over the imagined states does.
 * Components come from their registries (modelRegistry, plannerRegistry, explorerRegistry) and
 * the planner's entry builds the PlanningLoop that learns and plans between actions. Two ways
 * to run UCT:
 *   - real time (the default, `--planner parallel-uct`, `--rollouts 0`): model learning and
 *     planning run in their own threads while the agent acts at `--actrate` Hz;
 *   - synchronous (`--rollouts N`, or `--planner uct`): each step learns from the last
 *     transition, then plans N rollouts (or until 1/actrate passed, for `uct` without
 *     `--rollouts`) before acting. With `--rollouts` the same seed gives the same run.
 * Action choice: the planner's greedy action, except with --explore epsilongreedy (random with
 * probability epsilon), random (always uniformly random) and boltzmann (softmax of the
 * planner's Q-values with temperature --tau).
 * With `--history k` the last k actions (one-hot) are appended to the model's input. With
 * `--nstates n` (not for m5tree) states are binned as the original's DiscretizationAgent
 * before the model sees them; `--nstates n1,n2,...` gives each feature its own count (0: not
 * binned), as the original's runner did for its car domains. Binning matters for continuous,
 * noisy robot states: there every relative change is a class of its own, so the trees'
 * disagreement stays high everywhere, and UCT meets every imagined state only once.
 */
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rl_agent/agent/action_selector.h"
#include "rl_agent/agent/agent_options.h"
#include "rl_agent/agent/experience_log.h"
#include "rl_agent/agent/irreversible_step.h"
#include "rl_agent/agent/model_based_config.h"
#include "rl_agent/agent/reward_breakdown_source.h"
#include "rl_agent/model/exploration_model.h"
#include "rl_agent/model/model_registry.h"
#include "rl_agent/planner/planning_loop.h"
#include "rl_agent/planner/state_grid.h"
#include "rl_agent/planner/task_phase_planner.h"
#include "rl_common/agent.h"
#include "rl_common/environment.h"
#include "rl_common/random.h"

namespace rl_agent {

class ModelBasedAgent : public rl_common::Agent, public RewardBreakdownSource {
 public:
  using Config = ModelBasedConfig;

  /// Builds the agent for a task. Throws std::invalid_argument for a model, planner or explore
  /// type it does not offer, or a combination that does not work (e.g. competence with a
  /// tabular model).
  ModelBasedAgent(const Config& config, const rl_common::EnvironmentDescription& task);
  /// The same from the agent options (after applyAgentDefaults): modelBasedConfig(options).
  ModelBasedAgent(const AgentOptions& options, const rl_common::EnvironmentDescription& task);
  ~ModelBasedAgent() override;

  int firstAction(const rl_common::State& s) override;
  int nextAction(float reward, const rl_common::State& s) override;
  void lastAction(float reward) override;
  void seedExperiences(const std::vector<rl_common::Experience>& seeds) override;
  /// Writes Q-values in the original's policy-file format (PolicyFile, policyTable()), for
  /// `savedpolicy` to act greedily on. Throws as PolicyFile::write.
  void savePolicy(const std::string& filename) override;

  RewardBreakdown lastRewardBreakdown() const override { return lastBreakdown_; }

  /// Switches exploration on or off: the intrinsic rewards (R-MAX optimism for the tabular
  /// model) and the exploratory action choice of --explore random, boltzmann and
  /// epsilongreedy. Off: plan on the external reward only and act greedily on the planner, as
  /// the paper's task phase (§5.1: "the agents act greedily with respect to their previously
  /// learned transition models").
  void setIntrinsicEnabled(bool enabled);
  /// Keeps every experience (seeds and steps) from now on, for relabelRewards(). Off by
  /// default: the log grows with every step. Throws std::logic_error if the agent has learned
  /// from experiences already (a rebuilt model would lose them).
  void recordExperiences(bool on) { log_.record(on); }
  /// Gives the agent a task's reward function after a reward-free phase, as the paper's
  /// explore-then-task protocol ("provided with a reward function for a task", §5.1):
  /// `rewards[i]` replaces the reward of the i-th recorded step experience (seeds keep
  /// theirs), and the model is rebuilt from the recorded experiences, with the same seeds, so it
  /// equals the model the agent would have learned had it seen those rewards all along. The
  /// planner keeps its values and re-queries the new model (in real time: the workers are
  /// restarted on it). Throws std::logic_error unless recording was on from the start, and
  /// std::invalid_argument unless there is one reward per recorded step experience.
  void relabelRewards(const std::vector<float>& rewards);
  /// Step experiences recorded so far (see recordExperiences()).
  std::size_t recordedSteps() const { return log_.steps(); }
  /// The tree model's current view (for evaluation); thread-safe. Null for tabular and m5tree
  /// models: use learnedModelView().
  std::shared_ptr<const ExplorationModel::View> modelView() const;
  /// The learned model's current view without intrinsic bonuses, for every model type (for
  /// model-accuracy evaluation); thread-safe. With --history it takes states alone, as after
  /// no recorded actions (NoHistoryView), as well as full inputs.
  std::shared_ptr<const rl_common::ModelView> learnedModelView() const;
  /// Rollouts (UCT) or solver iterations (vi/pi/sweeping) planned for the last action.
  long lastRollouts() const { return lastRollouts_; }
  /// Steps a region is explored before a one-way step (--defer, or the explorer's); 0: never.
  long deferSteps() const { return deferral_ ? deferral_->steps() : 0; }
  /// The one-way steps learned and put off (null without --defer).
  const StepDeferral* deferral() const { return deferral_.get(); }
  /// Seconds the last step spent updating the model (synchronous mode; 0 in real time, where
  /// a thread of its own learns) and choosing the action (planning, or waiting for its due
  /// time in real time).
  double lastLearnSeconds() const { return loop_->lastLearnSeconds(); }
  double lastPlanSeconds() const { return lastPlanSeconds_; }
  bool realTime() const { return loop_->realTime(); }
  const Config& config() const { return config_; }

 private:
  /// The model the task phase plans on: learnedModelView(), its forests recombined as
  /// --taskcombo says.
  std::shared_ptr<const rl_common::ModelView> taskModelView() const;
  /// Gives the search planners the UCB bound of the current phase (--ucb exploring, --taskucb
  /// not).
  void applyUcbBound();
  /// A new, empty model of the configured type, with `explorer`'s rewards and learners.
  LearnedModel makeModel(const Explorer& explorer) const;
  int chooseAction(const rl_common::State& s);
  /// The planner's action at `s` (model input `input`), due at `due`.
  int planAction(const rl_common::State& s, const rl_common::State& input,
                 PlanningLoop::Clock::time_point due);
  void learn(const rl_common::Experience& e);
  rl_common::State modelInput(const rl_common::State& s);
  bool taskPlannerActive() const { return !exploring_ && taskPhase_.has_value(); }

  Config config_;
  rl_common::EnvironmentDescription task_;
  rl_common::Random rng_;
  ActionSelector selector_;
  bool exploring_ = true;  ///< false after setIntrinsicEnabled(false): act greedily
  StateGrid grid_;         ///< --nstates binning of the inputs (none for m5tree)
  LearnedModel model_;     ///< its switches (the model itself is owned by loop_)
  std::unique_ptr<PlanningLoop> loop_;
  std::optional<TaskPhasePlanner> taskPhase_;  ///< --taskplanner vi
  ExperienceLog log_;
  std::vector<int> history_;
  rl_common::State lastInput_;
  int lastAction_ = -1;
  long lastRollouts_ = 0;
  std::unique_ptr<StepDeferral> deferral_;  ///< --defer: one-way steps put off
  double lastPlanSeconds_ = 0.0;
  RewardBreakdown lastBreakdown_;
};

}  // namespace rl_agent
