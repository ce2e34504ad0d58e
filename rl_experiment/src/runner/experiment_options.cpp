// The runner's options: declared once for the `experiment` program and checked as a whole.
#include <algorithm>
#include <string>
#include <thread>

#include "rl_agent/agent/agent_registry.h"
#include "rl_env/env/environment_registry.h"
#include "rl_experiment/runner/experiment.h"
#include "rl_experiment/suite/suite_environments.h"

namespace rl_experiment {

void addExperimentOptions(rl_common::OptionParser& p, ExperimentConfig* c) {
  using rl_common::atLeast;
  using rl_common::greaterThan;
  rl_agent::addAgentOptions(p, &c->agent);
  rl_env::addEnvironmentOptions(p, &c->env, suiteEnvironments());
  p.value("nepisodes", &c->nepisodes,
          "episodes per trial (steps for non-episodic tasks, as the original)", atLeast(0));
  p.value("steps", &c->steps, "steps per trial of a non-episodic task (overrides --nepisodes)",
          atLeast(0));
  p.value("maxsteps", &c->maxsteps, "actions per episode before it is cut off", greaterThan(0));
  p.value("trials", &c->trials, "number of trials", greaterThan(0));
  p.value("first-trial", &c->firstTrial,
          "number of the first trial (split a sweep over machines: same seeds per trial)",
          atLeast(0));
  p.value("explore-steps", &c->exploreSteps,
          "phase 1: steps with the external reward hidden from the agent, intrinsic rewards on",
          atLeast(0));
  p.value("task-steps", &c->taskSteps,
          "phase 2 (after --explore-steps): steps with the external reward, intrinsic rewards "
          "off",
          atLeast(0));
  p.choice("task-rewards", &c->taskRewards, {"given", "learned"},
           "at the switch to --task-steps, model-based agents are given the task's reward "
           "of their exploration steps and rebuild their model (given: the paper's "
           "\"provided with a reward function\"), or learn it from the task steps only "
           "(learned)");
  p.value("eval-every", &c->evalEvery,
          "measure the model's accuracy every this many steps (0: never)", atLeast(0));
  p.value("eval-samples", &c->evalSamples, "state-actions sampled per accuracy measurement",
          greaterThan(0));
  p.value("eval-groups", &c->evalGroups,
          "also measure the accuracy per group of states, grouped by the values of these "
          "features (comma-separated indices, e.g. 4,2: LightWorld's room and have_key); "
          "groups-NNN.csv",
          rl_common::OptionParser::Check<std::vector<int>>([](const std::vector<int>& f) {
            for (int i : f) {
              if (i < 0) return std::string("feature indices must be >= 0");
            }
            return std::string();
          }));
  p.value("out", &c->out, "folder for the logs (none: no files)");
  p.flag("force", &c->force, true, "overwrite the results in --out");
  p.flag("journal", &c->journal, true,
         "every trial's agent appends the experiences it learns from to journal-NNN.rlj in "
         "--out, flushed per record (the agent node's --journal layout)");
  p.flag("resume", &c->resume, true, "finish the unfinished trials in --out");
  p.value("jobs", &c->jobs, "trials run in parallel processes", greaterThan(0));
  p.choice("format", &c->format, {"csv", "original"},
           "csv: logs only; original: also the original's bare numbers on stderr");
  p.value("label", &c->label, "name of this run in figures (default: the agent)");
  p.choice("progress", &c->progress, {"auto", "on", "off"},
           "progress bar on stderr (auto: only on a terminal)");
}

void finishExperimentConfig(const rl_common::OptionParser& p, ExperimentConfig* c) {
  const rl_env::EnvironmentCatalog& environments = suiteEnvironments();
  rl_env::checkEnvironmentOptions(p, c->env, environments);  // an unknown --env too
  c->env.env = environments.registry().canonical(c->env.env);
  try {
    c->agent.agent = rl_agent::agentRegistry().canonical(c->agent.agent);
  } catch (const std::invalid_argument& e) {
    throw rl_common::OptionError(std::string("option --agent: ") + e.what());
  }
  if (rl_agent::agentRegistry().hasFact(c->agent.agent, rl_agent::kTrueModelPlannerFact) &&
      !environments.registry().hasFact(c->env.env, rl_env::kTrueModelFact)) {
    throw rl_common::OptionError("--agent optimal plans on the environment's true model; --env " +
                                 c->env.env + " has none (valid: " + environments.trueModelNames() +
                                 ")");
  }
  rl_agent::applyAgentDefaults(p, &c->agent);
  rl_agent::checkAgentOptions(p, c->agent);
  // Parallel trials share the cores: each real-time agent plans with its share of them unless
  // --searchthreads says otherwise (the run records the value used). Only real-time planning
  // reads it, so a fixed-rollout run's configuration does not depend on --jobs (and resumes
  // with another --jobs).
  if (c->jobs > 1 && rl_agent::plansInRealTime(c->agent) && !p.given("searchthreads")) {
    c->agent.searchthreads =
        std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / c->jobs);
  }
  if (c->force && c->resume) {
    throw rl_common::OptionError("options --force and --resume exclude each other");
  }
  if ((c->force || c->resume || c->journal) && c->out.empty()) {
    throw rl_common::OptionError("options --force, --resume and --journal need --out");
  }
  if (c->format == "original" && c->jobs > 1) {
    throw rl_common::OptionError(
        "option --format original needs --jobs 1 (the bare-number stream has no trial column)");
  }
  // A task phase alone is allowed (intrinsic rewards off from the start).
  if (p.given("task-rewards") && (c->exploreSteps == 0 || c->taskSteps == 0)) {
    throw rl_common::OptionError(
        "option --task-rewards needs both phases (--explore-steps and --task-steps > 0)");
  }
  if ((c->exploreSteps > 0 || c->taskSteps > 0) && (p.given("steps") || p.given("nepisodes"))) {
    throw rl_common::OptionError(
        "options --explore-steps/--task-steps set the trial's length; do not combine them with "
        "--steps or --nepisodes");
  }
  if (c->label.empty()) c->label = c->agent.agent;
  for (char ch : c->label) {
    if (ch == ',' || ch == '\n' || ch == '/' || ch == ' ') {
      throw rl_common::OptionError("option --label: no commas, slashes or spaces, got '" +
                                   c->label + "'");
    }
  }
}

}  // namespace rl_experiment
