/**
 * RandomForest: TEXPLORE's ensemble of C4.5 trees for one output variable (the original's
 * MultipleClassifiers; Hester & Stone 2013, §4 of the TEXPLORE-VANIR paper; Breiman, "Random
 * forests", 2001).
 *
 * Each instance goes to each of the m trees independently with probability w (`expPct`,
 * 0.55); if no tree received it, one tree chosen uniformly does. Trees randomise their splits
 * with featPct (0.2). Predictions combine the trees' leaf distributions:
 *   AVERAGE   P(o) = (1/m) sum_i P_i(o)
 *   WEIGHTAVG P(o) = sum_i acc_i P_i(o) / sum_i acc_i
 *   BEST      the tree with the highest running accuracy
 *   SEPARATE  one tree (tree 0) trained on every instance for planning; the forest for variance
 *             (tree 0 is a full C4.5 tree, featPct 0, as the original's SepPlanExplore)
 *   BAGGED    the average of the bagged trees only: trees 1..m-1 of a SEPARATE forest, every
 *             tree of another (the suite's; a recombination for --taskcombo, so that a forest
 *             grown for SEPARATE can be planned on as the AVERAGE of trees grown as AVERAGE's)
 * where acc_i <- acc_i t/(t+1) + [P_i(y) > 0.5]/(t+1) is updated before training on y.
 *
 * The disagreement of the trees (the VANIR variance, paper §4.2, ORIGINAL.md §5.2):
 *   D = (1/(m(m-1))) sum_{i != j} KL(P_i || P_j) / ln 100,
 *   KL(P_i || P_j) = sum_{o: P_i(o) > 0} P_i(o) ln(P_i(o) / P'_j(o)),
 *   P'_j(o) = P_j(o) if non-zero, else 0.01.
 * It is 0 when all trees agree. A forest of one tree has D = 0.
 *
 * The trees keep their inputs in one shared C45Tree::InputTable (the forest's own, or one
 * shared with other forests fed the same inputs), so each input row is stored once.
 */
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "rl_agent/model/c45_tree.h"

namespace rl_agent {

enum class Combination { Average, WeightedAverage, Best, Separate, Bagged };

/// "average", "weighted", "best", "separate" (the --combo values), "bagged" (--taskcombo
/// only); throws otherwise.
Combination combinationFromName(const std::string& name);

class RandomForest {
 public:
  struct Config {
    int numTrees = 5;      ///< m
    double expPct = 0.55;  ///< w: probability that a tree receives an instance
    Combination combination = Combination::Average;
    C45Tree::Config tree;  ///< featPct etc. of every tree
  };

  /// An immutable view of the forest: cheap to copy, safe to read from any thread.
  class Snapshot {
   public:
    Snapshot() = default;
    /// The combined prediction.
    Distribution predict(const std::vector<float>& input) const;
    /// Each tree's own prediction (for tests and the variance).
    std::vector<Distribution> treePredictions(const std::vector<float>& input) const;
    /// D above: the trees' mean pairwise KL divergence / ln 100.
    double variance(const std::vector<float>& input) const;
    /// predict() and, into `*variance`, variance(), from one descent of each tree (the
    /// planner's queries need both; the values are the same as from the two calls).
    Distribution predict(const std::vector<float>& input, double* variance) const;
    std::size_t numTrees() const { return trees_.size(); }
    /// The same trees, combined as `combination` (the trees are shared, not copied).
    Snapshot recombined(Combination combination) const {
      Snapshot s = *this;
      s.combination_ = combination;
      return s;
    }

   private:
    friend class RandomForest;
    /// Every tree's leaf distribution for `input`, in tree order, into `leaves`.
    void leaves(const std::vector<float>& input, std::vector<const Distribution*>* leaves) const;
    Distribution combined(const std::vector<const Distribution*>& leaves) const;
    std::vector<C45Tree::Snapshot> trees_;
    std::vector<double> accuracy_;
    Combination combination_ = Combination::Average;
    /// Tree 0 is SEPARATE's full planning tree, not a bagged one (kept when recombined).
    bool planningTree_ = false;
  };

  /// `seed` seeds the forest's sampling; each tree gets its own derived stream. The trees
  /// keep their inputs in `inputs` if given (shared with whoever else appends to it, all on
  /// one learning thread), else in a table of the forest's own.
  RandomForest(const Config& config, std::uint64_t seed,
               std::shared_ptr<C45Tree::InputTable> inputs = nullptr);
  /// Move-only: the trees share the table, so a copy could not learn independently.
  RandomForest(const RandomForest&) = delete;
  RandomForest& operator=(const RandomForest&) = delete;
  RandomForest(RandomForest&&) = default;
  RandomForest& operator=(RandomForest&&) = default;

  /// Trains on one instance (appending its input to the table); returns true if any tree
  /// changed.
  bool addInstance(const std::vector<float>& input, float output);
  bool addInstances(const std::vector<std::vector<float>>& inputs,
                    const std::vector<float>& outputs);
  /// Trains on one instance whose input is row `row` of the table, which must be newer than
  /// every row the forest has learned. Same as addInstance() with that row's input.
  bool addRow(std::uint32_t row, float output);

  Snapshot snapshot() const;
  Distribution predict(const std::vector<float>& input) const { return snapshot().predict(input); }

  const Config& config() const { return config_; }
  std::size_t numInstances() const { return instances_; }
  /// Tree i (read-only; diagnostics and tests). Throws std::out_of_range.
  const C45Tree& tree(std::size_t i) const { return trees_.at(i); }
  /// The trees' running accuracies acc_i.
  const std::vector<double>& accuracies() const { return accuracy_; }
  /// The table holding the trees' inputs.
  const C45Tree::InputTable& inputs() const { return *inputs_; }

 private:
  /// Throws unless `input` has `expected` values (any if 0) and input and output are not NaN.
  static void checkInstance(const char* method, const std::vector<float>& input, float output,
                            std::size_t expected);
  /// Updates acc_i for an instance (before training on it) and returns the trees that get it.
  std::vector<std::size_t> sampleTrees(const std::vector<float>& input, float output);

  Config config_;
  rl_common::Random rng_;
  std::shared_ptr<C45Tree::InputTable> inputs_;
  std::vector<C45Tree> trees_;
  std::vector<double> accuracy_;
  std::size_t instances_ = 0;
  std::int64_t lastRow_ = -1;  ///< the newest table row learned
};

/// The KL term above for two distributions (with the 0.01 epsilon), in nats. Throws
/// std::invalid_argument if a probability lies outside [0, 1].
double klDivergence(const Distribution& p, const Distribution& q);

}  // namespace rl_agent
