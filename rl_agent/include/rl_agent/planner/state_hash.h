/**
 * StateHash: a hash of a float feature vector for the state tables of the planners and models.
 *
 * The features' bit patterns are taken two at a time as one 64-bit word and mixed into an
 * accumulator (multiply-xorshift), and the result goes through the SplitMix64 finaliser
 * (Steele, Lea & Flood 2014), so that states that differ in one low-order bit of one feature
 * land in unrelated buckets. Two features per multiply halve the serial chain of a 17-feature
 * state, the planner's most frequent operation. -0.0 and +0.0 hash alike (x + 0.0f turns -0.0
 * into +0.0 without a branch), since they compare equal; NaN never compares equal, so callers
 * must keep NaN out of keys (the planners do). The tables only look states up, so the hash
 * decides no order that a result depends on.
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
    const std::size_t n = v.size();
    std::size_t i = 0;
    for (; i + 1 < n; i += 2) {
      h = (h ^ (bitsOf(v[i]) | (bitsOf(v[i + 1]) << 32))) * 0xBF58476D1CE4E5B9ULL;
      h ^= h >> 31;
    }
    if (i < n) {
      h = (h ^ bitsOf(v[i])) * 0xBF58476D1CE4E5B9ULL;
      h ^= h >> 31;
    }
    h ^= h >> 30;
    h *= 0xBF58476D1CE4E5B9ULL;
    h ^= h >> 27;
    h *= 0x94D049BB133111EBULL;
    h ^= h >> 31;
    return static_cast<std::size_t>(h);
  }

 private:
  static std::uint64_t bitsOf(float x) noexcept {
    x += 0.0f;  // -0.0 + 0.0 = +0.0: equal states, equal hashes
    std::uint32_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    return bits;
  }
};

}  // namespace rl_agent
