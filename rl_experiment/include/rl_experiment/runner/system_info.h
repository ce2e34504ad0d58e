/**
 * What a run records about the machine and the code: the suite's version and the process's
 * peak memory (Linux /proc; best effort elsewhere).
 */
#pragma once

#include <string>

namespace rl_experiment {

/// The suite's version: `git describe --always --dirty --tags` of the source tree when this
/// binary was built (so a run records what it ran, even after the tree moved on), else the
/// package version.
std::string suiteVersion();

/// Peak resident memory of this process in kB (VmHWM), and a reset of it (best effort).
long peakRssKb();
void resetPeakRss();

}  // namespace rl_experiment
