#include "rl_agent/model/random_forest.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>

namespace rl_agent {

namespace {

/// Sum of weight_i * P_i over the distributions, equal outcomes merged, sorted by value.
Distribution combine(const std::vector<const Distribution*>& dists,
                     const std::vector<double>& weights) {
  // Weighted outcomes are gathered in a per-thread scratch list and merged there; the result
  // is one allocation of exactly its size (cached predictions keep it, so no spare capacity).
  thread_local Distribution out;
  out.clear();
  for (std::size_t i = 0; i < dists.size(); ++i) {
    if (weights[i] == 0.0) continue;
    for (const auto& [v, p] : *dists[i]) out.emplace_back(v, weights[i] * p);
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  // Merge in place: the same sums, in the same order, as into a second list.
  std::size_t n = 0;
  for (const auto& [v, p] : out) {
    if (n > 0 && out[n - 1].first == v) {
      out[n - 1].second += p;
    } else {
      out[n++] = {v, p};
    }
  }
  return Distribution(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(n));
}

/// KL(P || Q) with the original's epsilon, for distributions known to be valid (tree leaves).
double klUnchecked(const Distribution& p, const Distribution& q) {
  double kl = 0.0;
  for (const auto& [v, pv] : p) {
    if (pv <= 0.0) continue;
    double qv = probabilityOf(q, v);
    if (qv <= 0.0) qv = 0.01;  // the original's zero-probability epsilon
    kl += pv * std::log(pv / qv);
  }
  return kl;
}

std::size_t bestTree(const std::vector<double>& accuracy) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < accuracy.size(); ++i) {
    if (accuracy[i] > accuracy[best]) best = i;
  }
  return best;
}

const double kLn100 = std::log(100.0);

}  // namespace

Combination combinationFromName(const std::string& name) {
  if (name == "average") return Combination::Average;
  if (name == "weighted") return Combination::WeightedAverage;
  if (name == "best") return Combination::Best;
  if (name == "separate") return Combination::Separate;
  if (name == "bagged") return Combination::Bagged;
  throw std::invalid_argument("combinationFromName(): unknown combination '" + name +
                              "'; valid: average, weighted, best, separate, bagged");
}

double klDivergence(const Distribution& p, const Distribution& q) {
  for (const Distribution* d : {&p, &q}) {
    for (const auto& [v, prob] : *d) {
      if (!(prob >= 0.0 && prob <= 1.0)) {
        throw std::invalid_argument("klDivergence(): probability " + std::to_string(prob) +
                                    " of outcome " + std::to_string(v) + " is outside [0, 1]");
      }
    }
  }
  return klUnchecked(p, q);
}

namespace {

/// D of the leaves: mean pairwise KL / ln 100.
double disagreement(const std::vector<const Distribution*>& p) {
  const std::size_t m = p.size();
  if (m < 2) return 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = 0; j < m; ++j) {
      if (i != j) sum += klUnchecked(*p[i], *p[j]);
    }
  }
  return sum / static_cast<double>(m * (m - 1)) / kLn100;
}

// Weight 1/(n - first) for trees first..n-1, 0 before: a per-thread list, no allocation per
// query (the planner's predictions come through here).
const std::vector<double>& equalWeights(std::size_t n, std::size_t first) {
  thread_local std::vector<double> w;
  w.assign(n, 1.0 / static_cast<double>(n - first));
  std::fill(w.begin(), w.begin() + static_cast<std::ptrdiff_t>(first), 0.0);
  return w;
}

// The leaves of one query: reused across a thread's queries (no allocation per query).
std::vector<const Distribution*>& scratchLeaves() {
  thread_local std::vector<const Distribution*> leaves;
  return leaves;
}

}  // namespace

// ------------------------------------------------------------------------------------------
// Snapshot
// ------------------------------------------------------------------------------------------

std::vector<Distribution> RandomForest::Snapshot::treePredictions(
    const std::vector<float>& input) const {
  std::vector<Distribution> out;
  out.reserve(trees_.size());
  for (const C45Tree::Snapshot& t : trees_) out.push_back(t.leaf(input));
  return out;
}

void RandomForest::Snapshot::leaves(const std::vector<float>& input,
                                    std::vector<const Distribution*>* out) const {
  out->clear();
  for (const C45Tree::Snapshot& t : trees_) out->push_back(&t.leaf(input));
}

Distribution RandomForest::Snapshot::combined(
    const std::vector<const Distribution*>& leaves) const {
  switch (combination_) {
    case Combination::Separate:
      return *leaves[0];
    case Combination::Best:
      return *leaves[bestTree(accuracy_)];
    case Combination::WeightedAverage: {
      double sum = 0.0;
      for (double a : accuracy_) sum += a;
      if (sum > 0.0) {
        std::vector<double> w(accuracy_.size());
        for (std::size_t i = 0; i < w.size(); ++i) w[i] = accuracy_[i] / sum;
        return combine(leaves, w);
      }
      break;  // no tree has been right yet: plain average
    }
    case Combination::Bagged:
      if (planningTree_ && leaves.size() > 1)
        return combine(leaves, equalWeights(leaves.size(), 1));
      break;
    case Combination::Average:
      break;
  }
  return combine(leaves, equalWeights(trees_.size(), 0));
}

Distribution RandomForest::Snapshot::predict(const std::vector<float>& input) const {
  if (trees_.empty()) return {{0.0f, 1.0}};  // a default-constructed snapshot
  switch (combination_) {
    case Combination::Separate:
      return trees_[0].leaf(input);
    case Combination::Best:
      return trees_[bestTree(accuracy_)].leaf(input);
    default:
      break;
  }
  auto& l = scratchLeaves();
  leaves(input, &l);
  return combined(l);
}

double RandomForest::Snapshot::variance(const std::vector<float>& input) const {
  if (trees_.size() < 2) return 0.0;
  auto& l = scratchLeaves();
  leaves(input, &l);
  return disagreement(l);
}

Distribution RandomForest::Snapshot::predict(const std::vector<float>& input,
                                             double* variance) const {
  if (trees_.empty()) {
    *variance = 0.0;
    return {{0.0f, 1.0}};
  }
  auto& l = scratchLeaves();
  leaves(input, &l);
  *variance = disagreement(l);
  return combined(l);
}

// ------------------------------------------------------------------------------------------
// RandomForest
// ------------------------------------------------------------------------------------------

RandomForest::RandomForest(const Config& config, std::uint64_t seed,
                           std::shared_ptr<C45Tree::InputTable> inputs)
    : config_(config),
      rng_(rl_common::Random::deriveSeed(seed, "forest_sampling")),
      inputs_(inputs ? std::move(inputs) : std::make_shared<C45Tree::InputTable>()) {
  if (config.numTrees < 1) {
    throw std::invalid_argument("RandomForest::RandomForest(): numTrees must be >= 1, got " +
                                std::to_string(config.numTrees));
  }
  if (!(config.expPct >= 0.0 && config.expPct <= 1.0)) {
    throw std::invalid_argument("RandomForest::RandomForest(): expPct must be in [0, 1], got " +
                                std::to_string(config.expPct));
  }
  trees_.reserve(static_cast<std::size_t>(config.numTrees));
  for (int i = 0; i < config.numTrees; ++i) {
    C45Tree::Config treeConfig = config.tree;
    if (config.combination == Combination::Separate && i == 0) treeConfig.featPct = 0.0;
    // Throws (C45Tree::C45Tree()) on a bad tree configuration.
    trees_.emplace_back(treeConfig,
                        rl_common::Random::deriveSeed(seed, "c45_tree", static_cast<unsigned>(i)),
                        inputs_);
  }
  accuracy_.assign(trees_.size(), 0.0);
}

RandomForest::Snapshot RandomForest::snapshot() const {
  Snapshot s;
  s.trees_.reserve(trees_.size());
  for (const C45Tree& t : trees_) s.trees_.push_back(t.snapshot());
  s.accuracy_ = accuracy_;
  s.combination_ = config_.combination;
  s.planningTree_ = config_.combination == Combination::Separate;
  return s;
}

void RandomForest::checkInstance(const char* method, const std::vector<float>& input, float output,
                                 std::size_t expected) {
  if (input.empty()) {
    throw std::invalid_argument(std::string("RandomForest::") + method + ": empty input");
  }
  if (expected != 0 && input.size() != expected) {
    throw std::invalid_argument(std::string("RandomForest::") + method + ": input has " +
                                std::to_string(input.size()) + " values, expected " +
                                std::to_string(expected));
  }
  for (float x : input) {
    if (std::isnan(x)) {
      throw std::invalid_argument(std::string("RandomForest::") + method + ": NaN input");
    }
  }
  if (std::isnan(output)) {
    throw std::invalid_argument(std::string("RandomForest::") + method + ": NaN output");
  }
}

std::vector<std::size_t> RandomForest::sampleTrees(const std::vector<float>& input, float output) {
  // Running accuracy, scored before the trees learn the instance.
  const double t = static_cast<double>(instances_);
  for (std::size_t i = 0; i < trees_.size(); ++i) {
    const double hit = probabilityOf(trees_[i].predict(input), output) > 0.5 ? 1.0 : 0.0;
    accuracy_[i] = accuracy_[i] * t / (t + 1.0) + hit / (t + 1.0);
  }
  ++instances_;

  std::vector<std::size_t> chosen;
  const bool separate = config_.combination == Combination::Separate;
  if (separate) chosen.push_back(0);  // the planning tree learns everything
  for (std::size_t i = separate ? 1 : 0; i < trees_.size(); ++i) {
    if (rng_.uniform() < config_.expPct) chosen.push_back(i);
  }
  if (chosen.empty()) {
    chosen.push_back(
        static_cast<std::size_t>(rng_.uniformInt(0, static_cast<int>(trees_.size()) - 1)));
  }
  return chosen;
}

bool RandomForest::addInstance(const std::vector<float>& input, float output) {
  checkInstance("addInstance()", input, output, inputs_->numInputs());
  const std::vector<std::size_t> chosen = sampleTrees(input, output);
  const std::uint32_t row = inputs_->append(input);
  lastRow_ = row;
  bool changed = false;
  for (std::size_t i : chosen) changed = trees_[i].addRows({row}, {output}) || changed;
  return changed;
}

bool RandomForest::addRow(std::uint32_t row, float output) {
  if (row >= inputs_->size() || static_cast<std::int64_t>(row) <= lastRow_) {
    throw std::invalid_argument(
        "RandomForest::addRow(): row " + std::to_string(row) + " is not a new row of the table (" +
        std::to_string(inputs_->size()) + " rows, last learned " + std::to_string(lastRow_) + ")");
  }
  const std::vector<float> input = inputs_->row(row);
  checkInstance("addRow()", input, output, 0);
  lastRow_ = row;
  bool changed = false;
  for (std::size_t i : sampleTrees(input, output)) {
    changed = trees_[i].addRows({row}, {output}) || changed;
  }
  return changed;
}

bool RandomForest::addInstances(const std::vector<std::vector<float>>& inputs,
                                const std::vector<float>& outputs) {
  if (inputs.size() != outputs.size()) {
    throw std::invalid_argument("RandomForest::addInstances(): " + std::to_string(inputs.size()) +
                                " inputs but " + std::to_string(outputs.size()) + " outputs");
  }
  // Validate everything first so that a bad instance leaves the forest untouched.
  std::size_t expected = inputs_->numInputs();
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    checkInstance("addInstances()", inputs[k], outputs[k], expected);
    expected = inputs[k].size();  // later instances must match the first
  }
  // Accuracies are scored against the trees as they were before the batch; each tree then
  // learns its share in one call (at most one rebuild per tree).
  std::vector<std::vector<std::uint32_t>> treeRows(trees_.size());
  std::vector<std::vector<float>> treeOutputs(trees_.size());
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    const std::vector<std::size_t> chosen = sampleTrees(inputs[k], outputs[k]);
    const std::uint32_t row = inputs_->append(inputs[k]);
    lastRow_ = row;
    for (std::size_t i : chosen) {
      treeRows[i].push_back(row);
      treeOutputs[i].push_back(outputs[k]);
    }
  }
  bool changed = false;
  for (std::size_t i = 0; i < trees_.size(); ++i) {
    if (!treeRows[i].empty()) {
      changed = trees_[i].addRows(treeRows[i], treeOutputs[i]) || changed;
    }
  }
  return changed;
}

}  // namespace rl_agent
