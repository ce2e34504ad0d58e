#include "rl_env/env/environment_options.h"

#include <stdexcept>

#include "rl_env/env/environment_registry.h"

namespace rl_env {

std::string EnvironmentOptions::extraValue(const std::string& name,
                                           const std::string& fallback) const {
  const auto it = extra.find(name);
  return it == extra.end() ? fallback : it->second;
}

void addEnvironmentOptions(rl_common::OptionParser& parser, EnvironmentOptions* o,
                           const EnvironmentCatalog& catalog) {
  parser.value("env", &o->env, "environment (see the list of valid names with an unknown one)");
  parser.value("seed", &o->seed, "seed of the environment's own random source");
  addEnvironmentVariantOptions(parser, o, catalog);
}

void addEnvironmentVariantOptions(rl_common::OptionParser& parser, EnvironmentOptions* o,
                                  const EnvironmentCatalog& catalog) {
  parser.flag("stochastic", &o->stochastic, true, "noisy dynamics (the default)");
  parser.flag("deterministic", &o->stochastic, false, "noise-free dynamics");
  // Upper bounds keep a typo from exhausting memory (a delay of 1e9 queued 3.3 GB in 15 s).
  parser.value("delay", &o->delay, "delay in steps (mcar, tworooms)", rl_common::inRange(0, 1000));
  parser.value("nsectors", &o->nsectors, "number of sectors (stocks)", rl_common::inRange(1, 1000));
  parser.value("nstocks", &o->nstocks, "stocks per sector (stocks)", rl_common::inRange(1, 1000));
  parser.flag("lag", &o->lag, true, "second-order brake dynamics (car2to7, car7to2, carrandom)");
  parser.flag("nolag", &o->lag, false, "no brake lag (car*, the default)");
  parser.flag("highvar", &o->highvar, true, "high-variance fuel costs (fuelworld)");
  for (const ExtraOption& extra : catalog.extraOptions()) {
    // std::map keeps the element's address while other names are added.
    std::string& value = o->extra[extra.name];
    value = extra.defaultValue;
    parser.choice(
        extra.name, &value, extra.choices,
        extra.help + " (" + rl_common::joinNames(catalog.registry().namesTaking(extra.name)) + ")");
  }
}

void checkEnvironmentOptions(const rl_common::OptionParser& parser, const EnvironmentOptions& o,
                             const EnvironmentCatalog& catalog) {
  const EnvironmentRegistry& registry = catalog.registry();
  std::string env;
  try {
    env = registry.canonical(o.env);
  } catch (const std::invalid_argument& e) {
    throw rl_common::OptionError(std::string("option --env: ") + e.what());
  }
  for (const std::string& option : registry.specificOptions()) {
    if (parser.given(option) && !registry.takesOption(env, option)) {
      throw rl_common::OptionError("option --" + option + " applies only to --env " +
                                   rl_common::joinNames(registry.namesTaking(option)) +
                                   ", not to '" + o.env + "'");
    }
  }
}

}  // namespace rl_env
