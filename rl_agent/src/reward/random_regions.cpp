#include "rl_agent/reward/random_regions.h"

#include <stdexcept>

#include "rl_common/random.h"

namespace rl_agent {

RandomRegions::RandomRegions(const std::vector<float>& featMin, const std::vector<float>& featMax,
                             int count, std::uint64_t seed)
    : numFeatures_(featMin.size()) {
  if (featMin.empty() || featMin.size() != featMax.size() || count < 1) {
    throw std::invalid_argument(
        "RandomRegions::RandomRegions(): need feature ranges and at least one region");
  }
  rl_common::Random rng(seed);
  struct Box {
    std::vector<float> lo, hi;
  };
  std::vector<Box> boxes{{featMin, featMax}};  // per cut index (leaves only used)
  cuts_.push_back(Cut{});
  std::vector<int> leaves{0};
  for (int k = 1; k < count; ++k) {
    const std::size_t pick =
        static_cast<std::size_t>(rng.uniformInt(0, static_cast<int>(leaves.size()) - 1));
    const int leaf = leaves[pick];
    const Box box = boxes[static_cast<std::size_t>(leaf)];
    std::vector<int> wide;
    for (std::size_t j = 0; j < numFeatures_; ++j) {
      if (box.hi[j] > box.lo[j]) wide.push_back(static_cast<int>(j));
    }
    if (wide.empty()) break;  // nothing left to cut
    const int f =
        wide[static_cast<std::size_t>(rng.uniformInt(0, static_cast<int>(wide.size()) - 1))];
    const auto fs = static_cast<std::size_t>(f);
    const float t = static_cast<float>(rng.uniform(box.lo[fs], box.hi[fs]));
    Box lower = box, upper = box;
    lower.hi[fs] = t;
    upper.lo[fs] = t;
    const int li = static_cast<int>(cuts_.size());
    cuts_.push_back(Cut{});
    boxes.push_back(lower);
    const int ui = static_cast<int>(cuts_.size());
    cuts_.push_back(Cut{});
    boxes.push_back(upper);
    Cut& c = cuts_[static_cast<std::size_t>(leaf)];
    c.feature = f;
    c.threshold = t;
    c.lower = li;
    c.upper = ui;
    leaves[pick] = li;
    leaves.push_back(ui);
  }
  for (auto& c : cuts_) {
    if (c.feature < 0) c.region = count_++;
  }
}

int RandomRegions::regionOf(const rl_common::State& s) const {
  if (s.size() < numFeatures_) {
    throw std::invalid_argument("RandomRegions::regionOf(): state has too few features");
  }
  const Cut* c = &cuts_[0];
  while (c->feature >= 0) {
    c = &cuts_[static_cast<std::size_t>(
        s[static_cast<std::size_t>(c->feature)] <= c->threshold ? c->lower : c->upper)];
  }
  return c->region;
}

}  // namespace rl_agent
