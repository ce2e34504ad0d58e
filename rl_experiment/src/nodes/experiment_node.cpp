// The experiment node: `rosrun rl_experiment experiment_node --steps 500 --trials 3 --out DIR`.
// Runs trials against separately running agent and env nodes (see ExperimentNode). Options also
// come from ~private parameters (dashes become underscores); the command line wins.
#include <ros/ros.h>

#include <iostream>
#include <memory>

#include "rl_common/ros/param_loader.h"
#include "rl_common/ros/ros_home.h"
#include "rl_experiment/ros/experiment_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "experiment");
  rl_experiment::ExperimentConfig config;  // the runner's config: one default per option
  rl_common::OptionParser parser("experiment_node", "[--steps N] [--trials N] [--out DIR] ...");
  // The node counts steps, as the runner does on a non-episodic task: --steps is that count
  // (the runner's --nepisodes, which its --steps overrides).
  parser.value("steps", &config.nepisodes, "steps per trial", rl_common::greaterThan(0));
  parser.value("trials", &config.trials, "number of trials", rl_common::greaterThan(0));
  parser.value("seed", &config.env.seed, "run seed: trial seeds are derived from it");
  parser.value("out", &config.out,
               "folder for the logs (auto: a new folder under ROS_HOME/rl_experiment; none: no "
               "files)");
  parser.flag("force", &config.force, true, "overwrite the results in --out");
  parser.flag("resume", &config.resume, true,
              "finish the unfinished trials in --out (the same options as the run it resumes)");
  parser.value("label", &config.label, "name of this run in figures (default: the agent)");
  parser.value("agent", &config.agent.agent, "the agent node's type (recorded in the logs)");
  parser.value("env", &config.env.env, "the env node's environment (recorded in the logs)");
  parser.value("timeout", &config.stepTimeout, "seconds without a step before a trial fails",
               rl_common::greaterThan(0.0));
  const rl_common::NodeStart start =
      rl_common::startNode(parser, argc, argv, "experiment_node", [&] {
        if (config.resume && (config.force || config.out.empty() || config.out == "auto")) {
          throw rl_common::OptionError(
              "option --resume needs the --out folder of the run to finish, and not --force");
        }
      });
  if (!start) return start.exitCode;
  if (config.out == "auto") {
    const std::string home = rl_common::rosHome();
    config.out = (home.empty() ? std::string("/tmp") : home) + "/rl_experiment/run-" +
                 rl_common::localTimestamp();
    ROS_INFO_STREAM_NAMED("experiment_node", "out=auto: the run folder is " << config.out);
  }
  std::string commandLine;
  for (int i = 0; i < argc; ++i) commandLine += (i > 0 ? " " : "") + std::string(argv[i]);
  if (config.label.empty()) config.label = config.agent.agent;
  rl_experiment::Experiment experiment(config, parser.currentValues(), commandLine);
  try {
    experiment.prepare();
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM_NAMED("experiment", e.what());
    std::cerr << "experiment_node: " << e.what() << "\n";
    return 1;
  }
  rl_experiment::ExperimentNode node(ros::NodeHandle(), config, &experiment);
  const int failed = node.run();
  // The last progress message ("finished ...") leaves on the network thread: give it time to
  // reach the subscribers before the publisher goes away with the node.
  ros::WallDuration(1.0).sleep();
  return failed == 0 ? 0 : 1;
}
