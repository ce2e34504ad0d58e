#include "rl_agent/agent/agent_options.h"

#include <algorithm>
#include <thread>
#include <utility>
#include <vector>

#include "rl_agent/agent/agent_registry.h"
#include "rl_agent/model/model_registry.h"
#include "rl_agent/planner/planner_registry.h"
#include "rl_agent/reward/explorer_registry.h"
#include "rl_common/registry.h"

namespace rl_agent {

void addAgentOptions(rl_common::OptionParser& p, AgentOptions* o) {
  using rl_common::atLeast;
  using rl_common::greaterThan;
  using rl_common::inRange;
  p.value("agent", &o->agent, "agent type");
  p.value("gamma|discountfactor", &o->gamma, "discount factor", inRange(0.0f, 1.0f));
  p.value("epsilon", &o->epsilon, "epsilon-greedy exploration rate", inRange(0.0f, 1.0f));
  p.value("alpha", &o->alpha, "learning rate", inRange(0.0f, 1.0f));
  p.value("initialvalue", &o->initialvalue, "initial Q-value");
  p.value("actrate", &o->actrate, "actions per second (Hz) of the real-time agent",
          greaterThan(0.0f));
  p.value("lambda", &o->lambda, "UCT(lambda) mixing or Sarsa(lambda) trace decay",
          inRange(0.0f, 1.0f));
  p.value("m", &o->m, "visits before a state-action is known (R-MAX)", atLeast(0));
  // The component names come from their registries (with the original's other spellings).
  p.aliasedChoice("model", &o->model, modelRegistry().spellings(), "model type");
  p.choice("explore", &o->explore, explorerRegistry().names(), "exploration type");
  p.aliasedChoice("combo|modelcombo", &o->combo,
                  {{"average", "average"},
                   {"weighted", "weighted"},
                   {"best", "best"},
                   {"separate", "separate"}},
                  "how a forest combines its trees (texplore: separate, one full tree plans and "
                  "the forest gives the variance; the original's texplore: average)");
  p.choice("taskcombo", &o->taskcombo,
           {"same", "average", "weighted", "best", "separate", "bagged"},
           "--taskplanner vi: how the forests combine their trees for planning the task phase "
           "(same: --combo, but average after texplore's --combo separate; bagged: the average of "
           "the trees other than --combo separate's planning tree)");
  p.aliasedChoice("planner", &o->planner, plannerRegistry().spellings(), "planner");
  // Upper bounds keep a typo from exhausting memory or planning for hours in one step.
  p.value("nmodels", &o->nmodels, "trees per forest", inRange(1, 1000));
  p.flag("reltrans", &o->reltrans, true, "predict relative changes s'-s (default)");
  p.flag("abstrans", &o->reltrans, false, "predict absolute next states s'");
  p.value("v|b", &o->v, "VANIR variance (tree disagreement) reward coefficient", atLeast(0.0f));
  p.value("n", &o->n, "VANIR novelty reward coefficient", atLeast(0.0f));
  p.choice("novelty", &o->novelty, {"stateaction", "state"},
           "VANIR's novelty: of (s, a) against the states where a was taken (stateaction, the "
           "original), or of s against the states where any action was taken (state)");
  p.value("history", &o->history, "action-history length", inRange(0, 100));
  p.value("nstates", &o->nstates,
          "bins per feature: one count for every feature, or one per feature, comma-separated "
          "(0: that feature is not binned; 0 alone: no binning)",
          rl_common::OptionParser::Check<std::vector<int>>([](const std::vector<int>& bins) {
            const bool negative =
                std::any_of(bins.begin(), bins.end(), [](int n) { return n < 0; });
            return negative ? std::string("every entry must be >= 0") : std::string();
          }));
  p.value("k", &o->k, "Dyna model updates per step", atLeast(0));
  p.value("filename", &o->filename, "policy file");
  p.flag("pathvisits", &o->pathvisits, true,
         "UCT: at a state met again on a rollout, try the actions not yet chosen there on that "
         "rollout (the original repeats its choice, so a self-loop holds the rollout to the "
         "depth cap)");
  p.value("minprob", &o->minprob,
          "UCT: rollouts sample a feature of a factored prediction only among values of at "
          "least this probability (0: every value, as the original)",
          inRange(0.0f, 1.0f));
  p.value("defer", &o->defer,
          "while exploring, put off one-way steps (learned from the agent's own: features no "
          "action gave back) for this many steps after each one (0: never, as the original)",
          atLeast(0L));
  p.value("deferregions", &o->deferregions,
          "with --defer, put off one-way steps only in the first this many regions (a region "
          "begins at each one-way step; 0: in every region)",
          inRange(0L, 1000000L));
  p.value("depth", &o->depth, "UCT: at most this many simulated actions per rollout",
          greaterThan(0));
  p.flag("bonusonce", &o->bonusonce, true,
         "UCT: a rollout collects a state-action's intrinsic bonus only the first time it takes "
         "it (the original collects it again on every repeat, so self-loops look rich)");
  p.choice("ucb", &o->ucb, {"range", "normalized"},
           "UCT's bound: range = the original's Q + 2 max(R_range,1)/(1-gamma) sqrt(ln N/N_a); "
           "normalized = Q rescaled to [0,1] by the state's Q range + ucbc sqrt(ln N/N_a)");
  p.value("ucbc", &o->ucbc, "UCT: c of --ucb normalized", atLeast(0.0f));
  p.choice("taskucb", &o->taskucb, {"same", "range", "normalized"},
           "UCT's bound once intrinsic rewards are switched off (a task phase); same: --ucb");
  p.value("taskucbc", &o->taskucbc, "UCT: c of --taskucb normalized", atLeast(0.0f));
  p.choice("taskplanner", &o->taskplanner, {"same", "vi"},
           "the planner once intrinsic rewards are switched off (a task phase); same: --planner; "
           "vi: value iteration over the states the learned model reaches from the visited ones");
  p.value("taskdepth", &o->taskdepth,
          "--taskplanner vi: model steps expanded from the current state", greaterThan(0));
  p.value("taskminprob", &o->taskminprob,
          "--taskplanner vi: the learned model's joint outcomes below this probability are not "
          "planned through (lower plans better and slower)",
          inRange(0.0f, 0.999f));
  p.value("tasksweeps", &o->tasksweeps,
          "--taskplanner vi: value-iteration sweeps per task step, warm-started from the last "
          "step's values (0: to convergence)",
          atLeast(0L));
  p.value("taskrecent", &o->taskrecent,
          "--taskplanner vi: the last this many observed states are planned from and stand for "
          "their --taskkey entries (0: only the current state)",
          atLeast(0));
  p.value("taskkey", &o->taskkey,
          "--taskplanner vi: features (0-based, comma-separated) that tell the planner's states "
          "apart; states equal on them share a value (default: all features)");
  p.choice("taskoutcomes", &o->taskoutcomes, {"joint", "key"},
           "--taskplanner vi with --taskkey: the learned model's outcomes planned through; "
           "key: the --taskkey features' joint values, every other feature at its most likely "
           "value; joint: full states, a product over all features (before this option)");
  p.value("rollouts", &o->rollouts,
          "UCT rollouts per step, planned synchronously for reproducible runs (0: plan in real "
          "time at --actrate)",
          inRange(0L, 1000000L));
  p.value("searchthreads", &o->searchthreads,
          "real-time UCT: planning threads, each searching its own tree, whose root values are "
          "averaged (0: one per core)",
          inRange(0, kMaxSearchThreads));
  p.value("tau", &o->tau, "Boltzmann temperature (--explore boltzmann)", greaterThan(0.0f));
}

int searchThreads(const AgentOptions& o) {
  if (o.searchthreads > 0) return o.searchthreads;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

bool plansInRealTime(const AgentOptions& o) {
  return o.rollouts == 0 && agentRegistry().hasFact(o.agent, kModelBasedFact) &&
         plannerRegistry().hasFact(o.planner, kRealTimePlannerFact);
}

bool binsStates(const AgentOptions& o) {
  return std::any_of(o.nstates.begin(), o.nstates.end(), [](int n) { return n > 0; });
}

void checkStatesPerDim(const AgentOptions& o, std::size_t numFeatures) {
  if (o.nstates.size() != 1 && o.nstates.size() != numFeatures) {
    throw std::invalid_argument("--nstates " + rl_common::formatOptionValue(o.nstates) + " has " +
                                std::to_string(o.nstates.size()) +
                                " entries; give one, or one per feature (" +
                                std::to_string(numFeatures) + ")");
  }
}

namespace {

std::vector<std::string> modelFreeAgents() { return agentRegistry().namesWith(kModelFreeFact); }
std::vector<std::string> modelBasedAgents() { return agentRegistry().namesWith(kModelBasedFact); }

bool isOneOf(const std::string& name, const std::vector<std::string>& names) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

void requireAgent(const rl_common::OptionParser& p, const AgentOptions& o, const char* option,
                  const std::vector<std::string>& agents) {
  if (p.given(option) && !isOneOf(o.agent, agents)) {
    throw rl_common::OptionError(std::string("option --") + option + " applies only to --agent " +
                                 rl_common::joinNames(agents) + ", not to '" + o.agent + "'");
  }
}

/// True if the user gave `option` or another option that sets the same field (--reltrans and
/// --abstrans are one choice).
bool givenField(const rl_common::OptionParser& p, const std::string& option) {
  static const std::vector<std::vector<std::string>> oneField{{"reltrans", "abstrans"}};
  for (const auto& group : oneField) {
    if (std::find(group.begin(), group.end(), option) == group.end()) continue;
    return std::any_of(group.begin(), group.end(),
                       [&p](const std::string& o) { return p.given(o); });
  }
  return p.given(option);
}

/// Applies a registry entry's option values that the user did not give, parsed and validated
/// as on the command line.
void applyUnset(const rl_common::OptionParser& p, const rl_common::OptionValues& values,
                AgentOptions* o) {
  rl_common::OptionParser fields("agent", "");
  addAgentOptions(fields, o);
  for (const auto& [option, value] : values) {
    if (!givenField(p, option)) fields.set(option, value);
  }
}

/// The value of `option` in `o` as the option parser shows it, and the value it shows after
/// `value` is applied (equal when `o` already holds `value`, whatever its spelling).
std::pair<std::string, std::string> shownBeforeAndAfter(const AgentOptions& o,
                                                        const std::string& option,
                                                        const std::string& value) {
  AgentOptions copy = o;
  rl_common::OptionParser fields("agent", "");
  addAgentOptions(fields, &copy);
  const auto shown = [&fields, &option] {
    for (const auto& [name, current] : fields.currentValues()) {
      if (name == option) return current;
    }
    throw std::invalid_argument("shownBeforeAndAfter(): no option --" + option);
  };
  const std::string before = shown();
  fields.set(option, value);
  return {before, shown()};
}

}  // namespace

void applyAgentDefaults(const rl_common::OptionParser& p, AgentOptions* o) {
  // The agent's preset (its registry entry): defaults and needed values, where not given.
  // An unknown agent name is reported where the agent is built.
  const AgentRegistry& agents = agentRegistry();
  if (agents.contains(o->agent)) {
    applyUnset(p, agents.defaults(o->agent), o);
    applyUnset(p, agents.needs(o->agent), o);
  }
  // A forest of one tree has nothing to combine: unless --combo is given it plans as best.
  if (!p.given("combo") && o->nmodels == 1) o->combo = "best";
  const ExplorerRegistry& explorers = explorerRegistry();
  if (!p.given("explore") && explorers.contains(o->explore) &&
      explorers.hasFact(o->explore, kGreedyWithoutWeightsFact) && o->v == 0.0f && o->n == 0.0f) {
    o->explore = "greedy";
  }
  // The explorer's own defaults (the region bonuses' weight --v).
  if (explorers.contains(o->explore)) applyUnset(p, explorers.defaults(o->explore), o);
  // Value iteration plans the task on the whole forest's average, whose spread keeps rare
  // outcomes such as a door opening above --taskminprob (the note's §11-§12).
  if (o->combo == "separate" && o->taskplanner == "vi" && !p.given("taskcombo") &&
      modelRegistry().takesOption(o->model, "taskcombo")) {
    o->taskcombo = "average";
  }
}

void checkAgentOptions(const rl_common::OptionParser& p, const AgentOptions& o) {
  const std::vector<std::string> modelFreeList = modelFreeAgents();
  const std::vector<std::string> modelBasedList = modelBasedAgents();
  requireAgent(p, o, "alpha", modelFreeList);
  requireAgent(p, o, "initialvalue", modelFreeList);
  requireAgent(p, o, "k", {"dyna"});
  std::vector<std::string> lambdaAgents = modelBasedList;
  lambdaAgents.push_back("sarsa");
  requireAgent(p, o, "lambda", lambdaAgents);
  for (const char* option : {"actrate",
                             "m",
                             "model",
                             "planner",
                             "combo",
                             "nmodels",
                             "reltrans",
                             "abstrans",
                             "v",
                             "n",
                             "history",
                             "rollouts",
                             "tau",
                             "pathvisits",
                             "ucb",
                             "ucbc",
                             "bonusonce",
                             "taskucb",
                             "taskucbc",
                             "depth",
                             "minprob",
                             "novelty",
                             "taskplanner",
                             "taskdepth",
                             "taskkey",
                             "taskminprob",
                             "tasksweeps",
                             "taskrecent",
                             "searchthreads",
                             "defer",
                             "deferregions",
                             "taskoutcomes",
                             "taskcombo"}) {
    requireAgent(p, o, option, modelBasedList);
  }
  // Values the agent's entry needs (rmax: --model tabular, --explore unknown).
  if (agentRegistry().contains(o.agent)) {
    for (const auto& [option, value] : agentRegistry().needs(o.agent)) {
      const auto [given, needed] = shownBeforeAndAfter(o, option, value);
      if (given != needed) {
        throw rl_common::OptionError("--agent " + o.agent + " needs --" + option + " " + value +
                                     " (got " + given + ")");
      }
    }
  }
  const bool modelBased = isOneOf(o.agent, modelBasedList);
  if (modelBased) {
    const bool searchPlanner = plannerRegistry().hasFact(o.planner, kSearchPlannerFact);
    for (const char* option : {"actrate", "lambda", "history", "rollouts", "pathvisits", "ucb",
                               "ucbc", "bonusonce", "taskucb", "taskucbc", "depth", "minprob"}) {
      if (p.given(option) && !searchPlanner) {
        throw rl_common::OptionError(
            std::string("option --") + option + " needs a UCT planner (" +
            rl_common::joinNames(plannerRegistry().namesWith(kSearchPlannerFact)) + "), not '" +
            o.planner + "'");
      }
    }
    const std::vector<std::string> realTime = plannerRegistry().namesWith(kRealTimePlannerFact);
    if (p.given("searchthreads") && (o.rollouts > 0 || !isOneOf(o.planner, realTime))) {
      throw rl_common::OptionError(
          "option --searchthreads needs the real-time planner (--planner " +
          rl_common::joinNames(realTime, " or ") + ", without --rollouts)");
    }
    if (p.given("defer") && o.defer > 0 && o.history > 0) {
      throw rl_common::OptionError(
          "option --defer does not take --history (an action history never comes back, so "
          "every step would look irreversible)");
    }
    if (o.taskplanner == "vi" && o.history > 0) {
      throw rl_common::OptionError(
          "option --taskplanner vi does not take --history (value "
          "iteration plans on states alone)");
    }
    for (const char* option : {"taskdepth", "taskkey", "taskminprob", "tasksweeps", "taskrecent",
                               "taskoutcomes", "taskcombo"}) {
      if (p.given(option) && o.taskplanner != "vi") {
        throw rl_common::OptionError(std::string("option --") + option + " needs --taskplanner vi");
      }
    }
    if (p.given("taskoutcomes") && o.taskkey.empty()) {
      throw rl_common::OptionError(
          "option --taskoutcomes needs --taskkey (over all features the two are the same)");
    }
    // Each explorer's entry names the options it reads (--v, --n, --tau, --epsilon, ...).
    const ExplorerRegistry& explorers = explorerRegistry();
    for (const std::string& option : explorers.specificOptions()) {
      if (p.given(option) && !explorers.takesOption(o.explore, option)) {
        throw rl_common::OptionError("option --" + option + " applies to --explore " +
                                     rl_common::joinNames(explorers.namesTaking(option)) +
                                     ", not to '" + o.explore + "'");
      }
    }
    try {
      checkModelExplorer(o.model, o.explore);
      checkModelGrid(o.model, o.planner, searchPlanner, binsStates(o));
    } catch (const std::invalid_argument& e) {
      throw rl_common::OptionError(e.what());
    }
    if (p.given("taskcombo") && !modelRegistry().takesOption(o.model, "taskcombo")) {
      throw rl_common::OptionError("option --taskcombo applies to --model " +
                                   rl_common::joinNames(modelRegistry().namesTaking("taskcombo")) +
                                   ", not to '" + o.model + "'");
    }
    if (o.taskcombo != "same" && o.taskcombo != "best" && o.nmodels == 1) {
      throw rl_common::OptionError("option --taskcombo " + o.taskcombo +
                                   " needs --nmodels > 1 (one tree has nothing to combine)");
    }
    if (o.combo != "best" && o.nmodels == 1) {
      throw rl_common::OptionError("option --combo " + o.combo +
                                   " needs --nmodels > 1 (one tree has nothing to combine)");
    }
  } else if (p.given("explore") &&
             !explorerRegistry().hasFact(o.explore, kModelFreeSelectionFact)) {
    throw rl_common::OptionError(
        "option --explore for '" + o.agent + "' must be " +
        rl_common::joinNames(explorerRegistry().namesWith(kModelFreeSelectionFact), " or ") +
        " (it acts epsilon-greedily)");
  }
}

}  // namespace rl_agent
