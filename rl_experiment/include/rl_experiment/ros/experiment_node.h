/**
 * ExperimentNode: runs trials against separately running agent and environment nodes (on any
 * machine of the same ROS master) and writes the same run folder as the standalone runner.
 *
 * Per trial it resets the environment (rl_env/reset, reseeded with the trial's derived
 * environment seed), then the agent (rl_agent/reset, with the agent seed), counts the steps it
 * sees on rl_env/rl_state_reward (with the action from rl_agent/rl_action and the intrinsic parts
 * from rl_agent/rl_reward_breakdown), and ends the trial after `steps` steps. Progress goes out
 * on rl_experiment/progress (std_msgs/String) and to the log. With `resume` it runs only the
 * trials whose summary is not in the run folder yet (a killed run keeps its finished trials),
 * as the standalone runner's --resume.
 *
 * Limits of the ROS mode: the agent and environment keep running between trials, so a step or
 * two around a reset may belong to neither trial; the model accuracy and the press locations
 * need the objects themselves and are only measured by the standalone runner; the reward cannot
 * be hidden from the agent, so there are no phases.
 */
#pragma once

#include <rl_msgs/RLAction.h>
#include <rl_msgs/RLRewardBreakdown.h>
#include <rl_msgs/RLStateReward.h>
#include <ros/ros.h>

#include <memory>
#include <optional>
#include <string>

#include "rl_experiment/log/trial_logger.h"
#include "rl_experiment/runner/experiment.h"

namespace rl_experiment {

class ExperimentNode {
 public:
  /// Counts config.nonEpisodicSteps() steps per trial, config.trials trials seeded from
  /// config.env.seed; the agent and env names are recorded only.
  ExperimentNode(ros::NodeHandle nh, ExperimentConfig config, Experiment* experiment);

  /// Runs every trial; returns the number of failed ones. Spins the node's callbacks itself.
  int run();

  void onAction(const rl_msgs::RLAction::ConstPtr& msg);
  void onBreakdown(const rl_msgs::RLRewardBreakdown::ConstPtr& msg);
  void onState(const rl_msgs::RLStateReward::ConstPtr& msg);

 private:
  bool runTrial(int trial);
  bool callReset(ros::ServiceClient& client, const std::string& what, std::uint64_t seed);
  void publishProgress(const std::string& text);

  ros::NodeHandle nh_;
  ExperimentConfig config_;
  Experiment* experiment_;
  ros::Subscriber actionSub_, breakdownSub_, stateSub_;
  ros::Publisher progressPub_;
  ros::ServiceClient envReset_, agentReset_;

  // The trial being counted.
  std::unique_ptr<TrialLogger> logger_;
  bool counting_ = false;
  long steps_ = 0;
  int episode_ = 0;
  TrialSummary summary_;
  EpisodeRecord episodeRecord_;
  std::optional<int> lastAction_;
  std::optional<rl_msgs::RLRewardBreakdown> lastBreakdown_;
  ros::WallTime lastStepTime_;
};

}  // namespace rl_experiment
