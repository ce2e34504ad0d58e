#include "rl_agent/agent/agent_registry.h"

#include <stdexcept>

#include "rl_agent/agent/discretization_agent.h"
#include "rl_agent/agent/dyna.h"
#include "rl_agent/agent/model_based_agent.h"
#include "rl_agent/agent/optimal_agent.h"
#include "rl_agent/agent/q_learner.h"
#include "rl_agent/agent/sarsa.h"
#include "rl_agent/agent/saved_policy.h"

namespace rl_agent {

namespace {

AgentRegistry buildRegistry() {
  AgentRegistry reg("agent");
  reg.add("qlearner",
          [](const AgentOptions& o, const rl_common::EnvironmentDescription& d) {
            QLearner::Config c;
            c.numActions = d.numActions;
            c.gamma = o.gamma;
            c.initialValue = o.initialvalue;
            c.alpha = o.alpha;
            c.epsilon = o.epsilon;
            return std::make_unique<QLearner>(c, o.seed);
          },
          "tabular Q-learning, epsilon-greedy (Watkins & Dayan 1992)",
          {kModelFreeFact, kBinnedStatesFact});
  reg.add("sarsa",
          [](const AgentOptions& o, const rl_common::EnvironmentDescription& d) {
            Sarsa::Config c;
            c.numActions = d.numActions;
            c.gamma = o.gamma;
            c.initialValue = o.initialvalue;
            c.alpha = o.alpha;
            c.epsilon = o.epsilon;
            c.lambda = o.lambda;
            return std::make_unique<Sarsa>(c, o.seed);
          },
          "tabular Sarsa(lambda), replacing traces decaying by gamma*lambda (Rummery & Niranjan "
          "1994; Sutton & Barto 2018)",
          {kModelFreeFact, kBinnedStatesFact});
  reg.add("dyna",
          [](const AgentOptions& o, const rl_common::EnvironmentDescription& d) {
            Dyna::Config c;
            c.numActions = d.numActions;
            c.gamma = o.gamma;
            c.initialValue = o.initialvalue;
            c.alpha = o.alpha;
            c.epsilon = o.epsilon;
            c.k = o.k;
            return std::make_unique<Dyna>(c, o.seed);
          },
          "Dyna-Q: Q-learning plus --k replayed updates per step (Sutton 1990)",
          {kModelFreeFact, kBinnedStatesFact});
  const auto modelBased = [](const AgentOptions& o, const rl_common::EnvironmentDescription& d) {
    return std::make_unique<ModelBasedAgent>(o, d);
  };
  reg.add("texplore", modelBased,
          "TEXPLORE: random-forest model, UCT(lambda) in real time; with --v/--n "
          "TEXPLORE-VANIR (Hester & Stone 2013, 2017)",
          {kModelBasedFact});
  reg.add("modelbased", modelBased, "model-based agent with the chosen --model and --planner",
          {kModelBasedFact});
  reg.add("rmax", modelBased,
          "R-MAX: tabular model, optimistic for state-actions seen fewer than --m times, value "
          "iteration (Brafman & Tennenholtz 2002)",
          {kModelBasedFact});
  // The presets: what --agent texplore and --agent rmax mean (shared/spec/ORIGINAL.md §3.1).
  // The separate forest (the original's SEPARATE): plan on one tree that learns every
  // experience, take the variance from the whole forest; with it TEXPLORE-VANIR's model beats
  // every explorer's at step 1000, each on the same forest (docs/science/lightworld-curiosity.md
  // §11-§13). --combo average is the original's default; one tree plans as best. texplore is
  // TEXPLORE-VANIR with --v or --n, plain greedy TEXPLORE without (kGreedyWithoutWeightsFact).
  reg.setOptionValues("texplore", {{"model", "tree"},
                                   {"planner", "parallel-uct"},
                                   {"nmodels", "5"},
                                   {"combo", "separate"},
                                   {"reltrans", "true"},
                                   {"m", "0"},
                                   {"explore", "variancenovelty"}});
  reg.setOptionValues(
      "rmax",
      {{"combo", "best"}, {"planner", "vi"}, {"nmodels", "1"}, {"reltrans", "false"}, {"m", "5"}},
      {{"model", "tabular"}, {"explore", "unknown"}});
  reg.add("savedpolicy",
          [](const AgentOptions& o, const rl_common::EnvironmentDescription& d) {
            return std::make_unique<SavedPolicy>(d.numActions, static_cast<int>(d.numFeatures()),
                                                 o.filename, o.seed);
          },
          "greedy on the Q-values of a policy file (--filename)", {kBinnedStatesFact});
  reg.add("optimal",
          [](const AgentOptions&,
             const rl_common::EnvironmentDescription&) -> std::unique_ptr<rl_common::Agent> {
            throw std::invalid_argument(
                "makeAgent(): agent 'optimal' plans on the environment's true model: build it with "
                "that model (the experiment runner passes its environment; rl_experiment's "
                "optimal_agent node builds its own copy from --env), for environments with a true "
                "model");
          },
          "value iteration on the environment's true model (the paper's optimal policy)",
          {kTrueModelPlannerFact});
  return reg;
}

std::unique_ptr<rl_common::Agent> wrap(std::unique_ptr<rl_common::Agent> agent,
                                       const AgentOptions& o,
                                       const rl_common::EnvironmentDescription& d) {
  // Model-free agents and savedpolicy see binned states (the original's DiscretizationAgent);
  // the model-based agent bins its own inputs (except for m5tree).
  if (!binsStates(o) || !agentRegistry().hasFact(o.agent, kBinnedStatesFact)) return agent;
  checkStatesPerDim(o, d.minFeatures.size());
  return std::make_unique<DiscretizationAgent>(std::move(agent), o.nstates, d.minFeatures,
                                               d.maxFeatures);
}

}  // namespace

const AgentRegistry& agentRegistry() {
  static const AgentRegistry registry = buildRegistry();
  return registry;
}

std::unique_ptr<rl_common::Agent> makeAgent(const AgentOptions& options,
                                            const rl_common::EnvironmentDescription& description) {
  return wrap(agentRegistry().create(options.agent, options, description), options, description);
}

std::unique_ptr<rl_common::Agent> makeAgent(const AgentOptions& options,
                                            const rl_common::EnvironmentDescription& description,
                                            const rl_common::TrueModel* trueModel) {
  if (!agentRegistry().hasFact(options.agent, kTrueModelPlannerFact)) {
    return makeAgent(options, description);
  }
  if (trueModel == nullptr) {
    throw std::invalid_argument(
        "makeAgent(): agent 'optimal' needs the environment's true model, and this "
        "environment offers none");
  }
  OptimalAgent::Config c;
  c.numActions = description.numActions;
  c.gamma = options.gamma;
  return std::make_unique<OptimalAgent>(c, *trueModel, options.seed);
}

}  // namespace rl_agent
