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
 *
 * Trees fed the same inputs (a forest's trees, a factored model's forests) can share one
 * append-only InputTable: each tree then stores only row ids, its per-input sort orders and
 * class ids, not its own copy of every input row. A tree built without a table owns one.
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

  /// Append-only table of input rows shared by the trees that learn from them. Only the
  /// learning side touches it (snapshots never do), so all trees sharing one table must learn
  /// on the same thread.
  class InputTable {
   public:
    /// Appends a row and returns its id (ids count up from 0). Throws std::invalid_argument
    /// on an empty row, a NaN, or a length differing from the first row's.
    std::uint32_t append(const std::vector<float>& row);
    std::size_t size() const { return size_; }
    /// Row length (0 while the table is empty).
    std::size_t numInputs() const { return columns_.size(); }
    /// Row `id` (throws std::out_of_range).
    std::vector<float> row(std::uint32_t id) const;

   private:
    friend class C45Tree;
    /// Extends xlogx_ up to n.
    void prepareXlogx(std::size_t n);
    std::vector<std::vector<float>> columns_;  ///< columns_[d][id] = input d of row id
    std::size_t size_ = 0;
    std::vector<double> xlogx_;  ///< xlogx_[c] = c ln c (the gain ratio's counts)
  };

  /// An immutable view of the tree: cheap to copy, safe to read from any thread.
  class Snapshot {
   public:
    Snapshot() = default;
    /// Output frequencies at the leaf `input` falls into; {0: 1} for an empty tree (as the
    /// original). Throws std::invalid_argument if the input length differs from the tree's.
    Distribution predict(const std::vector<float>& input) const;
    /// The same without a copy: the leaf's own distribution, valid while this snapshot (or a
    /// copy) lives.
    const Distribution& leaf(const std::vector<float>& input) const;
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

  /// `seed` seeds the tree's own random source (split skipping). With `inputs` the tree keeps
  /// its instances' inputs in that shared table (copies of the tree share it too); without,
  /// it owns a table of its own (copied on write, so copies learn independently).
  C45Tree(const Config& config, std::uint64_t seed, std::shared_ptr<InputTable> inputs = nullptr);

  /// Adds one instance with the incremental rule. Returns true if the tree changed.
  /// Throws std::invalid_argument if the input length differs from earlier instances.
  bool addInstance(const std::vector<float>& input, float output);
  /// Adds many instances, rebuilding at most once (if any of them triggers the rule).
  bool addInstances(const std::vector<std::vector<float>>& inputs,
                    const std::vector<float>& outputs);
  /// Adds instances whose inputs are rows already in the tree's table (see addInstances()).
  /// Rows must come in ascending order, each above every row the tree has (ties between equal
  /// inputs break on the row id, i.e. on the order of arrival). Throws std::invalid_argument
  /// otherwise, or on a NaN output; a bad batch leaves the tree untouched.
  bool addRows(const std::vector<std::uint32_t>& rows, const std::vector<float>& outputs);

  /// Same as snapshot().predict(input).
  Distribution predict(const std::vector<float>& input) const;
  Snapshot snapshot() const;

  std::size_t numInstances() const;
  const Config& config() const { return config_; }
  /// The table holding the inputs (the shared one, or the tree's own).
  const InputTable& inputs() const { return *inputs_; }

 private:
  struct Store;  ///< the instances' ids, orders and classes, owned by the learning side only
  bool learn(const std::vector<std::uint32_t>& rows, const std::vector<float>& outputs);
  Config config_;
  rl_common::Random rng_;
  std::shared_ptr<InputTable> inputs_;
  bool ownsInputs_ = false;  ///< the table is this tree's own (copy it on write)
  std::shared_ptr<Store> store_;
  std::shared_ptr<const Node> root_;
};

}  // namespace rl_agent
