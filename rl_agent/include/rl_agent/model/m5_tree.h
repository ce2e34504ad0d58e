/**
 * M5Tree: a regression tree with linear models at its leaves (Quinlan, "Learning with
 * continuous classes", Proc. 5th Australian Joint Conference on AI, 1992; the original's
 * M5Tree, ORIGINAL.md §6.4), for continuous domains (mcar, cartpole).
 *
 * Growing: a node with at least 2·minLeaf examples is split on the feature and threshold
 * (midpoint between consecutive distinct values) that maximise the standard deviation
 * reduction SDR = sd(T) − Σ_i |T_i|/|T| sd(T_i); a node stays a leaf when its sd or the best
 * SDR is below `minSdr` (the original's MIN_SDR = treeThresh · range) or at `maxDepth`.
 * Models: every node gets a least-squares linear model y ≈ w·x_F + b over the features F tested
 * in its subtree (constant at a bottom leaf; all features with `allFeatures`, the original's
 * M5ALLMULTI), fitted with Eigen (a tiny ridge 1e-9 keeps degenerate designs solvable).
 * Pruning (bottom-up): a subtree becomes a leaf with its node's model when the model's
 * estimated error is no larger than the subtree's, the error being the mean absolute residual
 * times (n + ν)/(n − ν), ν = number of parameters (Quinlan's pessimistic correction).
 * Learning online: add() keeps every example and rebuilds the whole tree when the current
 * prediction of the new example is off by more than `rebuildTolerance` (the original rebuilt
 * on any error). Smoothing is not done.
 *
 * snapshot() is cheap (nodes are immutable and shared) and safe to use from any thread.
 */
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

namespace rl_agent {

class M5Tree {
 public:
  struct Config {
    std::size_t minLeaf = 2;  ///< examples at least on each side of a split
    double minSdr = 1e-4;     ///< minimum sd / SDR worth splitting
    int maxDepth = 30;
    bool allFeatures = false;  ///< leaf models over every feature
    bool prune = true;
    double rebuildTolerance = 1e-6;  ///< add(): rebuild when |prediction − y| exceeds this
  };

  struct Node {
    // Split (children non-null): x[feature] <= threshold goes left.
    int feature = -1;
    double threshold = 0.0;
    std::shared_ptr<const Node> left, right;
    // Linear model: y = bias + Σ weights[k] x[features[k]].
    std::vector<int> features;
    std::vector<double> weights;
    double bias = 0.0;
    bool leaf() const { return left == nullptr; }
  };

  /// An immutable tree: thread-safe predictions.
  class Snapshot {
   public:
    /// The tree's prediction (0 before any data).
    double predict(const std::vector<float>& x) const;
    std::size_t numLeaves() const;
    int depth() const;
    const Node* root() const { return root_.get(); }

   private:
    friend class M5Tree;
    std::shared_ptr<const Node> root_;
  };

  /// Throws std::invalid_argument if numInputs < 1 or the config is bad.
  M5Tree(int numInputs, const Config& config);

  /// Adds one example; rebuilds if needed; returns true if the tree changed. Throws
  /// std::invalid_argument for an input of the wrong size or a non-finite value.
  bool add(const std::vector<float>& x, double y);
  /// Replaces the data with (X, y) and builds the tree.
  void fit(const std::vector<std::vector<float>>& X, const std::vector<double>& y);

  double predict(const std::vector<float>& x) const { return current_.predict(x); }
  Snapshot snapshot() const { return current_; }
  std::size_t numExamples() const { return y_.size(); }
  std::size_t numLeaves() const { return current_.numLeaves(); }

 private:
  void rebuild();

  int numInputs_;
  Config config_;
  std::vector<std::vector<float>> x_;
  std::vector<double> y_;
  Snapshot current_;
};

}  // namespace rl_agent
