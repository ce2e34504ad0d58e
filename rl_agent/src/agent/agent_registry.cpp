#include "rl_agent/agent/agent_registry.h"

#include "rl_agent/agent/model_based_agent.h"
#include "rl_agent/agent/q_learner.h"

namespace rl_agent {

namespace {

AgentRegistry buildRegistry() {
  AgentRegistry reg("agent");
  reg.add(
      "qlearner",
      [](const AgentOptions& o, const rl_common::EnvironmentDescription& d) {
        QLearner::Config c;
        c.numActions = d.numActions;
        c.gamma = o.gamma;
        c.initialValue = o.initialvalue;
        c.alpha = o.alpha;
        c.epsilon = o.epsilon;
        return std::make_unique<QLearner>(c, o.seed);
      },
      "tabular Q-learning, epsilon-greedy (Watkins & Dayan 1992)");
  const auto modelBased = [](const AgentOptions& o, const rl_common::EnvironmentDescription& d) {
    return std::make_unique<ModelBasedAgent>(o, d);
  };
  reg.add("texplore", modelBased,
          "TEXPLORE: random-forest model, UCT(lambda) in real time; with --v/--n "
          "TEXPLORE-VANIR (Hester & Stone 2013, 2017)");
  reg.add("modelbased", modelBased, "model-based agent with the chosen --model and --planner");
  return reg;
}

}  // namespace

const AgentRegistry& agentRegistry() {
  static const AgentRegistry registry = buildRegistry();
  return registry;
}

std::unique_ptr<rl_common::Agent> makeAgent(const AgentOptions& options,
                                            const rl_common::EnvironmentDescription& description) {
  return agentRegistry().create(options.agent, options, description);
}

}  // namespace rl_agent
