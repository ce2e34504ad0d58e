#include "rl_experiment/runner/trial_processes.h"

#ifdef __linux__
#include <sys/prctl.h>
#endif
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <utility>

namespace rl_experiment {

int runTrialsInChildProcesses(
    const std::vector<int>& trials, int jobs, const std::function<std::string(int)>& run,
    const std::function<void(int, const std::optional<std::string>&)>& finished) {
  std::map<pid_t, std::pair<int, int>> running;  // pid -> (trial, read end)
  std::size_t next = 0;
  int failed = 0;
  std::fflush(nullptr);  // a child must not write the parent's buffered output again
  [[maybe_unused]] const pid_t parent = ::getpid();
  while (next < trials.size() || !running.empty()) {
    while (next < trials.size() && int(running.size()) < jobs) {
      int fds[2];
      if (::pipe(fds) != 0) throw std::runtime_error("Experiment::run(): pipe failed");
      const int trial = trials[next++];
      const pid_t pid = ::fork();
      if (pid < 0) throw std::runtime_error("Experiment::run(): fork failed");
      if (pid == 0) {
#ifdef __linux__
        // A trial must not outlive the runner: `kill PID` of the parent alone (not the
        // terminal's Ctrl-C, which reaches the whole group) would leave it writing on.
        ::prctl(PR_SET_PDEATHSIG, SIGTERM);
        if (::getppid() != parent) ::_exit(1);  // the runner died before the line above
#endif
        ::close(fds[0]);
        int status = 0;
        try {
          const std::string text = run(trial) + "\n";
          if (::write(fds[1], text.data(), text.size()) < 0) status = 1;
        } catch (const std::exception& e) {
          std::fprintf(stderr, "experiment: trial %d failed: %s\n", trial, e.what());
          status = 1;
        }
        ::close(fds[1]);
        std::fflush(nullptr);
        ::_exit(status);
      }
      ::close(fds[1]);
      running[pid] = {trial, fds[0]};
    }
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, 0);
    if (pid < 0) break;
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    std::string text;
    char buf[4096];
    ssize_t n;
    while ((n = ::read(it->second.second, buf, sizeof(buf))) > 0) text.append(buf, std::size_t(n));
    ::close(it->second.second);
    const int trial = it->second.first;
    running.erase(it);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && !text.empty()) {
      finished(trial, text);
    } else {
      ++failed;
      finished(trial, std::nullopt);
    }
  }
  return failed;
}

}  // namespace rl_experiment
