/**
 * ProgressBar: one line on stderr, "what [#####.....]  50%", redrawn when the percentage moves;
 * off when stderr is not wanted (--progress off, a pipe).
 */
#pragma once

#include <string>

namespace rl_experiment {

class ProgressBar {
 public:
  explicit ProgressBar(bool on) : on_(on) {}
  /// Shows `done` of `total` (nothing if off or total <= 0).
  void show(const std::string& what, long done, long total);
  /// Erases the bar (before a line of output).
  void clear();

 private:
  bool on_;
  int last_ = -1;
};

}  // namespace rl_experiment
