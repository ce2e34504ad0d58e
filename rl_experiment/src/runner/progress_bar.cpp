#include "rl_experiment/runner/progress_bar.h"

#include <cstdio>
#include <string>

namespace rl_experiment {

void ProgressBar::show(const std::string& what, long done, long total) {
  if (!on_ || total <= 0) return;
  const int pct = static_cast<int>(100 * done / total);
  if (pct == last_ && done != total) return;
  last_ = pct;
  const int width = 30;
  const int fill = static_cast<int>(width * done / total);
  std::fprintf(stderr, "\r%s [%s%s] %3d%%", what.c_str(), std::string(fill, '#').c_str(),
               std::string(width - fill, '.').c_str(), pct);
  std::fflush(stderr);
}

void ProgressBar::clear() {
  if (on_ && last_ >= 0) std::fprintf(stderr, "\r%60s\r", "");
  last_ = -1;
}

}  // namespace rl_experiment
