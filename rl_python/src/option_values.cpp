#include "rl_python/option_values.h"

namespace rl_python {

void applyOptionValues(rl_common::OptionParser& parser, const OptionValues& values) {
  for (const auto& [name, value] : values) parser.set(name, value);
}

}  // namespace rl_python
