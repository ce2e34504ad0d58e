/**
 * Where the nodes put files nobody named: ROS_HOME (as roslaunch's logs), else ~/.ros; and the
 * local-time stamp that names a new run folder or journal.
 */
#pragma once

#include <cstdlib>
#include <ctime>
#include <string>

namespace rl_common {

/// ROS_HOME if set and not empty, else $HOME/.ros; "" if neither is known.
inline std::string rosHome() {
  const char* rosHome = std::getenv("ROS_HOME");
  if (rosHome != nullptr && *rosHome != '\0') return rosHome;
  const char* home = std::getenv("HOME");
  return home != nullptr ? std::string(home) + "/.ros" : std::string();
}

/// The local time as YYYYmmdd-HHMMSS.
inline std::string localTimestamp() {
  char stamp[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(stamp, sizeof(stamp), "%Y%m%d-%H%M%S", std::localtime(&now));
  return stamp;
}

}  // namespace rl_common
