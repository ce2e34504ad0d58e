/**
 * The suite's TrueModelSource: --env (one of the suite's environments with a true model) and
 * the env node's variant options (--deterministic, ...), built as the optimal agent's private
 * copy of the env node's environment. rl_experiment's optimal_agent node gives it to the agent
 * node's program.
 */
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rl_agent/agent/true_model_source.h"
#include "rl_env/env/environment_registry.h"

namespace rl_experiment {

class SuiteTrueModelSource : public rl_agent::TrueModelSource {
 public:
  /// Offers the environments of `catalog`, which must outlive the source.
  explicit SuiteTrueModelSource(const rl_env::EnvironmentCatalog& catalog);

  void addOptions(rl_common::OptionParser& parser) override;
  std::vector<std::string> optionNames() const override;
  std::unique_ptr<rl_common::Environment> make(const rl_common::OptionParser& parser,
                                               std::uint64_t seed) override;

 private:
  const rl_env::EnvironmentCatalog& catalog_;
  rl_env::EnvironmentOptions options_;
};

}  // namespace rl_experiment
