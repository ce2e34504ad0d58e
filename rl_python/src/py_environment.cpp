#include "rl_python/py_environment.h"

#include <stdexcept>

namespace rl_python {

PyEnvironment::PyEnvironment(const rl_env::EnvironmentCatalog& catalog, const std::string& name,
                             const OptionValues& options)
    : catalog_(&catalog) {
  rl_common::OptionParser parser("make_env", "make_env(name, **options)");
  rl_env::addEnvironmentOptions(parser, &options_, catalog);
  parser.set("env", name);
  applyOptionValues(parser, options);
  rl_env::checkEnvironmentOptions(parser, options_, catalog);  // validates the name too
  options_.env = catalog.registry().canonical(options_.env);
  effective_ = parser.currentValues();
  env_ = catalog.make(options_);
}

const rl_common::State& PyEnvironment::reset(std::optional<std::uint64_t> seed) {
  if (seed.has_value()) {
    options_.seed = *seed;
    for (auto& [name, value] : effective_) {
      if (name == "seed") value = rl_common::formatOptionValue(*seed);
    }
    env_ = catalog_->make(options_);
  } else if (!fresh_) {
    env_->reset();
  }
  fresh_ = true;
  episodeSteps_ = 0;
  return env_->sensation();
}

PyEnvironment::Step PyEnvironment::step(int action) {
  if (env_->terminal()) {
    throw std::logic_error("PyEnvironment::step(): the episode has terminated; call reset()");
  }
  Step s;
  s.reward = env_->apply(action);
  fresh_ = false;
  ++episodeSteps_;
  s.observation = env_->sensation();
  s.terminated = env_->terminal();
  return s;
}

double PyEnvironment::run(const std::vector<int>& actions) {
  double total = 0.0;
  for (const int a : actions) {
    if (env_->terminal()) reset(std::nullopt);
    total += step(a).reward;
  }
  return total;
}

rl_common::TrueModel* PyEnvironment::trueModel() {
  return dynamic_cast<rl_common::TrueModel*>(env_.get());
}

void PyEnvironment::setState(const rl_common::State& s) {
  rl_common::TrueModel* model = trueModel();
  if (model == nullptr) {
    throw std::logic_error(
        "PyEnvironment::setState(): " + options_.env +
        " has no true model; environments with one: " + catalog_->trueModelNames());
  }
  model->setState(s);
  fresh_ = false;
  episodeSteps_ = 0;
}

}  // namespace rl_python
