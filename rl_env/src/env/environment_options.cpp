#include "rl_env/env/environment_options.h"

#include <algorithm>
#include <vector>

#include "nao_interface/env/nao_arm_task.h"
#include "rl_common/registry.h"

namespace rl_env {

void addEnvironmentOptions(rl_common::OptionParser& parser, EnvironmentOptions* o) {
  parser.value("env", &o->env, "environment (see the list of valid names with an unknown one)");
  parser.value("seed", &o->seed, "seed of the environment's random source");
  addEnvironmentVariantOptions(parser, o);
}

void addEnvironmentVariantOptions(rl_common::OptionParser& parser, EnvironmentOptions* o) {
  parser.flag("stochastic", &o->stochastic, true, "noisy dynamics (the default)");
  parser.flag("deterministic", &o->stochastic, false, "noise-free dynamics");
  // Upper bounds keep a typo from exhausting memory (a delay of 1e9 queued 3.3 GB in 15 s).
  parser.value("delay", &o->delay, "delay in steps (mcar, tworooms)", rl_common::inRange(0, 1000));
  parser.value("nsectors", &o->nsectors, "number of sectors (stocks)", rl_common::inRange(1, 1000));
  parser.value("nstocks", &o->nstocks, "stocks per sector (stocks)", rl_common::inRange(1, 1000));
  parser.flag("lag", &o->lag, true, "second-order brake dynamics (car2to7, car7to2, carrandom)");
  parser.flag("nolag", &o->lag, false, "no brake lag (car*, the default)");
  parser.flag("highvar", &o->highvar, true, "high-variance fuel costs (fuelworld)");
  parser.choice("task", &o->task, nao_interface::naoArmTaskNames(),
                "reward of the Nao arm task (naoarm): none, pink pixels, foot button, microphone");
}

void checkEnvironmentOptions(const rl_common::OptionParser& parser, const EnvironmentOptions& o) {
  struct Rule {
    const char* option;
    std::vector<std::string> envs;
  };
  const std::vector<Rule> rules = {
      {"delay", {"mcar", "tworooms"}},
      {"nsectors", {"stocks"}},
      {"nstocks", {"stocks"}},
      {"lag", {"car2to7", "car7to2", "carrandom"}},
      {"nolag", {"car2to7", "car7to2", "carrandom"}},
      {"highvar", {"fuelworld"}},
      {"task", {"naoarm"}},
  };
  for (const Rule& r : rules) {
    if (parser.given(r.option) && std::find(r.envs.begin(), r.envs.end(), o.env) == r.envs.end()) {
      throw rl_common::OptionError(std::string("option --") + r.option + " applies only to --env " +
                                   rl_common::joinNames(r.envs) + ", not to '" + o.env + "'");
    }
  }
}

}  // namespace rl_env
