/**
 * C45Tree: an incremental C4.5-style classification tree, the building block of TEXPLORE's
 * random-forest model (Hester & Stone, "TEXPLORE: real-time sample-efficient reinforcement
 * learning for robots", Machine Learning 90(3), 2013; Quinlan, "C4.5", 1993).
 *
 * Inputs are float vectors, outputs float class labels. Internal nodes test one input with a
 * "x <= v" (CUT) or "x == v" (ONLY) split chosen by C4.5 gain ratio
 *   GR = (I(T) - sum_k |T_k|/|T| I(T_k)) / SplitInfo,  I = entropy over output classes,
 * over every input and every observed value v (except the largest; ONLY also skips the
 * smallest), where each candidate (input, v) is skipped with probability `featPct` (the
 * forest's randomisation). Ties keep the first candidate (input order, ascending v, CUT before
 * ONLY). A node whose outputs are all equal, or whose best gain ratio is below
 * `minGainRatio`, is a leaf predicting the frequencies of its outputs.
 *
 * Incremental rule (BUILD_ON_ERROR, shared/spec/ORIGINAL.md §6.3): a new instance is stored;
 * if the tree's current leaf for it gives its output a probability below `rebuildThreshold`
 * (0.75), the tree is rebuilt, re-growing only the subtrees whose split changes or whose
 * instance set grew; otherwise the leaf is left as is and the instance counts at the next
 * rebuild. The first instance always builds the tree.
 *
 * Nodes are immutable and shared: snapshot() returns a cheap, thread-safe view that keeps
 * predicting from the tree as it was while the tree goes on learning, so a planner can read a
 * model that a learner thread is updating without copying it. Memory grows with the data.
 */
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rl_agent/model/distribution.h"
#include "rl_common/random.h"

namespace rl_agent {

class C45Tree {
 public:
  struct Config {
    double featPct = 0.2;            ///< probability of skipping each candidate split
    double rebuildThreshold = 0.75;  ///< rebuild when P(observed output) at its leaf is below
    double minGainRatio = 0.0001;    ///< below this a node becomes a leaf
  };

  struct Node;  ///< immutable tree node (defined in the .cpp)

  /// An immutable view of the tree: cheap to copy, safe to read from any thread.
  class Snapshot {
   public:
    Snapshot() = default;
    /// Output frequencies at the leaf `input` falls into; {0: 1} for an empty tree (as the
    /// original). Throws std::invalid_argument if the input length differs from the tree's.
    Distribution predict(const std::vector<float>& input) const;
    /// Number of nodes (splits and leaves); 0 for an empty tree.
    std::size_t numNodes() const;
    /// Number of splits on the longest root-to-leaf path (0 for a single leaf or empty tree).
    std::size_t depth() const;
    bool empty() const { return root_ == nullptr; }

    /// The tree as text, e.g. "(x0 <= 2 ? {0: 1} : (x1 == 3 ? {1: 0.5, 2: 0.5} : {1: 1}))"
    /// (diagnostics and tests).
    std::string describe() const;
    /// How many of this snapshot's nodes are also nodes of `other` (structure shared between
    /// two versions of a tree; diagnostics and tests).
    std::size_t sharedNodes(const Snapshot& other) const;

   private:
    friend class C45Tree;
    Snapshot(std::shared_ptr<const Node> root, std::size_t numInputs)
        : root_(std::move(root)), numInputs_(numInputs) {}
    std::shared_ptr<const Node> root_;
    std::size_t numInputs_ = 0;
  };

  /// `seed` seeds the tree's own random source (split skipping).
  C45Tree(const Config& config, std::uint64_t seed);

  /// Adds one instance with the incremental rule. Returns true if the tree changed.
  /// Throws std::invalid_argument if the input length differs from earlier instances.
  bool addInstance(const std::vector<float>& input, float output);
  /// Adds many instances, rebuilding at most once (if any of them triggers the rule).
  bool addInstances(const std::vector<std::vector<float>>& inputs,
                    const std::vector<float>& outputs);

  /// Same as snapshot().predict(input).
  Distribution predict(const std::vector<float>& input) const;
  Snapshot snapshot() const;

  std::size_t numInstances() const;
  const Config& config() const { return config_; }

 private:
  struct Store;  ///< the instances, owned by the learning side only
  Config config_;
  rl_common::Random rng_;
  std::shared_ptr<Store> store_;
  std::shared_ptr<const Node> root_;
};

}  // namespace rl_agent
