#include "rl_experiment/ros/experiment_node.h"

#include <rl_msgs/Reset.h>
#include <std_msgs/String.h>

#include <chrono>
#include <iostream>
#include <vector>

namespace rl_experiment {

ExperimentNode::ExperimentNode(ros::NodeHandle nh, ExperimentConfig config, Experiment* experiment)
    : nh_(nh), config_(std::move(config)), experiment_(experiment) {
  actionSub_ = nh_.subscribe("rl_agent/rl_action", 100, &ExperimentNode::onAction, this);
  breakdownSub_ =
      nh_.subscribe("rl_agent/rl_reward_breakdown", 100, &ExperimentNode::onBreakdown, this);
  stateSub_ = nh_.subscribe("rl_env/rl_state_reward", 100, &ExperimentNode::onState, this);
  progressPub_ = nh_.advertise<std_msgs::String>("rl_experiment/progress", 10, true);
  envReset_ = nh_.serviceClient<rl_msgs::Reset>("rl_env/reset");
  agentReset_ = nh_.serviceClient<rl_msgs::Reset>("rl_agent/reset");
}

void ExperimentNode::publishProgress(const std::string& text) {
  std_msgs::String m;
  m.data = text;
  progressPub_.publish(m);
  ROS_INFO_STREAM_NAMED("experiment", text);
}

void ExperimentNode::onAction(const rl_msgs::RLAction::ConstPtr& msg) { lastAction_ = msg->action; }

void ExperimentNode::onBreakdown(const rl_msgs::RLRewardBreakdown::ConstPtr& msg) {
  lastBreakdown_ = *msg;
}

void ExperimentNode::onState(const rl_msgs::RLStateReward::ConstPtr& msg) {
  if (!counting_ || !logger_) return;
  if (!lastAction_) return;  // the start state: no action led to it
  StepRecord rec;
  rec.step = steps_;
  rec.episode = episode_;
  rec.action = *lastAction_;
  rec.reward = msg->reward;
  rec.rewardSeen = msg->reward;
  rec.terminal = msg->terminal;
  if (lastBreakdown_ && lastBreakdown_->action == rec.action) {
    rec.hasBreakdown = true;
    rec.variance = lastBreakdown_->variance;
    rec.novelty = lastBreakdown_->novelty;
    rec.other = lastBreakdown_->other;
  }
  logger_->onStep(rec);
  lastAction_.reset();
  ++steps_;
  ++summary_.steps;
  summary_.totalReward += rec.reward;
  episodeRecord_.reward += rec.reward;
  ++episodeRecord_.steps;
  lastStepTime_ = ros::WallTime::now();
  if (rec.terminal) {
    episodeRecord_.terminal = true;
    logger_->onEpisode(episodeRecord_);
    ++summary_.episodes;
    ++episode_;
    episodeRecord_ = EpisodeRecord();
    episodeRecord_.episode = episode_;
  }
  if (steps_ >= config_.nonEpisodicSteps()) counting_ = false;
  if (steps_ % 100 == 0 || !counting_) {
    publishProgress("step " + std::to_string(steps_) + "/" +
                    std::to_string(config_.nonEpisodicSteps()));
  }
}

bool ExperimentNode::callReset(ros::ServiceClient& client, const std::string& what,
                               std::uint64_t seed) {
  // The node may still be starting (e.g. the agent waits for the environment's description):
  // retry until it accepts the reset or the timeout passes.
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(config_.stepTimeout);
  std::string problem = "no service " + client.getService();
  while (ros::ok() && ros::WallTime::now() < deadline) {
    if (client.waitForExistence(ros::Duration(0.2))) {
      rl_msgs::Reset srv;
      srv.request.use_seed = true;
      srv.request.seed = seed;
      if (client.call(srv) && srv.response.success) return true;
      problem = srv.response.message.empty() ? "call failed" : srv.response.message;
    }
    ros::spinOnce();
    ros::WallDuration(0.2).sleep();
  }
  ROS_ERROR_STREAM_NAMED("experiment", what << " reset failed: " << problem);
  std::cerr << "experiment_node: " << what << " reset failed: " << problem << std::endl;
  return false;
}

bool ExperimentNode::runTrial(int trial) {
  const TrialSeeds seeds = trialSeeds(config_.env.seed, trial);
  TrialInfo info{trial,       config_.label, config_.agent.agent, config_.env.env,
                 seeds.agent, seeds.env,     seeds.eval};
  counting_ = false;
  // Environment first, then the agent: the rebuilt agent starts (first action) on the next state
  // it receives.
  if (!callReset(envReset_, "environment", seeds.env)) return false;
  if (!callReset(agentReset_, "agent", seeds.agent)) return false;
  logger_ = std::make_unique<TrialLogger>(config_.out, info, EvalSettings{}, true);
  steps_ = 0;
  episode_ = 0;
  summary_ = TrialSummary();
  episodeRecord_ = EpisodeRecord();
  lastAction_.reset();
  lastBreakdown_.reset();
  resetPeakRss();
  const auto start = std::chrono::steady_clock::now();
  lastStepTime_ = ros::WallTime::now();
  counting_ = true;
  publishProgress("trial " + std::to_string(trial + 1) + "/" + std::to_string(config_.trials) +
                  " started");
  while (ros::ok() && counting_) {
    ros::spinOnce();
    if ((ros::WallTime::now() - lastStepTime_).toSec() > config_.stepTimeout) {
      ROS_ERROR_STREAM_NAMED("experiment", "trial " << trial << ": no step for "
                                                    << config_.stepTimeout
                                                    << " s; are the agent and env nodes up?");
      counting_ = false;
      return false;
    }
    ros::WallDuration(0.0005).sleep();
  }
  if (steps_ < config_.nonEpisodicSteps()) return false;
  if (episodeRecord_.steps > 0) {
    logger_->onEpisode(episodeRecord_);
    ++summary_.episodes;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  logger_->finish(summary_, seconds, peakRssKb());
  publishProgress("trial " + std::to_string(trial + 1) + "/" + std::to_string(config_.trials) +
                  " done: " + std::to_string(summary_.steps) + " steps, total reward " +
                  std::to_string(summary_.totalReward));
  return true;
}

int ExperimentNode::run() {
  int failed = 0;
  std::vector<int> trials;
  if (experiment_ != nullptr) {
    trials = experiment_->pendingTrials();  // with --resume, the unfinished ones
  } else {
    for (int t = 0; t < config_.trials; ++t) trials.push_back(t);
  }
  if (static_cast<int>(trials.size()) < config_.trials) {
    publishProgress("resuming: " + std::to_string(config_.trials - int(trials.size())) +
                    " trial(s) already finished");
  }
  for (int trial : trials) {
    if (!ros::ok()) break;
    if (!runTrial(trial)) ++failed;
    if (experiment_ != nullptr) experiment_->collect();
  }
  publishProgress("finished: " + std::to_string(config_.trials - failed) + "/" +
                  std::to_string(config_.trials) + " trials");
  return failed;
}

}  // namespace rl_experiment
