#include "rl_agent/ros/agent_node.h"

#include <rl_msgs/RLAction.h>
#include <rl_msgs/RLExperimentInfo.h>
#include <rl_msgs/RLRewardBreakdown.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "rl_agent/agent/agent_registry.h"
#include "rl_agent/agent/model_based_agent.h"
#include "rl_agent/agent/optimal_agent.h"
#include "rl_agent/agent/reward_breakdown_source.h"
#include "rl_agent/journal/journaling_agent.h"
#include "rl_agent/model/model_predictions.h"

// A "dropping ..." warning through the node's rate limit (rl_common::RateLimitedLog).
#define RL_AGENT_DROP(stream)                        \
  do {                                               \
    std::ostringstream dropLine_;                    \
    dropLine_ << stream;                             \
    if (auto l_ = dropLog_.admit(dropLine_.str())) { \
      ROS_WARN_STREAM_NAMED("agent", *l_);           \
    }                                                \
  } while (0)

namespace rl_agent {

namespace {

/// Seed experiences kept while no description has arrived.
constexpr std::size_t kMaxEarlySeeds = 100000;

/// The env sends one state per action, but any node may publish on the state topic: when the
/// queue overflows (the original's holds 1), a foreign message arriving before the callback
/// pushes the env's state out, the agent never answers it and the pair stalls. With 10, a
/// burst of 550 malformed states did that on a loaded machine (nodes_fuzz.test); the queue
/// holds only messages waiting for a callback, so a deep one costs nothing in normal running.
constexpr uint32_t kStateQueue = 10000;

bool allFinite(const std::vector<float>& v) {
  for (float x : v) {
    if (!std::isfinite(x)) return false;
  }
  return true;
}

}  // namespace

rl_common::EnvironmentDescription fromMessage(const rl_msgs::RLEnvDescription& m) {
  // Checked as floats before any cast: a cast of NaN, inf or 3e9 to int is undefined.
  const auto whole = [](float x, float most) {
    return std::isfinite(x) && x >= 1.0f && x <= most && x == std::floor(x);
  };
  if (!whole(m.num_actions, static_cast<float>(kMaxDescribedActions))) {
    throw std::invalid_argument("num_actions must be a whole number in [1, " +
                                std::to_string(kMaxDescribedActions) + "], got " +
                                std::to_string(m.num_actions));
  }
  if (!whole(m.num_states, static_cast<float>(kMaxDescribedFeatures))) {
    throw std::invalid_argument("num_states must be a whole number in [1, " +
                                std::to_string(kMaxDescribedFeatures) + "], got " +
                                std::to_string(m.num_states));
  }
  const auto n = static_cast<std::size_t>(m.num_states);
  if (m.min_state_range.size() != n || m.max_state_range.size() != n) {
    throw std::invalid_argument("num_states (" + std::to_string(n) +
                                ") does not match the range lengths (" +
                                std::to_string(m.min_state_range.size()) + ", " +
                                std::to_string(m.max_state_range.size()) + ")");
  }
  if (!allFinite(m.min_state_range) || !allFinite(m.max_state_range) ||
      !std::isfinite(m.max_reward) || !std::isfinite(m.reward_range)) {
    throw std::invalid_argument("ranges and rewards must be finite");
  }
  for (std::size_t j = 0; j < n; ++j) {
    if (m.min_state_range[j] > m.max_state_range[j]) {
      throw std::invalid_argument("feature " + std::to_string(j) + ": min_state_range " +
                                  std::to_string(m.min_state_range[j]) +
                                  " is above max_state_range " +
                                  std::to_string(m.max_state_range[j]));
    }
    // Distances are normalised by the span: an infinite one makes every state alike.
    if (!std::isfinite(m.max_state_range[j] - m.min_state_range[j])) {
      throw std::invalid_argument("feature " + std::to_string(j) +
                                  ": the range's span overflows a float (" +
                                  std::to_string(m.min_state_range[j]) + " to " +
                                  std::to_string(m.max_state_range[j]) + ")");
    }
  }
  if (m.reward_range < 0.0f) {
    throw std::invalid_argument("reward_range must be >= 0, got " + std::to_string(m.reward_range));
  }
  rl_common::EnvironmentDescription d;
  d.numActions = static_cast<int>(m.num_actions);
  d.minFeatures = m.min_state_range;
  d.maxFeatures = m.max_state_range;
  d.maxReward = m.max_reward;
  d.minReward = m.max_reward - m.reward_range;
  d.episodic = m.episodic;
  d.stochastic = m.stochastic;
  d.title = m.title;
  return d;
}

AgentNode::AgentNode(ros::NodeHandle nh, const AgentOptions& options,
                     std::unique_ptr<rl_common::Environment> trueModelEnv, JournalSettings journal,
                     std::string modelPredictions)
    : nh_(nh),
      options_(options),
      trueModelEnv_(std::move(trueModelEnv)),
      journalSettings_(std::move(journal)),
      modelPredictions_(std::move(modelPredictions)) {
  if (trueModelEnv_) {
    trueModel_ = dynamic_cast<const rl_common::TrueModel*>(trueModelEnv_.get());
    if (trueModel_ == nullptr) {
      throw std::invalid_argument("AgentNode::AgentNode(): environment '" + trueModelEnv_->name() +
                                  "' is not an rl_common::TrueModel (the env registry's "
                                  "'true-model' fact lists those that are)");
    }
  }
  const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
  actionPub_.advertise(nh_, "rl_agent/rl_action", 1, "action");
  infoPub_.advertise(nh_, "rl_agent/rl_experiment_info", 1, "episode end");
  breakdownPub_ = nh_.advertise<rl_msgs::RLRewardBreakdown>("rl_agent/rl_reward_breakdown", 10);
  descriptionSub_ =
      nh_.subscribe("rl_env/rl_env_description", 1, &AgentNode::onDescription, this, hints);
  stateSub_ =
      nh_.subscribe("rl_env/rl_state_reward", kStateQueue, &AgentNode::onStateEvent, this, hints);
  seedSub_ = nh_.subscribe("rl_env/rl_seed", 100, &AgentNode::onSeed, this, hints);
  resetSrv_ = nh_.advertiseService("rl_agent/reset", &AgentNode::onReset, this);
  ROS_INFO_STREAM_NAMED("agent", "agent '" << options_.agent << "' waiting for an environment");
}

AgentNode::~AgentNode() {
  saveModelPredictions();
  if (agent_ && !options_.filename.empty()) {
    try {
      agent_->savePolicy(options_.filename);
    } catch (const std::exception& e) {
      // ros::shutdown() has closed rosconsole by now (a ROS_ERROR here was never seen).
      std::cerr << "agent: could not save the policy: " << e.what() << "\n";
    }
  }
}

void AgentNode::noteState(const rl_common::State& s) {
  if (modelPredictions_.empty() || seenStates_.size() >= kMaxPredictionStates) return;
  seenStates_.insert(s);
  if (seenStates_.size() == kMaxPredictionStates) {
    ROS_WARN_STREAM_NAMED("agent", "--model-predictions: " << kMaxPredictionStates
                                                           << " distinct states seen; later ones "
                                                              "are not written");
  }
}

void AgentNode::saveModelPredictions() const {
  if (modelPredictions_.empty()) return;
  // Written at shutdown, when ros::shutdown() has already closed rosconsole: said on stderr.
  const auto* model = dynamic_cast<const ModelBasedAgent*>(core_);
  if (model == nullptr || !description_) {
    std::cerr << "agent: no learned model to write to '" << modelPredictions_
              << "' (no environment description arrived, or the agent could not be built)\n";
    return;
  }
  try {
    const std::vector<rl_common::State> states(seenStates_.begin(), seenStates_.end());
    rl_agent::saveModelPredictions(*model->learnedModelView(), states, description_->numActions,
                                   modelPredictions_);
    std::cerr << "agent: wrote the model's predictions for " << states.size() << " states to '"
              << modelPredictions_ << "'\n";
  } catch (const std::exception& e) {
    std::cerr << "agent: could not write the model's predictions: " << e.what() << "\n";
  }
}

void AgentNode::buildAgent() {
  agent_.reset();
  core_ = nullptr;
  auto agent = makeAgent(options_, *description_, trueModel_);
  const int features = static_cast<int>(description_->numFeatures());
  if (!journalSettings_.resume.empty()) {
    if (!resume_) {  // read once: a rebuild starts from what the node knew when it started
      resume_ = readExperienceJournal(journalSettings_.resume);
      if (resume_->droppedBytes > 0) {
        ROS_WARN_STREAM_NAMED("agent", "journal '" << journalSettings_.resume << "' ended in a "
                                                   << resume_->droppedBytes
                                                   << "-byte partial record (a write cut by a "
                                                      "kill): loaded up to the last whole one");
      }
    }
    if (resume_->numFeatures != features) {
      throw std::runtime_error("journal '" + journalSettings_.resume + "' holds " +
                               std::to_string(resume_->numFeatures) + "-feature experiences; " +
                               "the environment has " + std::to_string(features));
    }
    agent->seedExperiences(resume_->records);
    for (const auto& e : resume_->records) {
      noteState(e.s);
      noteState(e.next);
    }
    ROS_INFO_STREAM_NAMED("agent", "rebuilt the model from the " << resume_->records.size()
                                                                 << " experiences of journal '"
                                                                 << journalSettings_.resume << "'");
  }
  core_ = agent.get();
  if (!journalSettings_.journal.empty()) {
    if (!journal_ || journal_->numFeatures() != features) {
      journal_.reset();
      journal_ = std::make_shared<ExperienceJournalWriter>(journalSettings_.journal, features,
                                                           journalSettings_.header);
      ROS_INFO_STREAM_NAMED("agent", "journaling every experience to '"
                                         << journalSettings_.journal << "' (" << journal_->records()
                                         << " records in it)");
    }
    agent = std::make_unique<JournalingAgent>(std::move(agent), journal_);
  }
  agent_ = std::move(agent);
  driver_.emplace(*agent_);
  steps_ = 0;
}

void AgentNode::onDescription(const rl_msgs::RLEnvDescription::ConstPtr& msg) {
  try {
    description_ = fromMessage(*msg);
  } catch (const std::invalid_argument& e) {
    RL_AGENT_DROP("dropping a malformed environment description: " << e.what());
    return;
  }
  for (std::size_t j = 0; j < description_->numFeatures(); ++j) {
    if (description_->minFeatures[j] == description_->maxFeatures[j]) {
      ROS_WARN_STREAM_NAMED("agent", "feature " << j << " has an empty range ("
                                                << description_->minFeatures[j]
                                                << "): it is taken as constant");
    }
  }
  if (trueModelEnv_) {
    const std::string mismatch = trueModelMismatch(trueModelEnv_->describe(), *description_);
    if (!mismatch.empty()) {
      ROS_FATAL_STREAM_NAMED(
          "agent", "the env node's task ("
                       << msg->title.substr(0, msg->title.find('\n'))
                       << ") is not the environment agent '" << options_.agent << "' plans on ("
                       << trueModelEnv_->name()
                       << "; give the env node's --env and options): " << mismatch);
      agent_.reset();
      core_ = nullptr;
      description_.reset();
      failed_ = true;
      ros::shutdown();
      return;
    }
  }
  try {
    buildAgent();
  } catch (const std::exception& e) {
    ROS_ERROR_STREAM_NAMED("agent", "cannot build agent '" << options_.agent << "': " << e.what());
    agent_.reset();
    core_ = nullptr;
    return;
  }
  ROS_INFO_STREAM_NAMED("agent", "built agent '"
                                     << options_.agent << "' (seed " << options_.seed << ") for "
                                     << msg->title.substr(0, msg->title.find('\n')) << " with "
                                     << description_->numFeatures() << " features, "
                                     << description_->numActions << " actions");
  // What came before the description, in order: the seeds, then the latest state.
  const auto seeds = std::move(earlySeeds_);
  earlySeeds_.clear();
  const auto state = std::move(earlyState_);
  earlyState_.reset();
  for (const auto& seed : seeds) onSeed(seed);
  if (state) onState(state);
}

bool AgentNode::validState(const std::vector<float>& s, const char* what) const {
  if (s.size() != description_->numFeatures()) {
    RL_AGENT_DROP("dropping a " << what << " with " << s.size() << " features; the environment has "
                                << description_->numFeatures());
    return false;
  }
  if (!allFinite(s)) {
    RL_AGENT_DROP("dropping a " << what << " with NaN or infinite values");
    return false;
  }
  return true;
}

void AgentNode::onSeed(const rl_msgs::RLEnvSeedExperience::ConstPtr& msg) {
  if (!description_ && !failed_) {
    if (earlySeeds_.size() < kMaxEarlySeeds) {
      earlySeeds_.push_back(msg);  // replayed once the description has built the agent
    } else {
      ROS_WARN_THROTTLE_NAMED(10, "agent", "dropping seed experiences: no description yet");
    }
    return;
  }
  if (!agent_) {
    RL_AGENT_DROP("dropping a seed experience: no agent (see the errors above)");
    return;
  }
  if (!validState(msg->from_state, "seed experience") ||
      !validState(msg->to_state, "seed experience")) {
    return;  // said by validState
  }
  if (!std::isfinite(msg->reward) || msg->action < 0 || msg->action >= description_->numActions) {
    RL_AGENT_DROP("dropping a seed experience with action "
                  << msg->action << " and reward " << msg->reward << " (valid actions: 0.."
                  << description_->numActions - 1 << ", a finite reward)");
    return;
  }
  agent_->seedExperiences({{msg->from_state, msg->action, msg->reward, msg->to_state,
                            static_cast<bool>(msg->terminal)}});
}

void AgentNode::onStateEvent(const ros::MessageEvent<rl_msgs::RLStateReward const>& event) {
  stateSender_ = event.getPublisherName();
  onState(event.getMessage());
}

void AgentNode::onState(const rl_msgs::RLStateReward::ConstPtr& msg) {
  if (!description_ && !failed_) {
    earlyState_ = msg;  // acted on once the description has built the agent
    return;
  }
  if (!agent_) {
    RL_AGENT_DROP("dropping a state: no agent (see the errors above)");
    return;
  }
  if (!validState(msg->state, "state")) return;
  if (!std::isfinite(msg->reward)) {
    RL_AGENT_DROP("dropping a state with reward " << msg->reward);
    return;
  }
  try {
    act(*msg);
  } catch (const std::exception& e) {
    // The agent could not act (out of memory, a model error): say so and keep the node up.
    ROS_ERROR_STREAM_NAMED("agent", "agent '" << options_.agent << "' failed on a state (step "
                                              << steps_ << "): " << e.what());
  }
}

void AgentNode::act(const rl_msgs::RLStateReward& state) {
  noteState(state.state);
  if (state.terminal && !driver_->starting()) {
    const rl_common::EpisodeDriver::Episode e = driver_->end(state.reward, true, state.state);
    ROS_INFO_STREAM_NAMED("agent", "Episode " << e.index << " reward: " << e.reward);
    rl_msgs::RLExperimentInfo info;
    info.episode_number = e.index;
    info.episode_reward = e.reward;
    info.number_actions = static_cast<int>(e.actions);
    infoPub_.publish(info, stateSender_);  // the env resets on it: held until it hears
    return;
  }
  const int action = driver_->act(state.state, state.reward);
  rl_msgs::RLRewardBreakdown b;
  b.episode_number = driver_->episode().index;
  b.step = static_cast<int>(steps_++);
  b.action = action;
  b.external = state.reward;
  if (const auto* src = dynamic_cast<const RewardBreakdownSource*>(core_)) {
    const RewardBreakdown parts = src->lastRewardBreakdown();
    b.variance = parts.variance;
    b.novelty = parts.novelty;
    b.other = parts.other;
  }
  breakdownPub_.publish(b);
  rl_msgs::RLAction a;
  a.action = action;
  // Everyone connected hears it; the state's sender, if not connected yet, when it connects.
  if (actionPub_.publish(a, stateSender_)) {
    // Once per sender: a relay (e.g. rosbag play) that never subscribes would repeat it.
    ROS_INFO_STREAM_COND_NAMED(stateSender_ != heldLoggedFor_, "agent",
                               "holding action " << action << " for " << stateSender_
                                                 << " until it subscribes to rl_action");
    heldLoggedFor_ = stateSender_;
  }
}

bool AgentNode::onReset(rl_msgs::Reset::Request& req, rl_msgs::Reset::Response& res) {
  if (req.use_seed) options_.seed = req.seed;
  if (!description_) {
    res.success = false;
    res.message = "no environment description yet";
    return true;
  }
  try {
    buildAgent();
  } catch (const std::exception& e) {
    res.success = false;
    res.message = e.what();
    return true;
  }
  res.success = true;
  res.message = "agent rebuilt with seed " + std::to_string(options_.seed);
  ROS_INFO_STREAM_NAMED("agent", res.message);
  return true;
}

}  // namespace rl_agent
