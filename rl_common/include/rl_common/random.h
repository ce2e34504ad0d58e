/**
 * A seeded random source, owned by each stochastic object (never shared, never global).
 *
 * The engine is std::mt19937_64, whose output the C++ standard fixes; the distributions are
 * written here rather than taken from <random>, whose algorithms differ between standard
 * libraries. The same seed therefore gives the same numbers on every platform. Not thread-safe:
 * each thread and each object holds its own Random.
 *
 * Independent streams for components (agent, environment, each tree ...) are derived with
 * deriveSeed(), a SplitMix64 hash of the base seed, a stream name and an index, so streams
 * are not offset copies of one sequence as in the original.
 */
#pragma once

#include <cstdint>
#include <random>
#include <string_view>

namespace rl_common {

class Random {
 public:
  /// Seeds the generator; every seed, including 0, is valid.
  explicit Random(std::uint64_t seed);

  /// The seed this object was constructed with.
  std::uint64_t seed() const { return seed_; }

  /// Uniform 64-bit integer.
  std::uint64_t nextU64() { return engine_(); }
  /// Uniform double in [0, 1).
  double uniform();
  /// Uniform double in [a, b).
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  /// Uniform integer in [lo, hi], both inclusive; lo == hi is allowed. Throws if lo > hi.
  int uniformInt(int lo, int hi);
  /// True with probability p.
  bool bernoulli(double p) { return uniform() < p; }
  /// Normal deviate (Marsaglia polar method; keeps its spare value per object).
  double normal(double mean = 0.0, double stddev = 1.0);

  /// A seed for an independent stream named `stream`, index `index`, derived from `base`.
  static std::uint64_t deriveSeed(std::uint64_t base, std::string_view stream,
                                  std::uint64_t index = 0);
  /// A new Random on the stream deriveSeed(seed(), stream, index).
  Random derive(std::string_view stream, std::uint64_t index = 0) const {
    return Random(deriveSeed(seed_, stream, index));
  }

 private:
  std::uint64_t seed_;
  std::mt19937_64 engine_;
  bool hasSpare_ = false;
  double spare_ = 0.0;
};

}  // namespace rl_common
