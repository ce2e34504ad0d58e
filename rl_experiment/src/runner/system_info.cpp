#include "rl_experiment/runner/system_info.h"

#include <cstdlib>
#include <fstream>
#include <string>

#include "rl_experiment/build_version.h"  // generated at build time (write_build_version.cmake)

#ifndef RL_EXPERIMENT_VERSION
#define RL_EXPERIMENT_VERSION "unknown"
#endif

namespace rl_experiment {

std::string suiteVersion() {
  const std::string built = RL_EXPERIMENT_BUILD_VERSION;
  if (!built.empty()) return "git " + built;
  return std::string("package ") + RL_EXPERIMENT_VERSION;
}

long peakRssKb() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::atol(line.c_str() + 6);
  }
  return 0;
}

void resetPeakRss() {
  std::ofstream out("/proc/self/clear_refs");
  if (out) out << "5";
}

}  // namespace rl_experiment
