// Shared by the rostests that start, kill and restart nodes themselves: a node as a child
// process, its output in a log file.
#pragma once

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace test_nodes {

/// Starts `argv[0]` (a path, or a program on PATH such as rosrun) with its arguments; its
/// stdout and stderr go to `log`, a line at a time (so a test can wait for a log line). Returns
/// the child's pid (-1 if fork failed).
inline pid_t start(const std::vector<std::string>& args, const std::string& log) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::vector<std::string> all = args;
    std::vector<char*> argv;
    for (auto& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    if (std::freopen(log.c_str(), "w", stdout) == nullptr) ::_exit(126);
    ::dup2(::fileno(stdout), 2);
    ::setenv("ROSCONSOLE_STDOUT_LINE_BUFFERED", "1", 1);  // rosconsole buffers a file otherwise
    ::execvp(argv[0], argv.data());
    ::_exit(127);
  }
  return pid;
}

/// Sends `sig` and reaps the child; returns its wait status.
inline int stop(pid_t pid, int sig) {
  int status = 0;
  ::kill(pid, sig);
  ::waitpid(pid, &status, 0);
  return status;
}

/// The text of a file ("" if it cannot be read).
inline std::string fileText(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "r");
  std::string text;
  if (f == nullptr) return text;
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof(buf), f)) > 0) text.append(buf, n);
  std::fclose(f);
  return text;
}

}  // namespace test_nodes
