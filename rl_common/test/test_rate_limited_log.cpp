// RateLimitedLog: one line per message, at most N a second, the held-back ones counted.
#include <gtest/gtest.h>

#include "rl_common/rate_limited_log.h"

using rl_common::RateLimitedLog;

TEST(RateLimitedLog, OneLinePerMessageUntilABurstThenACount) {
  RateLimitedLog log(3);
  const auto t0 = RateLimitedLog::Clock::time_point{} + std::chrono::hours(1);
  const auto ms = [&](int n) { return t0 + std::chrono::milliseconds(n); };
  EXPECT_EQ(log.admit("a", ms(0)), std::optional<std::string>("a"));
  EXPECT_EQ(log.admit("b", ms(10)), std::optional<std::string>("b"));
  EXPECT_EQ(log.admit("c", ms(20)), std::optional<std::string>("c"));
  for (int i = 0; i < 500; ++i) EXPECT_FALSE(log.admit("burst", ms(30 + i)).has_value());
  EXPECT_EQ(log.heldBack(), 500);
  // A new second: the next line goes out and says how many were held back.
  EXPECT_EQ(log.admit("d", ms(1000)),
            std::optional<std::string>("d (500 similar lines held back)"));
  EXPECT_EQ(log.heldBack(), 0);
  EXPECT_EQ(log.admit("e", ms(1001)), std::optional<std::string>("e"));
  EXPECT_EQ(log.admit("f", ms(1002)), std::optional<std::string>("f"));
  EXPECT_FALSE(log.admit("g", ms(1003)).has_value());
  EXPECT_EQ(log.admit("h", ms(2500)), std::optional<std::string>("h (1 similar line held back)"));
}
