/**
 * RateLimitedLog: decides which "dropped a malformed message" lines a node writes, so that one
 * bad message gives one clear line but a burst of them cannot flood the log: at most
 * `perSecond` lines in any one-second window; the lines held back are counted and named in
 * the next line that goes out ("(12 similar lines held back)"). ROS-free: the node logs what
 * admit() returns with its own rosconsole macro (whose logger name must be a literal).
 */
#pragma once

#include <chrono>
#include <optional>
#include <string>

namespace rl_common {

class RateLimitedLog {
 public:
  using Clock = std::chrono::steady_clock;

  explicit RateLimitedLog(int perSecond = 10) : perSecond_(perSecond < 1 ? 1 : perSecond) {}

  /// The line to log now (with the count of lines held back since the last one), or nothing.
  std::optional<std::string> admit(const std::string& line, Clock::time_point now = Clock::now()) {
    if (now - windowStart_ >= std::chrono::seconds(1)) {
      windowStart_ = now;
      inWindow_ = 0;
    }
    if (inWindow_ >= perSecond_) {
      ++heldBack_;
      return std::nullopt;
    }
    ++inWindow_;
    if (heldBack_ == 0) return line;
    std::string out = line + " (" + std::to_string(heldBack_) + " similar line" +
                      (heldBack_ == 1 ? "" : "s") + " held back)";
    heldBack_ = 0;
    return out;
  }

  /// Lines held back since the last one admitted.
  long heldBack() const { return heldBack_; }

 private:
  int perSecond_;
  Clock::time_point windowStart_{};
  int inWindow_ = 0;
  long heldBack_ = 0;
};

}  // namespace rl_common
