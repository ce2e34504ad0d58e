#include "rl_experiment/suite/suite_true_model_source.h"

#include <stdexcept>

#include "rl_common/true_model.h"

namespace rl_experiment {

SuiteTrueModelSource::SuiteTrueModelSource(const rl_env::EnvironmentCatalog& catalog)
    : catalog_(catalog) {
  options_.env.clear();  // none unless given
}

void SuiteTrueModelSource::addOptions(rl_common::OptionParser& parser) {
  parser.value("env", &options_.env,
               "--agent optimal only: the env node's environment, built privately as the true "
               "model to plan on (" +
                   catalog_.trueModelNames() + "); give the env node's options too");
  rl_env::addEnvironmentVariantOptions(parser, &options_, catalog_);
}

std::vector<std::string> SuiteTrueModelSource::optionNames() const {
  rl_common::OptionParser scratch("names", "");
  rl_env::EnvironmentOptions unused;
  scratch.value("env", &unused.env, "");
  rl_env::addEnvironmentVariantOptions(scratch, &unused, catalog_);
  std::vector<std::string> out;
  for (const auto& spec : scratch.specs()) out.push_back(spec.name);
  return out;
}

std::unique_ptr<rl_common::Environment> SuiteTrueModelSource::make(
    const rl_common::OptionParser& parser, std::uint64_t seed) {
  if (!parser.given("env")) {
    throw rl_common::OptionError(
        "--agent optimal needs --env <name>: the env node's environment (one of " +
        catalog_.trueModelNames() + "), with the env node's options (e.g. --deterministic)");
  }
  rl_env::checkEnvironmentOptions(parser, options_, catalog_);
  rl_env::EnvironmentOptions o = options_;
  o.env = catalog_.registry().canonical(o.env);
  o.seed = seed;  // never stepped: only its dynamics are used
  auto env = catalog_.make(o);
  if (dynamic_cast<const rl_common::TrueModel*>(env.get()) == nullptr) {
    throw rl_common::OptionError(
        "option --env: '" + o.env +
        "' offers no true model for --agent optimal (valid: " + catalog_.trueModelNames() + ")");
  }
  return env;
}

}  // namespace rl_experiment
