#include "rl_experiment/runner/system_info.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#ifndef RL_EXPERIMENT_SOURCE_DIR
#define RL_EXPERIMENT_SOURCE_DIR ""
#endif
#ifndef RL_EXPERIMENT_VERSION
#define RL_EXPERIMENT_VERSION "unknown"
#endif

namespace rl_experiment {

std::string suiteVersion() {
  std::string dir = RL_EXPERIMENT_SOURCE_DIR;
  if (!dir.empty()) {
    const std::string cmd = "git -C '" + dir + "' describe --always --dirty --tags 2>/dev/null";
    if (std::FILE* pipe = ::popen(cmd.c_str(), "r")) {
      char buf[256] = {0};
      std::string out;
      while (std::fgets(buf, sizeof(buf), pipe) != nullptr) out += buf;
      const int status = ::pclose(pipe);
      while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
      if (status == 0 && !out.empty()) return "git " + out;
    }
  }
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
