#include "nao_interface/env/nao_arm_registration.h"

#include <memory>

#include "nao_interface/env/nao_arm_environment.h"
#include "nao_interface/env/nao_arm_task.h"

namespace nao_interface {

void addNaoArmEnvironment(rl_env::EnvironmentCatalog& catalog) {
  catalog.registry().add(
      "naoarm",
      [](const rl_env::EnvironmentOptions& o,
         std::uint64_t seed) -> std::unique_ptr<rl_common::Environment> {
        NaoArmSimConfig config;
        config.stochastic = o.stochastic;
        return std::make_unique<NaoArmEnvironment>(
            config, parseNaoArmTask(o.extraValue("task", kDefaultNaoArmTask)), seed);
      },
      "the paper's simulated seated Nao moving its right shoulder (8 features, 5 actions); "
      "--task explore|pink|button|mic",
      {}, {"task"});
  catalog.addOption({"task", naoArmTaskNames(), kDefaultNaoArmTask,
                     "reward of the Nao arm task: none, pink pixels, foot button, microphone"});
}

}  // namespace nao_interface
