#include "rl_experiment/eval/scripted_stream.h"

#include <stdexcept>

#include "rl_agent/agent/agent_options.h"
#include "rl_agent/agent/model_based_agent.h"
#include "rl_common/option_parser.h"
#include "rl_common/random.h"
#include "rl_env/env/light_world.h"
#include "rl_experiment/eval/model_accuracy.h"

namespace rl_experiment {

const std::vector<std::string>& scriptedStreamNames() {
  static const std::vector<std::string> names{"walk", "iid", "teleport", "keep-key"};
  return names;
}

std::vector<rl_common::Experience> scriptedLightWorldStream(const ScriptedStreamConfig& config,
                                                            std::uint64_t seed) {
  const std::string& kind = config.stream;
  bool known = false;
  for (const auto& n : scriptedStreamNames()) known = known || n == kind;
  if (!known) {
    throw std::invalid_argument("unknown stream '" + kind +
                                "' (valid: walk, iid, teleport, keep-key)");
  }
  if (config.steps < 1) throw std::invalid_argument("steps must be at least 1");
  if (config.period < 1) throw std::invalid_argument("period must be at least 1");

  using rl_env::LightWorld;
  LightWorld env(seed, /*stochastic=*/true);
  // The action source is separate from the environment's own, so every stream of one seed
  // meets the same dynamics noise sequence until their actions differ.
  rl_common::Random rng(seed ^ 0x9e3779b97f4a7c15ULL);
  const std::vector<rl_common::State> reachable = env.reachableStates();
  auto drawState = [&]() {
    return reachable[static_cast<std::size_t>(
        rng.uniformInt(0, static_cast<int>(reachable.size()) - 1))];
  };

  std::vector<rl_common::Experience> out;
  out.reserve(static_cast<std::size_t>(config.steps));
  for (long i = 0; i < config.steps; ++i) {
    if (kind == "iid" || (kind == "teleport" && i % config.period == 0)) {
      env.setState(drawState());
    }
    int a = rng.uniformInt(0, LightWorld::kNumActions - 1);
    if (kind == "keep-key" && i < config.period && a == LightWorld::kPickup) {
      const LightWorld::Objects o = env.objects();
      const LightWorld::FullState& f = env.fullState();
      if (o.keyPresent && o.key == LightWorld::Cell{f.ns, f.ew}) {
        a = rng.uniformInt(LightWorld::kNorth, LightWorld::kSouth);
      }
    }
    rl_common::Experience e;
    e.s = env.sensation();
    e.action = a;
    e.reward = env.apply(a);
    e.next = env.sensation();
    e.terminal = false;
    out.push_back(std::move(e));
  }
  return out;
}

ScriptedStreamResult measureScriptedStream(const ScriptedStreamConfig& config,
                                           std::uint64_t streamSeed, std::uint64_t modelSeed,
                                           std::uint64_t evalSeed, int samples) {
  using rl_env::LightWorld;
  const LightWorld truth(streamSeed, /*stochastic=*/true);
  rl_agent::AgentOptions ao;
  rl_common::OptionParser p("scripted stream", "");
  rl_agent::addAgentOptions(p, &ao);
  // --rollouts: the synchronous agent, whose model learns each seed at once (it never acts).
  p.parse({"--agent", "texplore", "--explore", "random", "--rollouts", "1"});
  rl_agent::applyAgentDefaults(p, &ao);
  ao.seed = modelSeed;
  rl_agent::ModelBasedAgent agent(ao, truth.describe());
  ScriptedStreamResult r;
  for (const auto& e : scriptedLightWorldStream(config, streamSeed)) {
    // The key sensors read something only while the key lies on the floor.
    float keyLight = 0.0f;
    for (int j = LightWorld::kKeyN; j <= LightWorld::kKeyS; ++j) {
      keyLight += e.s[static_cast<std::size_t>(j)];
    }
    r.keyOnFloor += keyLight > 0.0f ? 1 : 0;
    agent.seedExperiences({e});
  }
  ModelAccuracy measure(truth, LightWorld::kNumActions);
  rl_common::Random rng(evalSeed);
  r.distance = measure.evaluate(*agent.learnedModelView(), rng, samples);
  return r;
}

}  // namespace rl_experiment
