/**
 * TrueModelSource: how a program that knows environments lets an agent node offer the agents
 * that plan on the environment's true model (`optimal`, kTrueModelPlannerFact). rl_agent knows
 * no environment, so its own agent node has none; rl_experiment's optimal_agent node gives one
 * built on the suite's environments (the env node's --env and variant options).
 */
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rl_common/environment.h"
#include "rl_common/option_parser.h"

namespace rl_agent {

class TrueModelSource {
 public:
  virtual ~TrueModelSource() = default;

  /// Declares the options that choose the environment (e.g. --env, --deterministic) on the
  /// node's parser; their storage lives in the source.
  virtual void addOptions(rl_common::OptionParser& parser) = 0;

  /// The names of the options addOptions declares (refused for agents that learn from the env
  /// node's messages alone).
  virtual std::vector<std::string> optionNames() const = 0;

  /// The chosen environment, which must be an rl_common::TrueModel, after parsing. Throws
  /// rl_common::OptionError if --env is missing or invalid, an option does not apply to it, or
  /// it has no true model.
  virtual std::unique_ptr<rl_common::Environment> make(const rl_common::OptionParser& parser,
                                                       std::uint64_t seed) = 0;
};

}  // namespace rl_agent
