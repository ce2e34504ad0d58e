/**
 * Parallel trials: one child process per trial (fork), at most `jobs` at a time. A trial's
 * child sends its report line back through a pipe and exits; a child dies with the runner
 * (Linux: PR_SET_PDEATHSIG), so that `kill RUNNER` leaves no trial writing on.
 */
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rl_experiment {

/// Runs `run(trial)` for every trial of `trials` in child processes, at most `jobs` at once.
/// In the parent, calls `finished(trial, line)` as each child ends, with the line run()
/// returned, or nullopt if the trial failed (run() threw: the child printed why on stderr, or
/// it died). Returns the number of failed trials. Throws std::runtime_error if it cannot
/// make a pipe or a process.
int runTrialsInChildProcesses(
    const std::vector<int>& trials, int jobs, const std::function<std::string(int)>& run,
    const std::function<void(int, const std::optional<std::string>&)>& finished);

}  // namespace rl_experiment
