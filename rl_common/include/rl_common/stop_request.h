#pragma once
/**
 * A process-wide request to stop planning now, set from a SIGINT handler: planners end the
 * current step at their next rollout or sweep, so a node planning 20,000 rollouts a step stops
 * within one rollout instead of one step.
 *
 * A lock-free atomic at namespace scope (constant-initialised), so setting it is
 * async-signal-safe.
 */
#include <atomic>

namespace rl_common {

inline std::atomic<bool> stopRequestedFlag{false};

inline void requestStop() noexcept { stopRequestedFlag.store(true, std::memory_order_relaxed); }
inline bool stopRequested() noexcept { return stopRequestedFlag.load(std::memory_order_relaxed); }
/// For tests, and for a program that goes on after handling a stop.
inline void clearStopRequest() noexcept { stopRequestedFlag.store(false); }

}  // namespace rl_common
