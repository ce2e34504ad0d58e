/**
 * StateHash: a hash of a float feature vector for unordered containers keyed by states.
 *
 * Each feature's bit pattern is mixed into a 64-bit accumulator (multiply-xorshift), and the
 * result goes through the SplitMix64 finaliser (Steele, Lea & Flood 2014), so that states that
 * differ in one low-order bit of one feature land in unrelated buckets. -0.0 and +0.0 hash
 * alike, since they compare equal; NaN never compares equal, so callers must keep NaN out of
 * keys (the planners do).
 */
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace rl_agent {

struct StateHash {
  std::size_t operator()(const std::vector<float>& v) const noexcept {
    std::uint64_t h = 0x9E3779B97F4A7C15ULL ^ static_cast<std::uint64_t>(v.size());
    for (float x : v) {
      if (x == 0.0f) {
        x = 0.0f;  // -0.0 == +0.0: same hash
      }
      std::uint32_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      h = (h ^ bits) * 0xBF58476D1CE4E5B9ULL;
      h ^= h >> 31;
    }
    h ^= h >> 30;
    h *= 0xBF58476D1CE4E5B9ULL;
    h ^= h >> 27;
    h *= 0x94D049BB133111EBULL;
    h ^= h >> 31;
    return static_cast<std::size_t>(h);
  }
};

}  // namespace rl_agent
