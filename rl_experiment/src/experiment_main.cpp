// Standalone experiment runner: an agent and an environment in one process, no ROS master.
// Writes the logs of every trial into --out (see rl_experiment/runner/experiment.h), prints the
// configuration and one line per trial on stdout, a progress bar on a terminal, and with
// --format original the original's bare-number stream on stderr.
#include <unistd.h>

#include <climits>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "rl_agent/agent/agent_registry.h"
#include "rl_experiment/runner/experiment.h"
#include "rl_experiment/runner/slurm_submit.h"
#include "rl_experiment/suite/suite_environments.h"

namespace {

// --slurm: the sweep's submitter takes over this process (it prints the job ids).
int submitToSlurm(const rl_common::OptionParser& parser, const rl_experiment::SlurmConfig& slurm,
                  const rl_experiment::ExperimentConfig& config, const std::string& commandLine) {
  char self[PATH_MAX] = {0};
  const ssize_t n = readlink("/proc/self/exe", self, sizeof(self) - 1);
  if (n <= 0) {
    std::cerr << "experiment: cannot find this program's path (/proc/self/exe)\n";
    return 1;
  }
  const std::string runner(self, static_cast<std::size_t>(n));
  const std::string python = access("/usr/bin/python3", X_OK) == 0 ? "/usr/bin/python3" : "python3";
  std::vector<std::string> cmd = rl_experiment::slurmSubmitCommand(
      parser, slurm, config, runner, python, rl_experiment::slurmSweepScript(runner), commandLine);
  std::vector<char*> args;
  for (std::string& a : cmd) args.push_back(a.data());
  args.push_back(nullptr);
  execvp(args[0], args.data());
  std::cerr << "experiment: cannot start " << cmd[0] << " " << cmd[1] << ": "
            << std::strerror(errno) << "\n";
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  rl_experiment::ExperimentConfig config;  // --agent defaults to texplore, as the agent node's
  bool listAgents = false;
  bool check = false;
  rl_common::OptionParser parser("experiment", "--agent <type> --env <type> [options]");
  rl_experiment::addExperimentOptions(parser, &config);
  rl_experiment::SlurmConfig slurm;
  rl_experiment::addSlurmOptions(parser, &slurm);
  parser.flag("list-agents", &listAgents, true,
              "print the registered agents (name and description), one a line, and exit");
  parser.flag("check", &check, true, "validate the options and exit (0 if valid)");
  try {
    if (!parser.parse(argc, argv)) {
      std::cout << parser.help()
                << "\nValid agents: " << rl_common::joinNames(rl_agent::agentRegistry().names())
                << "\nValid environments: "
                << rl_common::joinNames(rl_experiment::suiteEnvironments().registry().names())
                << "\n";
      return 0;
    }
    if (listAgents) {
      for (const auto& name : rl_agent::agentRegistry().names()) {
        std::cout << name << "\t" << rl_agent::agentRegistry().description(name) << "\n";
      }
      return 0;
    }
    rl_experiment::finishExperimentConfig(parser, &config);
    rl_experiment::checkSlurmOptions(parser, slurm, config);
    if (check || slurm.slurm) {
      // Some rules need the task (e.g. --taskkey's range, whether the explorer defers): build
      // the environment and the agent once, as a trial does.
      const auto env = rl_experiment::suiteEnvironments().make(config.env);
      rl_agent::makeAgent(config.agent, env->describe(),
                          dynamic_cast<const rl_common::TrueModel*>(env.get()));
    }
  } catch (const rl_common::OptionError& e) {
    std::cerr << "experiment: " << e.what() << "\n(see experiment --help)\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "experiment: " << e.what() << "\n(see experiment --help)\n";
    return 2;
  }
  if (check) return 0;

  std::string commandLine;
  for (int i = 0; i < argc; ++i) commandLine += (i > 0 ? " " : "") + std::string(argv[i]);
  if (slurm.slurm) return submitToSlurm(parser, slurm, config, commandLine);
  auto values = parser.currentValues();
  try {
    rl_experiment::Experiment experiment(config, values, commandLine);
    experiment.prepare();
    std::cout << "suite version: " << rl_experiment::suiteVersion() << "\n";
    for (const auto& [name, value] : values) {
      if (name != "list-agents" && name != "check") {
        std::cout << "config " << name << " = " << value << "\n";
      }
    }
    std::cout << "Environment is "
              << (rl_experiment::suiteEnvironments().make(config.env)->isEpisodic() ? "" : "NOT ")
              << "episodic." << std::endl;
    const int failed = experiment.run(std::cout, std::cerr);
    if (!config.out.empty()) std::cout << "logs in " << config.out << "\n";
    return failed == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "experiment: " << e.what() << "\n";
    return 1;
  }
}
