/**
 * OptionValues: options given by name, as the Python keyword arguments of make_env() and
 * make_agent() (`rollouts=100` is ("rollouts", "100")), applied to the suite's own
 * rl_common::OptionParser through OptionParser::set(), the path the ROS adapter takes for
 * `~private` parameters. Names, aliases, value checks and error messages are therefore those of
 * the command line: an unknown name or a bad value throws rl_common::OptionError naming the
 * option and what is valid. A flag takes "true" (give it) or "false" (its opposite), so
 * `stochastic=False` is `--deterministic`.
 */
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "rl_common/option_parser.h"

namespace rl_python {

/// (option name without dashes, value as command-line text), in the order given.
using OptionValues = std::vector<std::pair<std::string, std::string>>;

/// Applies every value to `parser` in order. Throws rl_common::OptionError on an unknown name
/// or an invalid value (the parser's message).
void applyOptionValues(rl_common::OptionParser& parser, const OptionValues& values);

}  // namespace rl_python
