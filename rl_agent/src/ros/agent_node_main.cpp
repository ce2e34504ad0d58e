#include "rl_agent/ros/agent_node_main.h"

#include <ros/ros.h>

#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "rl_agent/agent/agent_registry.h"
#include "rl_agent/journal/experience_journal.h"
#include "rl_agent/ros/agent_node.h"
#include "rl_common/ros/param_loader.h"
#include "rl_common/ros/ros_home.h"
#include "rl_common/stop_request.h"

namespace rl_agent {

namespace {

/// The true-model environment of an agent that plans on one (optimal), or null for every other
/// agent. Throws rl_common::OptionError if the node cannot build one, or if an option of the
/// source is given for an agent that learns from the env node's messages alone.
std::unique_ptr<rl_common::Environment> trueModelEnvironment(const rl_common::OptionParser& parser,
                                                             const AgentOptions& options,
                                                             TrueModelSource* source) {
  if (!agentRegistry().hasFact(options.agent, kTrueModelPlannerFact)) {
    if (source != nullptr) {
      for (const std::string& name : source->optionNames()) {
        if (parser.given(name)) {
          throw rl_common::OptionError(
              "option --" + name + " applies only to --agent optimal, which plans on its own " +
              "copy of the env node's environment; every other agent learns from the env " +
              "node's messages alone");
        }
      }
    }
    return nullptr;
  }
  if (source == nullptr) {
    throw rl_common::OptionError(
        "--agent " + options.agent +
        " plans on the environment's true model, which this node cannot build (rl_agent knows "
        "no environment): run `rosrun rl_experiment optimal_agent --env <name>` with the env "
        "node's options instead");
  }
  return source->make(parser, options.seed);
}

/// Ctrl-C: roscpp's own handler only requests shutdown, which the node sees after the step it
/// is planning (20,000 rollouts take over 10 s); this one also ends the step at its next rollout.
void onSigint(int) {
  rl_common::requestStop();
  ros::requestShutdown();
}

/// ROS_HOME/rl_agent/journals/journal-<local time>-<pid>.rlj (ROS_HOME: ~/.ros if unset),
/// its folder created.
std::string autoJournalPath() {
  const std::string home = rl_common::rosHome();
  if (home.empty()) throw std::runtime_error("neither ROS_HOME nor HOME is set");
  const std::filesystem::path dir = std::filesystem::path(home) / "rl_agent" / "journals";
  std::filesystem::create_directories(dir);
  return (dir /
          ("journal-" + rl_common::localTimestamp() + "-" + std::to_string(::getpid()) + ".rlj"))
      .string();
}

}  // namespace

int runAgentNodeMain(int argc, char** argv, TrueModelSource* source, const std::string& program,
                     const std::string& defaultAgent) {
  std::signal(SIGINT, onSigint);
  AgentOptions options;
  options.agent = defaultAgent;
  rl_common::OptionParser parser(program, "--agent <type> [options]");
  addAgentOptions(parser, &options);
  parser.value("seed", &options.seed, "seed of the agent's random source");
  if (source != nullptr) source->addOptions(parser);
  JournalSettings journal;
  parser.value("journal", &journal.journal,
               "append every experience the agent learns from to this file, flushed per record "
               "(the original's experience-file layout behind a header; an existing journal of "
               "the same task is appended to); auto: a new file under "
               "ROS_HOME/rl_agent/journals (empty: none)");
  parser.value("resume-journal", &journal.resume,
               "before acting, rebuild the agent's model from the experiences of this journal "
               "(e.g. the --journal of a killed node; a record cut by the kill is dropped)");
  std::string modelPredictions;
  parser.value("model-predictions", &modelPredictions,
               "when the node shuts down, write the learned model's predictions (next-feature "
               "distributions, reward, termination) for every action in each state the node has "
               "seen to this CSV file; model-based agents without --history (empty: none)");
  std::unique_ptr<rl_common::Environment> trueModelEnv;
  const rl_common::NodeStart start = rl_common::startNode(
      parser, argc, argv, program,
      [&] {
        options.agent = agentRegistry().canonical(options.agent);
        applyAgentDefaults(parser, &options);
        checkAgentOptions(parser, options);
        trueModelEnv = trueModelEnvironment(parser, options, source);
        if (!journal.resume.empty()) {
          readExperienceJournal(journal.resume);  // a missing or foreign file: exit 2 now
        }
        if (!modelPredictions.empty() &&
            (!agentRegistry().hasFact(options.agent, kModelBasedFact) || options.history > 0)) {
          throw std::invalid_argument(
              "option --model-predictions needs a learned model queried by state alone: --agent " +
              rl_common::joinNames(agentRegistry().namesWith(kModelBasedFact)) +
              " with --history 0 (got --agent " + options.agent + ", --history " +
              std::to_string(options.history) + ")");
        }
      },
      "\nValid agents: " + rl_common::joinNames(agentRegistry().names()) + "\n");
  if (!start) return start.exitCode;
  journal.header = {{"written_by", "rl_agent " + program + " node"},
                    {"version", RL_AGENT_VERSION},
                    {"agent", options.agent},
                    {"seed", std::to_string(options.seed)},
                    {"config", parser.currentValuesLine()}};
  if (journal.journal == "auto") {
    try {
      journal.journal = autoJournalPath();
    } catch (const std::exception& e) {
      std::cerr << program << ": --journal auto: " << e.what() << "\n";
      return 2;
    }
  }
  AgentNode node(ros::NodeHandle(), options, std::move(trueModelEnv), std::move(journal),
                 modelPredictions);
  ros::spin();
  return node.failed() ? 1 : 0;
}

}  // namespace rl_agent
