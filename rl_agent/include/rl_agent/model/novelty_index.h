/**
 * NoveltyIndex: the visited state-actions of an agent, for TEXPLORE-VANIR's novelty reward and
 * for visit counts (Hester & Stone, "Intrinsically motivated model learning for developing
 * curious robots", Artificial Intelligence 2017, §4.2; shared/spec/ORIGINAL.md §5.3).
 *
 * Novelty of (s, a): the L1 distance, with each feature normalised by its declared range, to
 * the nearest state where action a was taken, divided by the number of features:
 *   delta(s, a) = min_{x in X_a} sum_j |s_j - x_j| / (max_j - min_j) / d,
 * 0 if (s, a) itself was visited and 1 if a was never taken. Features with a zero range are
 * skipped (but still count in d, as in the original).
 *
 * Cost: the original scanned every visited state on every query. Here each action's states
 * are kept in k-d trees (nanoflann, L1 metric) by the logarithmic method: a small buffer of
 * recent states searched linearly, and immutable blocks of 2^k * 32 states, merged like a
 * binary counter when the buffer fills. A query costs O(log^2 n); an insertion O(log n)
 * amortised. Blocks are immutable and shared, so a snapshot() is cheap and stays valid and
 * unchanged while the index grows: planner threads query snapshots.
 */
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "rl_common/experience.h"

namespace rl_agent {

class NoveltyIndex {
 public:
  struct Block;  ///< an immutable k-d tree over normalised states (defined in the .cpp)

  /// An immutable view of the index; thread-safe queries.
  class Snapshot {
   public:
    /// delta(s, a) above, in [0, 1].
    double novelty(const rl_common::State& s, int action) const;
    /// How many times exactly (s, a) was added.
    int visits(const rl_common::State& s, int action) const;
    /// True if s was added with any action.
    bool stateVisited(const rl_common::State& s) const;
    /// Number of states added with `action`.
    std::size_t size(int action) const;
    /// Number of actions.
    int numActions() const { return static_cast<int>(actions_.size()); }

   private:
    friend class NoveltyIndex;
    struct PerAction {
      std::vector<std::shared_ptr<const Block>> blocks;
      std::shared_ptr<const std::vector<float>> buffer;  ///< normalised, row-major
    };
    std::vector<float> normalise(const rl_common::State& s) const;
    std::shared_ptr<const std::vector<float>> scale_;  ///< 1/range per feature (0: skipped)
    std::shared_ptr<const std::vector<float>> min_;
    std::size_t numFeatures_ = 0;
    std::vector<PerAction> actions_;
  };

  /// Throws std::invalid_argument if the ranges differ in length, numActions < 1 or a
  /// maximum is below its minimum.
  NoveltyIndex(int numActions, const std::vector<float>& featMin,
               const std::vector<float>& featMax);

  /// Records that `action` was taken in `s` (only the first numFeatures values are used).
  void add(const rl_common::State& s, int action);
  /// The index as it is now.
  Snapshot snapshot() const { return snap_; }

  static constexpr std::size_t kBufferSize = 32;

 private:
  Snapshot snap_;
};

}  // namespace rl_agent
