// The agent node: `rosrun rl_agent agent --agent texplore --v 1 --n 3`. Options also come from
// ~private parameters (the command line wins); see AgentNode for the protocol.
//
// `--agent optimal --env E [--deterministic ...]` builds a private copy of environment E from
// rl_env's registry as the true model the agent plans on (value iteration); E and its options
// must be those of the env node, which the node checks against the received description.
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
#include "rl_common/true_model.h"
#include "rl_env/env/environment_registry.h"

namespace {

/// The true-model environment of `optimal`, or null for every other agent. Throws
/// rl_common::OptionError if --env (or an environment option) is missing, misplaced or invalid.
std::unique_ptr<rl_common::Environment> trueModelEnvironment(
    const rl_common::OptionParser& parser, const rl_agent::AgentOptions& options,
    rl_env::EnvironmentOptions envOptions) {
  const bool optimal = options.agent == "optimal";
  if (!optimal) {
    rl_common::OptionParser envOnly("agent", "");
    rl_env::EnvironmentOptions unused;
    envOnly.value("env", &unused.env, "");
    rl_env::addEnvironmentVariantOptions(envOnly, &unused);
    for (const auto& spec : envOnly.specs()) {
      if (parser.given(spec.name)) {
        throw rl_common::OptionError(
            "option --" + spec.name + " applies only to --agent optimal, which plans on its own " +
            "copy of the env node's environment: agent --agent optimal --env {" +
            rl_common::joinNames(rl_env::environmentRegistry().namesWith(rl_env::kTrueModelFact),
                                 "|") +
            "} [--seed S] [the env node's options, e.g. " +
            "--deterministic]; every other agent learns from the env node's messages alone");
      }
    }
    return nullptr;
  }
  if (!parser.given("env")) {
    throw rl_common::OptionError(
        "--agent optimal needs --env <name>: the env node's environment (one of " +
        rl_env::trueModelEnvironments() + "), with the env node's options (e.g. --deterministic)");
  }
  rl_env::checkEnvironmentOptions(parser, envOptions);
  try {
    envOptions.env = rl_env::environmentRegistry().canonical(envOptions.env);
  } catch (const std::invalid_argument& e) {
    throw rl_common::OptionError(std::string("option --env: ") + e.what());
  }
  envOptions.seed = options.seed;  // never stepped: only its dynamics are used
  auto env = rl_env::makeEnvironment(envOptions);
  if (dynamic_cast<const rl_common::TrueModel*>(env.get()) == nullptr) {
    throw rl_common::OptionError("option --env: '" + envOptions.env +
                                 "' offers no true model for --agent optimal (valid: " +
                                 rl_env::trueModelEnvironments() + ")");
  }
  return env;
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

int main(int argc, char** argv) {
  ros::init(argc, argv, "RLAgent", ros::init_options::NoSigintHandler);
  std::signal(SIGINT, onSigint);
  rl_agent::AgentOptions options;
  rl_env::EnvironmentOptions envOptions;
  envOptions.env.clear();  // none unless --agent optimal
  rl_common::OptionParser parser("agent", "--agent <type> [options]");
  rl_agent::addAgentOptions(parser, &options);
  parser.value("seed", &options.seed, "seed of the agent's random source");
  parser.value("env", &envOptions.env,
               "--agent optimal only: the env node's environment, built privately as the true "
               "model to plan on (" +
                   rl_env::trueModelEnvironments() + "); give the env node's options too");
  rl_env::addEnvironmentVariantOptions(parser, &envOptions);
  rl_agent::JournalSettings journal;
  parser.value("journal", &journal.journal,
               "append every experience the agent learns from to this file, flushed per record "
               "(the original's experience-file layout behind a header; an existing journal of "
               "the same task is appended to); auto: a new file under "
               "ROS_HOME/rl_agent/journals (empty: none)");
  parser.value("resume-journal", &journal.resume,
               "before acting, rebuild the agent's model from the experiences of this journal "
               "(e.g. the --journal of a killed node; a record cut by the kill is dropped)");
  std::unique_ptr<rl_common::Environment> trueModelEnv;
  std::unique_ptr<ros::NodeHandle> pnh;
  try {
    // --help must work without a master: look at argv before the parameter server.
    if (!parser.parse(argc, argv)) {
      std::cout << parser.help()
                << "\nValid agents: " << rl_common::joinNames(rl_agent::agentRegistry().names())
                << "\n";
      return 0;
    }
    // Keep this first node handle until the end: the last handle's destruction shuts the node
    // down, and logging with it (a temporary here silenced every later ROS_* line).
    pnh = std::make_unique<ros::NodeHandle>("~");
    rl_common::loadPrivateParams(parser, *pnh);
    parser.parse(argc, argv);  // the command line wins over parameters
    options.agent = rl_agent::agentRegistry().canonical(options.agent);
    rl_agent::applyAgentDefaults(parser, &options);
    rl_agent::checkAgentOptions(parser, options);
    trueModelEnv = trueModelEnvironment(parser, options, envOptions);
    if (!journal.resume.empty()) {
      rl_agent::readExperienceJournal(journal.resume);  // a missing or foreign file: exit 2 now
    }
  } catch (const std::exception& e) {
    std::cerr << "agent: " << e.what() << "\n";
    return 2;
  }
  std::string config;
  for (const auto& [name, value] : parser.currentValues()) config += " " + name + "=" + value;
  ROS_INFO_STREAM_NAMED("agent", "configuration:" << config);
  journal.header = {{"written_by", "rl_agent agent node"},
                    {"version", RL_AGENT_VERSION},
                    {"agent", options.agent},
                    {"seed", std::to_string(options.seed)},
                    {"config", config.empty() ? config : config.substr(1)}};
  if (journal.journal == "auto") {
    try {
      journal.journal = autoJournalPath();
    } catch (const std::exception& e) {
      std::cerr << "agent: --journal auto: " << e.what() << "\n";
      return 2;
    }
  }
  rl_agent::AgentNode node(ros::NodeHandle(), options, std::move(trueModelEnv), std::move(journal));
  ros::spin();
  return node.failed() ? 1 : 0;
}
