#include "rl_agent/model/m5_tree.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <stdexcept>

namespace rl_agent {

namespace {

using Examples = std::vector<std::vector<float>>;

double stddev(const std::vector<double>& y, const std::vector<int>& idx) {
  if (idx.size() < 2) return 0.0;
  double sum = 0.0, sq = 0.0;
  for (int i : idx) {
    sum += y[static_cast<std::size_t>(i)];
    sq += y[static_cast<std::size_t>(i)] * y[static_cast<std::size_t>(i)];
  }
  const double n = static_cast<double>(idx.size());
  return std::sqrt(std::max(0.0, sq / n - (sum / n) * (sum / n)));
}

double evaluate(const M5Tree::Node& n, const std::vector<float>& x) {
  double y = n.bias;
  for (std::size_t k = 0; k < n.features.size(); ++k) {
    y += n.weights[k] * x[static_cast<std::size_t>(n.features[k])];
  }
  return y;
}

class Builder {
 public:
  Builder(const Examples& x, const std::vector<double>& y, int d, const M5Tree::Config& c)
      : x_(x), y_(y), d_(d), c_(c) {}

  struct Result {
    std::shared_ptr<M5Tree::Node> node;
    std::set<int> used;  // features tested in the subtree
    double error;        // estimated (corrected) error of the subtree
  };

  Result build(const std::vector<int>& idx, int depth) {
    Result r;
    r.node = std::make_shared<M5Tree::Node>();
    const double sd = stddev(y_, idx);
    int bestF = -1;
    double bestT = 0.0, bestSdr = 0.0;
    if (idx.size() >= 2 * c_.minLeaf && sd > c_.minSdr && depth < c_.maxDepth) {
      findSplit(idx, sd, &bestF, &bestT, &bestSdr);
    }
    if (bestF < 0 || bestSdr <= c_.minSdr) {
      fitModel(idx, c_.allFeatures ? allFeatures() : std::set<int>{}, r.node.get());
      r.error = correctedError(idx, *r.node);
      return r;
    }
    std::vector<int> left, right;
    for (int i : idx) {
      (x_[static_cast<std::size_t>(i)][static_cast<std::size_t>(bestF)] <= bestT ? left : right)
          .push_back(i);
    }
    Result L = build(left, depth + 1), R = build(right, depth + 1);
    r.used = L.used;
    r.used.insert(R.used.begin(), R.used.end());
    r.used.insert(bestF);
    fitModel(idx, c_.allFeatures ? allFeatures() : r.used, r.node.get());
    const double n = static_cast<double>(idx.size());
    const double subtree = (left.size() * L.error + right.size() * R.error) / n;
    const double own = correctedError(idx, *r.node);
    if (c_.prune && own <= subtree) {
      r.error = own;  // the node's linear model is as good: keep it as a leaf
      return r;
    }
    r.node->feature = bestF;
    r.node->threshold = bestT;
    r.node->left = L.node;
    r.node->right = R.node;
    r.error = subtree;
    return r;
  }

 private:
  std::set<int> allFeatures() const {
    std::set<int> all;
    for (int j = 0; j < d_; ++j) all.insert(j);
    return all;
  }

  void findSplit(const std::vector<int>& idx, double sd, int* bestF, double* bestT,
                 double* bestSdr) const {
    const double n = static_cast<double>(idx.size());
    std::vector<int> order(idx);
    for (int f = 0; f < d_; ++f) {
      const auto fs = static_cast<std::size_t>(f);
      std::sort(order.begin(), order.end(), [&](int a, int b) {
        return x_[static_cast<std::size_t>(a)][fs] < x_[static_cast<std::size_t>(b)][fs];
      });
      double totalSum = 0.0, totalSq = 0.0;
      for (int i : order) {
        totalSum += y_[static_cast<std::size_t>(i)];
        totalSq += y_[static_cast<std::size_t>(i)] * y_[static_cast<std::size_t>(i)];
      }
      double sum = 0.0, sq = 0.0;
      for (std::size_t k = 0; k + 1 < order.size(); ++k) {
        const double yk = y_[static_cast<std::size_t>(order[k])];
        sum += yk;
        sq += yk * yk;
        const float a = x_[static_cast<std::size_t>(order[k])][fs];
        const float b = x_[static_cast<std::size_t>(order[k + 1])][fs];
        const std::size_t nl = k + 1, nr = order.size() - nl;
        if (a == b || nl < c_.minLeaf || nr < c_.minLeaf) continue;
        const double ml = sum / nl, mr = (totalSum - sum) / nr;
        const double sdl = std::sqrt(std::max(0.0, sq / nl - ml * ml));
        const double sdr = std::sqrt(std::max(0.0, (totalSq - sq) / nr - mr * mr));
        const double reduction = sd - (nl / n) * sdl - (nr / n) * sdr;
        if (reduction > *bestSdr) {
          *bestSdr = reduction;
          *bestF = f;
          *bestT = 0.5 * (static_cast<double>(a) + static_cast<double>(b));
        }
      }
    }
  }

  void fitModel(const std::vector<int>& idx, const std::set<int>& used, M5Tree::Node* node) const {
    const std::vector<int> feats(used.begin(), used.end());
    const int k = static_cast<int>(feats.size());
    const int rows = static_cast<int>(idx.size());
    Eigen::MatrixXd A(rows, k + 1);
    Eigen::VectorXd b(rows);
    for (int r = 0; r < rows; ++r) {
      const auto& x = x_[static_cast<std::size_t>(idx[static_cast<std::size_t>(r)])];
      for (int c = 0; c < k; ++c)
        A(r, c) = x[static_cast<std::size_t>(feats[static_cast<std::size_t>(c)])];
      A(r, k) = 1.0;
      b(r) = y_[static_cast<std::size_t>(idx[static_cast<std::size_t>(r)])];
    }
    Eigen::MatrixXd normal = A.transpose() * A;
    normal.diagonal().array() += 1e-9 * std::max(1.0, normal.diagonal().maxCoeff());
    const Eigen::VectorXd w = normal.ldlt().solve(A.transpose() * b);
    node->features = feats;
    node->weights.assign(w.data(), w.data() + k);
    node->bias = w(k);
    // Guard against non-finite weights from a degenerate design.
    for (double& v : node->weights) {
      if (!std::isfinite(v)) v = 0.0;
    }
    if (!std::isfinite(node->bias)) node->bias = 0.0;
  }

  double correctedError(const std::vector<int>& idx, const M5Tree::Node& node) const {
    if (idx.empty()) return 0.0;
    double err = 0.0;
    for (int i : idx) {
      err += std::fabs(evaluate(node, x_[static_cast<std::size_t>(i)]) -
                       y_[static_cast<std::size_t>(i)]);
    }
    const double n = static_cast<double>(idx.size());
    const double v = static_cast<double>(node.features.size() + 1);
    const double factor = n > v ? (n + v) / (n - v) : 10.0;
    return err / n * factor;
  }

  const Examples& x_;
  const std::vector<double>& y_;
  int d_;
  const M5Tree::Config& c_;
};

}  // namespace

double M5Tree::Snapshot::predict(const std::vector<float>& x) const {
  const Node* n = root_.get();
  if (n == nullptr) return 0.0;
  while (!n->leaf()) {
    n = x[static_cast<std::size_t>(n->feature)] <= n->threshold ? n->left.get() : n->right.get();
  }
  return evaluate(*n, x);
}

std::size_t M5Tree::Snapshot::numLeaves() const {
  std::size_t count = 0;
  std::vector<const Node*> stack;
  if (root_) stack.push_back(root_.get());
  while (!stack.empty()) {
    const Node* n = stack.back();
    stack.pop_back();
    if (n->leaf()) {
      ++count;
    } else {
      stack.push_back(n->left.get());
      stack.push_back(n->right.get());
    }
  }
  return count;
}

int M5Tree::Snapshot::depth() const {
  struct Item {
    const Node* n;
    int d;
  };
  int best = 0;
  std::vector<Item> stack;
  if (root_) stack.push_back({root_.get(), 0});
  while (!stack.empty()) {
    const Item it = stack.back();
    stack.pop_back();
    best = std::max(best, it.d);
    if (!it.n->leaf()) {
      stack.push_back({it.n->left.get(), it.d + 1});
      stack.push_back({it.n->right.get(), it.d + 1});
    }
  }
  return best;
}

M5Tree::M5Tree(int numInputs, const Config& config) : numInputs_(numInputs), config_(config) {
  if (numInputs < 1 || config.minLeaf < 1 || config.minSdr < 0.0 || config.maxDepth < 0 ||
      config.rebuildTolerance < 0.0) {
    throw std::invalid_argument("M5Tree::M5Tree(): bad configuration");
  }
}

bool M5Tree::add(const std::vector<float>& x, double y) {
  if (static_cast<int>(x.size()) != numInputs_ || !std::isfinite(y) ||
      !std::all_of(x.begin(), x.end(), [](float v) { return std::isfinite(v); })) {
    throw std::invalid_argument("M5Tree::add(): input must have " + std::to_string(numInputs_) +
                                " finite values and a finite target");
  }
  const bool wrong =
      current_.root_ == nullptr || std::fabs(current_.predict(x) - y) > config_.rebuildTolerance;
  x_.push_back(x);
  y_.push_back(y);
  if (!wrong) return false;
  rebuild();
  return true;
}

void M5Tree::fit(const std::vector<std::vector<float>>& X, const std::vector<double>& y) {
  if (X.size() != y.size()) throw std::invalid_argument("M5Tree::fit(): X and y differ in size");
  for (const auto& x : X) {
    if (static_cast<int>(x.size()) != numInputs_) {
      throw std::invalid_argument("M5Tree::fit(): an input has the wrong size");
    }
  }
  x_ = X;
  y_ = y;
  rebuild();
}

void M5Tree::rebuild() {
  if (y_.empty()) {
    current_.root_.reset();
    return;
  }
  std::vector<int> idx(y_.size());
  std::iota(idx.begin(), idx.end(), 0);
  Builder b(x_, y_, numInputs_, config_);
  current_.root_ = b.build(idx, 0).node;
}

}  // namespace rl_agent
