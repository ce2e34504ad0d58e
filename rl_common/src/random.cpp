#include "rl_common/random.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rl_common {

namespace {

// SplitMix64 finaliser (Steele, Lea, Flood 2014): a bijective 64-bit mixer.
std::uint64_t splitMix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

}  // namespace

Random::Random(std::uint64_t seed) : seed_(seed), engine_(splitMix64(seed)) {}

double Random::uniform() {
  // 53 random bits scaled into [0, 1).
  return static_cast<double>(engine_() >> 11) * 0x1.0p-53;
}

int Random::uniformInt(int lo, int hi) {
  if (lo > hi) {
    throw std::invalid_argument("Random::uniformInt(): empty range [" + std::to_string(lo) + ", " +
                                std::to_string(hi) + "]");
  }
  const std::uint64_t span =
      static_cast<std::uint64_t>(static_cast<std::int64_t>(hi) - static_cast<std::int64_t>(lo)) + 1;
  // Rejection sampling: draws above the largest multiple of span would bias low values.
  const std::uint64_t limit = UINT64_MAX - (UINT64_MAX % span);
  std::uint64_t x;
  do {
    x = engine_();
  } while (x >= limit);
  return static_cast<int>(static_cast<std::int64_t>(lo) + static_cast<std::int64_t>(x % span));
}

double Random::normal(double mean, double stddev) {
  if (hasSpare_) {
    hasSpare_ = false;
    return mean + stddev * spare_;
  }
  double u, v, s;
  do {
    u = uniform(-1.0, 1.0);
    v = uniform(-1.0, 1.0);
    s = u * u + v * v;
  } while (s >= 1.0 || s == 0.0);
  const double m = std::sqrt(-2.0 * std::log(s) / s);
  spare_ = v * m;
  hasSpare_ = true;
  return mean + stddev * u * m;
}

std::uint64_t Random::deriveSeed(std::uint64_t base, std::string_view stream, std::uint64_t index) {
  // FNV-1a of the stream name, then mixed with the base seed and the index.
  std::uint64_t h = 0xCBF29CE484222325ULL;
  for (unsigned char c : stream) {
    h = (h ^ c) * 0x100000001B3ULL;
  }
  return splitMix64(splitMix64(base ^ splitMix64(h)) + index);
}

}  // namespace rl_common
