// Standalone experiment runner: an agent and an environment in one process, no ROS master.
// Prints the original's data stream (one bare number per episode, or per step for
// non-episodic tasks) on stderr and the configuration and a summary on stdout.
#include <cstdint>
#include <iostream>
#include <memory>

#include "rl_agent/agent/agent_registry.h"
#include "rl_common/random.h"
#include "rl_env/env/environment_registry.h"
#include "rl_experiment/runner/trial_runner.h"

namespace {

// The original's stderr stream: one number per episode, or per step if non-episodic.
class OriginalFormatPrinter : public rl_experiment::TrialObserver {
 public:
  explicit OriginalFormatPrinter(bool perStep) : perStep_(perStep) {}
  void onStep(const rl_experiment::StepRecord& r) override {
    if (perStep_) std::cerr << r.reward << "\n";
  }
  void onEpisode(const rl_experiment::EpisodeRecord& r) override {
    if (!perStep_) std::cerr << r.reward << std::endl;
  }

 private:
  bool perStep_;
};

}  // namespace

int main(int argc, char** argv) {
  rl_agent::AgentOptions agentOptions;
  agentOptions.agent = "qlearner";
  rl_env::EnvironmentOptions envOptions;
  int nepisodes = 1000;
  int maxsteps = 1000;
  int trials = 1;
  rl_common::OptionParser parser("experiment", "--agent <type> --env <type> [options]");
  rl_agent::addAgentOptions(parser, &agentOptions);
  rl_env::addEnvironmentOptions(parser, &envOptions);
  parser.value("nepisodes", &nepisodes,
               "episodes per trial (steps for non-episodic tasks, as the original)",
               rl_common::atLeast(0));
  parser.value("maxsteps", &maxsteps, "actions per episode before it is cut off",
               rl_common::greaterThan(0));
  parser.value("trials", &trials, "number of trials", rl_common::greaterThan(0));
  try {
    if (!parser.parse(argc, argv)) {
      std::cout << parser.help();
      return 0;
    }
    rl_env::checkEnvironmentOptions(parser, envOptions);
    rl_agent::agentRegistry().canonical(agentOptions.agent);
    rl_env::environmentRegistry().canonical(envOptions.env);
    rl_agent::applyAgentDefaults(parser, &agentOptions);
    rl_agent::checkAgentOptions(parser, agentOptions);
    const std::uint64_t runSeed = envOptions.seed;
    for (const auto& [name, value] : parser.currentValues()) {
      std::cout << "config " << name << " = " << value << "\n";
    }
    for (int trial = 0; trial < trials; ++trial) {
      // Independent streams per trial and component (the original shared one stream).
      rl_env::EnvironmentOptions eo = envOptions;
      eo.seed = rl_common::Random::deriveSeed(runSeed, "environment", trial);
      rl_agent::AgentOptions ao = agentOptions;
      ao.seed = rl_common::Random::deriveSeed(runSeed, "agent", trial);
      auto env = rl_env::makeEnvironment(eo);
      auto agent = rl_agent::makeAgent(ao, env->describe());
      std::cout << "Environment is " << (env->isEpisodic() ? "" : "NOT ") << "episodic."
                << std::endl;
      rl_experiment::TrialLimits limits;
      limits.steps = nepisodes;
      limits.episodes = nepisodes;
      limits.maxSteps = maxsteps;
      OriginalFormatPrinter printer(!env->isEpisodic());
      const auto summary = rl_experiment::TrialRunner(limits).run(*env, *agent, &printer);
      std::cout << "trial " << trial << ": " << summary.steps << " steps, " << summary.episodes
                << " episodes, total reward " << summary.totalReward << std::endl;
    }
  } catch (const rl_common::OptionError& e) {
    std::cerr << e.what() << "\n(see experiment --help)\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "experiment: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
