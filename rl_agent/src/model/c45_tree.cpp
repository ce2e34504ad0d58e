#include "rl_agent/model/c45_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <utility>

namespace rl_agent {

// ------------------------------------------------------------------------------------------
// Data structures
// ------------------------------------------------------------------------------------------

/// An immutable node. Internal nodes send inputs with test(x) true to `yes`, others to `no`;
/// leaves hold their output distribution, precomputed, so prediction never needs the instances.
struct C45Tree::Node {
  int dim = -1;           ///< input tested; -1 for a leaf
  float value = 0.0f;     ///< split value v
  bool equality = false;  ///< ONLY split (x == v) rather than CUT (x <= v)
  std::shared_ptr<const Node> yes, no;
  Distribution dist;             ///< leaf prediction
  std::size_t count = 0;         ///< instances the node was grown from
  std::size_t subtreeNodes = 1;  ///< nodes in this subtree, this one included
  std::size_t subtreeDepth = 0;  ///< splits on the longest path below

  bool isLeaf() const { return dim < 0; }
  bool test(float x) const { return equality ? x == value : x <= value; }
  const Node* child(const float* input) const { return test(input[dim]) ? yes.get() : no.get(); }

  Node() = default;
  Node(const Node&) = delete;
  Node& operator=(const Node&) = delete;
  /// Releases the subtree without recursion, so that very deep trees cannot overflow the stack.
  ~Node();
};

C45Tree::Node::~Node() {
  std::vector<std::shared_ptr<const Node>> pending;
  if (yes) pending.push_back(std::move(yes));
  if (no) pending.push_back(std::move(no));
  while (!pending.empty()) {
    std::shared_ptr<const Node> n = std::move(pending.back());
    pending.pop_back();
    if (n.use_count() == 1) {
      // Sole owner: nobody else can reach the node any more, so its children may be detached
      // (the node object itself was created non-const by make_shared).
      Node& mut = const_cast<Node&>(*n);
      if (mut.yes) pending.push_back(std::move(mut.yes));
      if (mut.no) pending.push_back(std::move(mut.no));
    }
  }
}

namespace c45_detail {

/// The learner-side instance store: the instances' rows in the input table, class ids, and per
/// input the rows sorted by value (merged lazily before each rebuild). The inputs themselves
/// stay in the table, which the trees fed the same rows share.
struct InstanceStore {
  std::size_t count = 0;                          ///< instances
  std::vector<std::uint32_t> pending;             ///< rows added since the last prepare()
  std::vector<std::uint32_t> classOf;             ///< class id of the instance at table row r
  std::vector<float> classValue;                  ///< class id -> output value
  std::map<float, std::uint32_t> classIndex;      ///< output value -> class id (== equality)
  std::vector<std::vector<std::uint32_t>> order;  ///< order[d]: rows sorted by input d, then row

  std::int64_t lastRow = -1;  ///< the highest row added

  std::size_t size() const { return count; }

  void add(std::uint32_t row, float output) {
    auto it = classIndex.find(output);
    if (it == classIndex.end()) {
      it = classIndex.emplace(output, static_cast<std::uint32_t>(classValue.size())).first;
      classValue.push_back(output);
    }
    if (classOf.size() <= row) classOf.resize(std::size_t{row} + 1, 0);
    classOf[row] = it->second;
    pending.push_back(row);
    lastRow = row;
    ++count;
  }

  /// Merges the rows added since the last call into the per-input sorted orders: O(N + m log m)
  /// per input for m new rows. Rows arrive in ascending order, so breaking ties on the row
  /// keeps the order of arrival.
  void prepare(const std::vector<std::vector<float>>& columns) {
    if (pending.empty()) return;
    if (order.empty()) order.assign(columns.size(), {});
    for (std::size_t d = 0; d < columns.size(); ++d) {
      const std::vector<float>& col = columns[d];
      auto less = [&col](std::uint32_t a, std::uint32_t b) {
        return col[a] < col[b] || (col[a] == col[b] && a < b);
      };
      std::vector<std::uint32_t>& o = order[d];
      const std::size_t mid = o.size();
      o.insert(o.end(), pending.begin(), pending.end());
      std::sort(o.begin() + static_cast<std::ptrdiff_t>(mid), o.end(), less);
      std::inplace_merge(o.begin(), o.begin() + static_cast<std::ptrdiff_t>(mid), o.end(), less);
    }
    pending.clear();
  }
};

}  // namespace c45_detail

struct C45Tree::Store : c45_detail::InstanceStore {};

namespace {

using Node = C45Tree::Node;
using NodePtr = std::shared_ptr<const Node>;

/// A node's instances sorted by each input: row d lists them in ascending order of input d.
/// The root reads the store's own orders; every other node owns one flat buffer of d rows
/// (its size may exceed d * n: buffers are recycled within a rebuild).
struct Lists {
  const std::vector<std::vector<std::uint32_t>>* shared = nullptr;
  std::vector<std::uint32_t> own;
  std::size_t n = 0;
  const std::uint32_t* row(std::size_t d) const {
    return shared ? (*shared)[d].data() : own.data() + d * n;
  }
};

// Candidates whose gain ratio is within this of the best so far count as ties, so the first
// one found keeps winning even when rounding differs between equal candidates (the gain ratio
// lies in [0, 1]).
constexpr double kTieTolerance = 1e-9;

struct Split {
  int dim = -1;
  float value = 0.0f;
  bool equality = false;
  double gainRatio = -1.0;
  std::size_t numYes = 0;  // instances for which the test holds
};

/// Spare list buffers, kept per thread between rebuilds (all trees a learner thread grows share
/// them, so the memory kept is that of one rebuild, not one per tree). At most kMaxSpare.
constexpr std::size_t kMaxSpare = 8;
std::vector<std::vector<std::uint32_t>>& spareBuffers() {
  thread_local std::vector<std::vector<std::uint32_t>> spare;
  return spare;
}

const Node* findLeaf(const Node* node, const float* input) {
  while (!node->isLeaf()) node = node->child(input);
  return node;
}

void checkInput(const char* method, const std::vector<float>& input, std::size_t expected) {
  if (input.empty()) {
    throw std::invalid_argument(std::string("C45Tree::") + method + ": empty input");
  }
  if (expected != 0 && input.size() != expected) {
    throw std::invalid_argument(std::string("C45Tree::") + method + ": input has " +
                                std::to_string(input.size()) + " values, expected " +
                                std::to_string(expected));
  }
  for (float x : input) {
    if (std::isnan(x)) {
      throw std::invalid_argument(std::string("C45Tree::") + method + ": NaN input");
    }
  }
}

/// One rebuild of the tree: grows a new root from the previous one, reusing every subtree
/// whose path of splits is unchanged and whose instance count did not grow. Iterative (an
/// explicit stack), so the depth of the tree is not bounded by the call stack.
class Builder {
 public:
  Builder(const c45_detail::InstanceStore& store, const std::vector<std::vector<float>>& columns,
          const std::vector<double>& xlogx, std::size_t tableSize, const C45Tree::Config& config,
          rl_common::Random& rng)
      : store_(store),
        columns_(columns),
        xlogx_(xlogx),
        config_(config),
        rng_(rng),
        localOf_(store.classValue.size(), -1),
        side_(tableSize, 0),
        pool_(std::move(spareBuffers())) {
    spareBuffers().clear();
  }
  ~Builder() {
    if (pool_.size() > kMaxSpare) {  // keep the largest
      std::sort(pool_.begin(), pool_.end(),
                [](const auto& a, const auto& b) { return a.size() > b.size(); });
      pool_.resize(kMaxSpare);
    }
    spareBuffers() = std::move(pool_);
  }
  Builder(const Builder&) = delete;
  Builder& operator=(const Builder&) = delete;

  NodePtr build(const NodePtr& oldRoot) {
    struct Frame {
      NodePtr old;  // the node at the same place in the previous tree, if its path is unchanged
      Lists lists;
      std::size_t count = 0;
      int stage = 0;
      Split split;
      bool keep = false;  // the old node's split was chosen again
      bool reuseNo = false;
      Lists noLists;
      NodePtr yes;
    };
    std::vector<Frame> stack;
    stack.emplace_back();
    stack.back().old = oldRoot;
    stack.back().lists.shared = &store_.order;
    stack.back().lists.n = store_.size();
    NodePtr result;
    while (!stack.empty()) {
      Frame& f = stack.back();
      if (f.stage == 0) {
        f.count = f.lists.n;
        if (f.old && f.old->count == f.count) {  // same path, same instances: unchanged
          result = f.old;
          release(f.lists);
          stack.pop_back();
          continue;
        }
        mapClasses(f.lists.row(0), f.count);
        Split split;
        if (numLocal_ < 2 || !bestSplit(f.lists, split) || split.gainRatio < config_.minGainRatio) {
          result = makeLeaf(f.count);
          unmapClasses();
          release(f.lists);
          stack.pop_back();
          continue;
        }
        unmapClasses();
        const bool keep = f.old && !f.old->isLeaf() && f.old->dim == split.dim &&
                          f.old->value == split.value && f.old->equality == split.equality;
        const bool reuseYes = keep && f.old->yes->count == split.numYes;
        const bool reuseNo = keep && f.old->no->count == f.count - split.numYes;
        Lists yesLists;
        partition(f.lists, split, !reuseYes, !reuseNo, yesLists, f.noLists);
        release(f.lists);
        f.split = split;
        f.keep = keep;
        f.reuseNo = reuseNo;
        f.stage = 1;
        if (reuseYes) {
          result = f.old->yes;
          continue;  // straight to stage 1
        }
        NodePtr childOld = keep ? f.old->yes : nullptr;
        stack.emplace_back();  // invalidates f
        stack.back().old = std::move(childOld);
        stack.back().lists = std::move(yesLists);
      } else if (f.stage == 1) {
        f.yes = std::move(result);
        f.stage = 2;
        if (f.reuseNo) {
          result = f.old->no;
          continue;
        }
        NodePtr childOld = f.keep ? f.old->no : nullptr;
        Lists noLists = std::move(f.noLists);
        stack.emplace_back();  // invalidates f
        stack.back().old = std::move(childOld);
        stack.back().lists = std::move(noLists);
      } else {
        auto node = std::make_shared<Node>();
        node->dim = f.split.dim;
        node->value = f.split.value;
        node->equality = f.split.equality;
        node->count = f.count;
        node->subtreeNodes = 1 + f.yes->subtreeNodes + result->subtreeNodes;
        node->subtreeDepth = 1 + std::max(f.yes->subtreeDepth, result->subtreeDepth);
        node->yes = std::move(f.yes);
        node->no = std::move(result);
        result = std::move(node);
        stack.pop_back();
      }
    }
    return result;
  }

 private:
  /// Numbers the classes present among `ids` 0..numLocal_-1 and counts them into total_.
  void mapClasses(const std::uint32_t* ids, std::size_t n) {
    numLocal_ = 0;
    localClasses_.clear();
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t g = store_.classOf[ids[k]];
      if (localOf_[g] < 0) {
        localOf_[g] = static_cast<int>(numLocal_++);
        localClasses_.push_back(g);
      }
    }
    total_.assign(numLocal_, 0);
    for (std::size_t k = 0; k < n; ++k) {
      ++total_[static_cast<std::size_t>(localOf_[store_.classOf[ids[k]]])];
    }
  }

  void unmapClasses() {
    for (std::uint32_t g : localClasses_) localOf_[g] = -1;
  }

  NodePtr makeLeaf(std::size_t n) const {
    auto node = std::make_shared<Node>();
    node->count = n;
    node->dist.reserve(numLocal_);
    for (std::size_t c = 0; c < numLocal_; ++c) {
      node->dist.emplace_back(store_.classValue[localClasses_[c]],
                              static_cast<double>(total_[c]) / static_cast<double>(n));
    }
    std::sort(node->dist.begin(), node->dist.end());
    return node;
  }

  /// Evaluates every CUT and ONLY candidate of every input in one sorted sweep per input (the
  /// lists are already sorted): cumulative class counts give the CUT partitions, the run of
  /// equal values the ONLY partitions. The gain ratio of a partition into (Y, N) is
  ///   GR = (D - S(T) + S(Y) + S(N)) / D,  S(X) = sum_c n_c ln n_c,  D = f(n) - f(|Y|) - f(|N|)
  /// with f(x) = x ln x, which is the C4.5 gain over the split information (both times n).
  bool bestSplit(const Lists& lists, Split& best) {
    const std::size_t n = lists.n;
    const std::vector<double>& f = xlogx_;
    long double sT = 0.0L;
    for (std::size_t c = 0; c < numLocal_; ++c) sT += f[total_[c]];
    cum_.assign(numLocal_, 0);
    group_.assign(numLocal_, 0);
    bool found = false;
    auto consider = [&](int dim, float value, bool equality, long double sYes, long double sNo,
                        std::size_t nYes) {
      const long double d = static_cast<long double>(f[n]) - f[nYes] - f[n - nYes];
      if (d <= 0.0L) return;
      const double gr = static_cast<double>((d - sT + sYes + sNo) / d);
      if (gr > best.gainRatio + kTieTolerance) {
        best = Split{dim, value, equality, gr, nYes};
        found = true;
      }
    };
    for (std::size_t dim = 0; dim < columns_.size(); ++dim) {
      const std::uint32_t* l = lists.row(dim);
      const std::vector<float>& col = columns_[dim];
      if (col[l[0]] == col[l[n - 1]]) continue;  // constant input: no candidate
      std::fill(cum_.begin(), cum_.end(), 0);
      long double sLeft = 0.0L, sRight = sT;
      std::size_t pos = 0;
      while (true) {
        const float v = col[l[pos]];
        std::size_t end = pos;
        touched_.clear();
        while (end < n && col[l[end]] == v) {
          const auto c = static_cast<std::size_t>(localOf_[store_.classOf[l[end]]]);
          if (group_[c]++ == 0) touched_.push_back(c);
          ++end;
        }
        if (end == n) {  // the largest value: no candidate
          for (std::size_t c : touched_) group_[c] = 0;
          break;
        }
        const bool skip = config_.featPct > 0.0 && rng_.uniform() < config_.featPct;
        for (std::size_t c : touched_) {
          const std::uint32_t before = cum_[c], after = before + group_[c];
          sLeft += static_cast<long double>(f[after]) - f[before];
          sRight += static_cast<long double>(f[total_[c] - after]) - f[total_[c] - before];
          cum_[c] = after;
        }
        if (!skip) {
          consider(static_cast<int>(dim), v, false, sLeft, sRight, end);  // CUT x <= v
          if (pos > 0) {                                                  // ONLY x == v
            long double sYes = 0.0L, sNo = sT;
            for (std::size_t c : touched_) {
              sYes += f[group_[c]];
              sNo -= static_cast<long double>(f[total_[c]]) - f[total_[c] - group_[c]];
            }
            consider(static_cast<int>(dim), v, true, sYes, sNo, end - pos);
          }
        }
        for (std::size_t c : touched_) group_[c] = 0;
        pos = end;
      }
    }
    return found;
  }

  /// A buffer for d rows of n instances plus one slack slot (for the branch-free partition):
  /// the smallest spare one that is large enough, else the largest spare one grown.
  std::vector<std::uint32_t> acquire(std::size_t size) {
    std::vector<std::uint32_t> buf;
    if (!pool_.empty()) {
      std::size_t pick = 0;
      for (std::size_t i = 1; i < pool_.size(); ++i) {
        const std::size_t have = pool_[i].size(), best = pool_[pick].size();
        const bool fits = have > size, bestFits = best > size;
        if ((fits && (!bestFits || have < best)) || (!fits && !bestFits && have > best)) pick = i;
      }
      buf = std::move(pool_[pick]);
      pool_[pick] = std::move(pool_.back());
      pool_.pop_back();
    }
    if (buf.size() < size + 1) buf.resize(size + 1);
    return buf;
  }

  void release(Lists& lists) {
    if (!lists.own.empty()) pool_.push_back(std::move(lists.own));
    lists = Lists();
  }

  /// Splits the sorted lists by the test, keeping the order; only the sides asked for.
  void partition(const Lists& lists, const Split& split, bool wantYes, bool wantNo, Lists& yes,
                 Lists& no) {
    const std::vector<float>& col = columns_[static_cast<std::size_t>(split.dim)];
    const std::size_t n = lists.n, numRows = columns_.size();
    const std::uint32_t* ids = lists.row(0);
    for (std::size_t k = 0; k < n; ++k) {
      const float x = col[ids[k]];
      side_[ids[k]] = (split.equality ? x == split.value : x <= split.value) ? 1 : 0;
    }
    yes.n = split.numYes;
    no.n = n - split.numYes;
    if (wantYes) yes.own = acquire(numRows * yes.n);
    if (wantNo) no.own = acquire(numRows * no.n);
    for (std::size_t d = 0; d < numRows; ++d) {
      const std::uint32_t* r = lists.row(d);
      std::uint32_t* y = wantYes ? yes.own.data() + d * yes.n : nullptr;
      std::uint32_t* o = wantNo ? no.own.data() + d * no.n : nullptr;
      if (wantYes && wantNo) {
        // Branch-free: write to both, advance one (each row's last write lands in the next
        // row's first slot or in the slack slot, and is overwritten or ignored).
        for (std::size_t k = 0; k < n; ++k) {
          const std::uint32_t id = r[k];
          const std::size_t s = static_cast<std::size_t>(side_[id]);
          *y = id;
          *o = id;
          y += s;
          o += 1 - s;
        }
      } else if (wantYes) {
        for (std::size_t k = 0; k < n; ++k) {
          if (side_[r[k]]) *y++ = r[k];
        }
      } else if (wantNo) {
        for (std::size_t k = 0; k < n; ++k) {
          if (!side_[r[k]]) *o++ = r[k];
        }
      }
    }
  }

  const c45_detail::InstanceStore& store_;
  const std::vector<std::vector<float>>& columns_;  // the input table's columns
  const std::vector<double>& xlogx_;
  const C45Tree::Config& config_;
  rl_common::Random& rng_;
  std::vector<int> localOf_;                 // global class id -> local id, -1 if absent
  std::vector<std::uint32_t> localClasses_;  // local id -> global class id
  std::size_t numLocal_ = 0;
  std::vector<std::uint32_t> total_, cum_, group_;
  std::vector<std::size_t> touched_;
  std::vector<char> side_;
  std::vector<std::vector<std::uint32_t>> pool_;  // spare list buffers
};

void describeNode(const Node* node, std::ostringstream& out) {
  if (node->isLeaf()) {
    out << '{';
    for (std::size_t i = 0; i < node->dist.size(); ++i) {
      out << (i ? ", " : "") << node->dist[i].first << ": " << node->dist[i].second;
    }
    out << '}';
    return;
  }
  out << "(x" << node->dim << (node->equality ? " == " : " <= ") << node->value << " ? ";
  describeNode(node->yes.get(), out);
  out << " : ";
  describeNode(node->no.get(), out);
  out << ')';
}

}  // namespace

// ------------------------------------------------------------------------------------------
// Snapshot
// ------------------------------------------------------------------------------------------

Distribution C45Tree::Snapshot::predict(const std::vector<float>& input) const {
  return leaf(input);
}

const Distribution& C45Tree::Snapshot::leaf(const std::vector<float>& input) const {
  static const Distribution kEmptyTree{{0.0f, 1.0}};
  if (!root_) return kEmptyTree;
  if (input.size() != numInputs_) {
    throw std::invalid_argument("C45Tree::Snapshot::predict(): input has " +
                                std::to_string(input.size()) + " values, expected " +
                                std::to_string(numInputs_));
  }
  return findLeaf(root_.get(), input.data())->dist;
}

std::size_t C45Tree::Snapshot::numNodes() const { return root_ ? root_->subtreeNodes : 0; }

std::size_t C45Tree::Snapshot::depth() const { return root_ ? root_->subtreeDepth : 0; }

std::string C45Tree::Snapshot::describe() const {
  if (!root_) return "{}";
  std::ostringstream out;
  describeNode(root_.get(), out);
  return out.str();
}

std::size_t C45Tree::Snapshot::sharedNodes(const Snapshot& other) const {
  if (!root_ || !other.root_) return 0;
  std::unordered_set<const Node*> theirs;
  std::vector<const Node*> pending{other.root_.get()};
  while (!pending.empty()) {
    const Node* n = pending.back();
    pending.pop_back();
    theirs.insert(n);
    if (!n->isLeaf()) {
      pending.push_back(n->yes.get());
      pending.push_back(n->no.get());
    }
  }
  std::size_t shared = 0;
  pending.push_back(root_.get());
  while (!pending.empty()) {
    const Node* n = pending.back();
    pending.pop_back();
    if (theirs.count(n)) {
      shared += n->subtreeNodes;  // immutable: the whole subtree is shared
    } else if (!n->isLeaf()) {
      pending.push_back(n->yes.get());
      pending.push_back(n->no.get());
    }
  }
  return shared;
}

// ------------------------------------------------------------------------------------------
// InputTable
// ------------------------------------------------------------------------------------------

std::uint32_t C45Tree::InputTable::append(const std::vector<float>& row) {
  checkInput("InputTable::append()", row, numInputs());
  if (size_ >= std::numeric_limits<std::uint32_t>::max()) {
    throw std::invalid_argument("C45Tree::InputTable::append(): table full");
  }
  if (columns_.empty()) columns_.assign(row.size(), {});
  for (std::size_t d = 0; d < row.size(); ++d) columns_[d].push_back(row[d]);
  return static_cast<std::uint32_t>(size_++);
}

std::vector<float> C45Tree::InputTable::row(std::uint32_t id) const {
  if (id >= size_) {
    throw std::out_of_range("C45Tree::InputTable::row(): row " + std::to_string(id) + " of " +
                            std::to_string(size_));
  }
  std::vector<float> out(columns_.size());
  for (std::size_t d = 0; d < out.size(); ++d) out[d] = columns_[d][id];
  return out;
}

void C45Tree::InputTable::prepareXlogx(std::size_t n) {
  for (std::size_t c = xlogx_.size(); c <= n; ++c) {
    xlogx_.push_back(c == 0 ? 0.0 : static_cast<double>(c) * std::log(static_cast<double>(c)));
  }
}

// ------------------------------------------------------------------------------------------
// C45Tree
// ------------------------------------------------------------------------------------------

C45Tree::C45Tree(const Config& config, std::uint64_t seed, std::shared_ptr<InputTable> inputs)
    : config_(config),
      rng_(seed),
      inputs_(std::move(inputs)),
      ownsInputs_(inputs_ == nullptr),
      store_(std::make_shared<Store>()) {
  if (!inputs_) inputs_ = std::make_shared<InputTable>();
  if (!(config.featPct >= 0.0 && config.featPct <= 1.0)) {
    throw std::invalid_argument("C45Tree::C45Tree(): featPct must be in [0, 1], got " +
                                std::to_string(config.featPct));
  }
  if (!(config.rebuildThreshold >= 0.0 && config.rebuildThreshold <= 1.0)) {
    throw std::invalid_argument("C45Tree::C45Tree(): rebuildThreshold must be in [0, 1], got " +
                                std::to_string(config.rebuildThreshold));
  }
  if (!(config.minGainRatio >= 0.0)) {
    throw std::invalid_argument("C45Tree::C45Tree(): minGainRatio must be >= 0, got " +
                                std::to_string(config.minGainRatio));
  }
}

C45Tree::Snapshot C45Tree::snapshot() const { return Snapshot(root_, inputs_->numInputs()); }

Distribution C45Tree::predict(const std::vector<float>& input) const {
  return snapshot().predict(input);
}

std::size_t C45Tree::numInstances() const { return store_->size(); }

bool C45Tree::addInstance(const std::vector<float>& input, float output) {
  return addInstances({input}, {output});
}

bool C45Tree::addInstances(const std::vector<std::vector<float>>& inputs,
                           const std::vector<float>& outputs) {
  if (inputs.size() != outputs.size()) {
    throw std::invalid_argument("C45Tree::addInstances(): " + std::to_string(inputs.size()) +
                                " inputs but " + std::to_string(outputs.size()) + " outputs");
  }
  if (inputs.empty()) return false;
  std::size_t numInputs = inputs_->numInputs();
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    checkInput("addInstance()", inputs[k], numInputs);
    if (std::isnan(outputs[k])) {
      throw std::invalid_argument("C45Tree::addInstance(): NaN output");
    }
    numInputs = inputs[k].size();
  }
  // Copy-on-write: a copied C45Tree shares its own table until one of the copies learns.
  if (ownsInputs_ && inputs_.use_count() > 1) inputs_ = std::make_shared<InputTable>(*inputs_);
  std::vector<std::uint32_t> rows;
  rows.reserve(inputs.size());
  for (const auto& x : inputs) rows.push_back(inputs_->append(x));
  return learn(rows, outputs);
}

bool C45Tree::addRows(const std::vector<std::uint32_t>& rows, const std::vector<float>& outputs) {
  if (rows.size() != outputs.size()) {
    throw std::invalid_argument("C45Tree::addRows(): " + std::to_string(rows.size()) +
                                " rows but " + std::to_string(outputs.size()) + " outputs");
  }
  std::int64_t last = store_->lastRow;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (rows[k] >= inputs_->size() || static_cast<std::int64_t>(rows[k]) <= last) {
      throw std::invalid_argument("C45Tree::addRows(): row " + std::to_string(rows[k]) +
                                  " is not a new row of the table (" +
                                  std::to_string(inputs_->size()) + " rows, last added " +
                                  std::to_string(last) + ")");
    }
    if (std::isnan(outputs[k])) throw std::invalid_argument("C45Tree::addRows(): NaN output");
    last = rows[k];
  }
  return learn(rows, outputs);
}

bool C45Tree::learn(const std::vector<std::uint32_t>& rows, const std::vector<float>& outputs) {
  if (rows.empty()) return false;
  // Copy-on-write: a copied C45Tree shares the store until one of the copies learns.
  if (store_.use_count() > 1) store_ = std::make_shared<Store>(*store_);

  // The rule is checked against the tree as it was before these instances.
  const std::vector<std::vector<float>>& columns = inputs_->columns_;
  bool rebuild = root_ == nullptr;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    store_->add(rows[k], outputs[k]);
    if (!rebuild) {
      const Node* leaf = root_.get();
      while (!leaf->isLeaf()) {
        const float x = columns[static_cast<std::size_t>(leaf->dim)][rows[k]];
        leaf = leaf->test(x) ? leaf->yes.get() : leaf->no.get();
      }
      rebuild = probabilityOf(leaf->dist, outputs[k]) < config_.rebuildThreshold;
    }
  }
  if (!rebuild) return false;
  store_->prepare(columns);
  inputs_->prepareXlogx(store_->size());
  root_ = Builder(*store_, columns, inputs_->xlogx_, inputs_->size(), config_, rng_).build(root_);
  return true;
}

}  // namespace rl_agent
