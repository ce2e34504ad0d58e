#include "rl_agent/model/novelty_index.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nanoflann.hpp>
#include <stdexcept>
#include <string>

namespace rl_agent {

namespace {
// Distances are sums of normalised differences; equal states are at exactly 0.
constexpr float kSameState = 1e-6f;
}  // namespace

/// Immutable point set with its k-d tree (L1 metric).
struct NoveltyIndex::Block {
  // nanoflann dataset adaptor over the row-major points.
  struct Points {
    std::vector<float> data;
    std::size_t dim = 0;
    std::size_t kdtree_get_point_count() const { return dim == 0 ? 0 : data.size() / dim; }
    float kdtree_get_pt(std::size_t idx, std::size_t d) const { return data[idx * dim + d]; }
    template <class BBox>
    bool kdtree_get_bbox(BBox&) const {
      return false;
    }
  };
  using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L1_Adaptor<float, Points>, Points, -1,
                                                   std::uint32_t>;

  Block(std::vector<float> data, std::size_t dim) {
    points.data = std::move(data);
    points.dim = dim;
    tree = std::make_unique<Tree>(static_cast<int>(dim), points,
                                  nanoflann::KDTreeSingleIndexAdaptorParams(16));
    tree->buildIndex();
  }
  std::size_t size() const { return points.kdtree_get_point_count(); }

  float nearest(const float* q) const {
    std::uint32_t idx = 0;
    float dist = std::numeric_limits<float>::infinity();
    tree->knnSearch(q, 1, &idx, &dist);
    return dist;
  }
  int countSame(const float* q) const {
    std::vector<std::pair<std::uint32_t, float>> matches;
    nanoflann::SearchParams params;
    params.sorted = false;
    return static_cast<int>(tree->radiusSearch(q, kSameState, matches, params));
  }

  Points points;
  std::unique_ptr<Tree> tree;
};

NoveltyIndex::NoveltyIndex(int numActions, const std::vector<float>& featMin,
                           const std::vector<float>& featMax) {
  if (numActions < 1) {
    throw std::invalid_argument("NoveltyIndex::NoveltyIndex(): numActions must be >= 1");
  }
  if (featMin.size() != featMax.size() || featMin.empty()) {
    throw std::invalid_argument(
        "NoveltyIndex::NoveltyIndex(): feature ranges must be non-empty and of equal length");
  }
  auto scale = std::make_shared<std::vector<float>>(featMin.size());
  for (std::size_t j = 0; j < featMin.size(); ++j) {
    const float range = featMax[j] - featMin[j];
    if (!(range >= 0.0f)) {
      throw std::invalid_argument("NoveltyIndex::NoveltyIndex(): feature " + std::to_string(j) +
                                  " has max < min");
    }
    (*scale)[j] = range > 0.0f ? 1.0f / range : 0.0f;
  }
  snap_.scale_ = scale;
  snap_.min_ = std::make_shared<std::vector<float>>(featMin);
  snap_.numFeatures_ = featMin.size();
  snap_.actions_.resize(numActions);
  for (auto& pa : snap_.actions_) pa.buffer = std::make_shared<std::vector<float>>();
}

std::vector<float> NoveltyIndex::Snapshot::normalise(const rl_common::State& s) const {
  if (s.size() < numFeatures_) {
    throw std::invalid_argument("NoveltyIndex: state has " + std::to_string(s.size()) +
                                " features, expected " + std::to_string(numFeatures_));
  }
  std::vector<float> out(numFeatures_);
  for (std::size_t j = 0; j < numFeatures_; ++j) {
    out[j] = (s[j] - (*min_)[j]) * (*scale_)[j];
  }
  return out;
}

void NoveltyIndex::add(const rl_common::State& s, int action) {
  if (action < 0 || action >= static_cast<int>(snap_.actions_.size())) {
    throw std::invalid_argument("NoveltyIndex::add(): action " + std::to_string(action) +
                                " out of range");
  }
  const std::vector<float> p = snap_.normalise(s);
  Snapshot::PerAction& pa = snap_.actions_[action];
  // Copy-on-write: snapshots taken earlier keep the old buffer.
  auto buffer = std::make_shared<std::vector<float>>(*pa.buffer);
  buffer->insert(buffer->end(), p.begin(), p.end());
  const std::size_t dim = snap_.numFeatures_;
  if (buffer->size() / dim < kBufferSize) {
    pa.buffer = std::move(buffer);
    return;
  }
  // The buffer becomes a block; merge equal-sized blocks like a binary counter carry.
  std::vector<float> merged = std::move(*buffer);
  while (!pa.blocks.empty() && pa.blocks.back()->size() <= merged.size() / dim) {
    const auto& last = pa.blocks.back()->points.data;
    merged.insert(merged.end(), last.begin(), last.end());
    pa.blocks.pop_back();
  }
  pa.blocks.push_back(std::make_shared<const Block>(std::move(merged), dim));
  pa.buffer = std::make_shared<std::vector<float>>();
}

double NoveltyIndex::Snapshot::novelty(const rl_common::State& s, int action) const {
  const PerAction& pa = actions_.at(action);
  if (pa.blocks.empty() && pa.buffer->empty()) return 1.0;
  const std::vector<float> q = normalise(s);
  float best = std::numeric_limits<float>::infinity();
  const std::vector<float>& buf = *pa.buffer;
  for (std::size_t i = 0; i < buf.size(); i += numFeatures_) {
    float d = 0.0f;
    for (std::size_t j = 0; j < numFeatures_ && d < best; ++j) d += std::fabs(buf[i + j] - q[j]);
    best = std::min(best, d);
  }
  for (const auto& b : pa.blocks) best = std::min(best, b->nearest(q.data()));
  if (best < kSameState) return 0.0;
  return std::min(1.0, static_cast<double>(best) / static_cast<double>(numFeatures_));
}

int NoveltyIndex::Snapshot::visits(const rl_common::State& s, int action) const {
  const PerAction& pa = actions_.at(action);
  const std::vector<float> q = normalise(s);
  int count = 0;
  const std::vector<float>& buf = *pa.buffer;
  for (std::size_t i = 0; i < buf.size(); i += numFeatures_) {
    float d = 0.0f;
    for (std::size_t j = 0; j < numFeatures_; ++j) d += std::fabs(buf[i + j] - q[j]);
    count += d < kSameState;
  }
  for (const auto& b : pa.blocks) count += b->countSame(q.data());
  return count;
}

bool NoveltyIndex::Snapshot::stateVisited(const rl_common::State& s) const {
  for (std::size_t a = 0; a < actions_.size(); ++a) {
    if (visits(s, static_cast<int>(a)) > 0) return true;
  }
  return false;
}

std::size_t NoveltyIndex::Snapshot::size(int action) const {
  const PerAction& pa = actions_.at(action);
  std::size_t n = pa.buffer->size() / numFeatures_;
  for (const auto& b : pa.blocks) n += b->size();
  return n;
}

}  // namespace rl_agent
