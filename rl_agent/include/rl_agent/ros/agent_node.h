/**
 * AgentNode: runs an rl_common::Agent against an environment node over the original rl_msgs
 * protocol (shared/spec/ORIGINAL.md §2.2-2.3), so the original env node or ours can drive it.
 *
 * Topics (relative: `/rl_env/...`, `/rl_agent/...` without a namespace):
 *   subscribes rl_env/rl_env_description, rl_env/rl_state_reward, rl_env/rl_seed
 *   publishes  rl_agent/rl_action, rl_agent/rl_experiment_info,
 *              rl_agent/rl_reward_breakdown (new: RLRewardBreakdown, every step)
 *   service    rl_agent/reset (rl_msgs/Reset, new): rebuild the agent (optionally reseeded)
 *
 * With a true model (`--agent optimal --env E`) the node holds its own copy of environment E,
 * used only as the model the agent plans on; a description that does not match that copy's
 * (actions, features, ranges, rewards, episodic, stochastic) is fatal: ROS_FATAL, the node
 * shuts down and failed() is true (main exits non-zero).
 *
 * A description (re)builds the agent; each seed message is learned at once; a state message
 * starts an episode (first action), continues it (next action) or ends it (terminal: last
 * action, an RLExperimentInfo, no action published), as the original. Seeds and a state that
 * arrive before the first description (the latched state of an env node that is already
 * running can) are kept and replayed once the agent is built. Malformed messages
 * (wrong lengths, NaN or infinite values) are logged and dropped; the node keeps running.
 *
 * Experience journal (journal/experience_journal.h): with `journal` set, every experience the
 * agent learns from is appended to that file and flushed; with `resume` set, every agent the
 * node builds (at a description, or by the reset service between trials) learns that
 * journal's experiences, as read at the first build, before it acts. Both may be one file: a
 * resumed node goes on writing the journal it was rebuilt from.
 *
 * Model predictions (model/model_predictions.h): with `modelPredictions` set, a model-based
 * agent's learned model is written to that file when the node shuts down, for every action in
 * each distinct state the node has seen (the resumed journal's and those it acted on, at most
 * kMaxPredictionStates).
 */
#pragma once

#include <rl_msgs/RLAction.h>
#include <rl_msgs/RLEnvDescription.h>
#include <rl_msgs/RLEnvSeedExperience.h>
#include <rl_msgs/RLExperimentInfo.h>
#include <rl_msgs/RLStateReward.h>
#include <rl_msgs/Reset.h>
#include <ros/ros.h>

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "rl_agent/agent/agent_options.h"
#include "rl_agent/journal/experience_journal.h"
#include "rl_agent/ros/held_publisher.h"
#include "rl_common/agent.h"
#include "rl_common/environment.h"
#include "rl_common/episode_driver.h"
#include "rl_common/rate_limited_log.h"
#include "rl_common/true_model.h"

namespace rl_agent {

/// The most actions and features a description may declare: beyond them the agents' per-action
/// tables and per-feature forests would exhaust memory (the original protocol's tasks have at
/// most a few hundred).
constexpr int kMaxDescribedActions = 65536;
constexpr int kMaxDescribedFeatures = 65536;

/// Converts a description message; throws std::invalid_argument if it is inconsistent
/// (num_actions or num_states not a whole number in [1, 65536], ranges not matching num_states,
/// min above max, a span or value that is not finite, a negative reward_range).
rl_common::EnvironmentDescription fromMessage(const rl_msgs::RLEnvDescription& m);

/// The agent node's journal files (empty: none) and the header a new journal gets.
struct JournalSettings {
  std::string journal;
  std::string resume;
  JournalHeader header;
};

/// The most distinct states whose predictions `--model-predictions` writes (the first seen).
constexpr std::size_t kMaxPredictionStates = 100000;

class AgentNode {
 public:
  /// `trueModelEnv`: for `optimal`, the node's own copy of the env node's environment (it
  /// must implement rl_common::TrueModel); null for every other agent. Throws
  /// std::invalid_argument if it is given but has no true model.
  AgentNode(ros::NodeHandle nh, const AgentOptions& options,
            std::unique_ptr<rl_common::Environment> trueModelEnv = nullptr,
            JournalSettings journal = {}, std::string modelPredictions = "");
  ~AgentNode();

  /// True after a fatal error (a description that does not match the true model); the node
  /// has then called ros::shutdown().
  bool failed() const { return failed_; }

  void onDescription(const rl_msgs::RLEnvDescription::ConstPtr& msg);
  void onSeed(const rl_msgs::RLEnvSeedExperience::ConstPtr& msg);
  /// A state from the network: notes which node sent it (the one the action answers).
  void onStateEvent(const ros::MessageEvent<rl_msgs::RLStateReward const>& event);
  void onState(const rl_msgs::RLStateReward::ConstPtr& msg);
  /// The agent's answer to a valid state: its action, or at a terminal state the episode's
  /// end. Throws what the agent throws.
  void act(const rl_msgs::RLStateReward& state);
  bool onReset(rl_msgs::Reset::Request& req, rl_msgs::Reset::Response& res);

 private:
  void buildAgent();
  void noteState(const rl_common::State& s);
  void saveModelPredictions() const;
  bool validState(const std::vector<float>& s, const char* what) const;

  ros::NodeHandle nh_;
  AgentOptions options_;
  std::unique_ptr<rl_common::Environment> trueModelEnv_;
  const rl_common::TrueModel* trueModel_ = nullptr;  ///< trueModelEnv_ as a TrueModel
  bool failed_ = false;
  std::optional<rl_common::EnvironmentDescription> description_;
  std::unique_ptr<rl_common::Agent> agent_;  ///< the agent, journaling if asked
  rl_common::Agent* core_ = nullptr;         ///< the agent itself (agent_ or the one it wraps)
  JournalSettings journalSettings_;
  std::shared_ptr<ExperienceJournalWriter> journal_;
  std::optional<JournalContents> resume_;  ///< the resume journal, read at the first build
  std::string modelPredictions_;           ///< where the model goes at shutdown (empty: nowhere)
  std::set<rl_common::State> seenStates_;  ///< kept only with modelPredictions_
  std::optional<rl_common::EpisodeDriver> driver_;  ///< drives agent_ through its episodes
  long steps_ = 0;
  std::vector<rl_msgs::RLEnvSeedExperience::ConstPtr> earlySeeds_;  ///< before any description
  rl_msgs::RLStateReward::ConstPtr earlyState_;                     ///< the latest such state
  ros::Subscriber descriptionSub_, stateSub_, seedSub_;
  /// The action and the episode end answer the latest state's sender, and are held for it
  /// while it is not connected (HeldPublisher).
  HeldPublisher<rl_msgs::RLAction> actionPub_;
  HeldPublisher<rl_msgs::RLExperimentInfo> infoPub_;
  ros::Publisher breakdownPub_;
  /// The node that sent the latest state (the environment, or whoever plays it).
  std::string stateSender_;
  std::string heldLoggedFor_;  ///< the sender the last "holding" line named
  ros::ServiceServer resetSrv_;
  /// Malformed messages: one warning each, at most 10 a second (a burst is counted, not logged).
  mutable rl_common::RateLimitedLog dropLog_;
};

}  // namespace rl_agent
