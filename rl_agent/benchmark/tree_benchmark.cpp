// Benchmark of the incremental C4.5 tree and the random forest on LightWorld-sized data:
// 23 inputs (17 small-integer state features + a one-hot over 6 actions) and a few output
// classes, added one instance at a time as an agent would. Prints figures; never fails.
//
//   rl_agent_tree_benchmark [instances=5000] [seed=1]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "rl_agent/model/c45_tree.h"
#include "rl_agent/model/random_forest.h"
#include "rl_common/random.h"

namespace {

struct Data {
  std::vector<std::vector<float>> inputs;
  std::vector<float> featureDelta;  // a state-feature change in {-1, 0, 1}
  std::vector<float> reward;        // a sparse reward
};

Data makeData(int n, std::uint64_t seed) {
  rl_common::Random rng(seed);
  Data d;
  for (int k = 0; k < n; ++k) {
    std::vector<float> x(23, 0.0f);
    for (int j = 0; j < 17; ++j) x[j] = static_cast<float>(rng.uniformInt(0, j < 2 ? 15 : 1));
    const int action = rng.uniformInt(0, 5);
    x[17 + action] = 1.0f;
    // Moves change x0 unless a wall (x0 at the border) or the action does not move.
    float delta = 0.0f;
    if (action == 0 && x[0] < 15) delta = 1.0f;
    if (action == 1 && x[0] > 0) delta = -1.0f;
    if (rng.uniform() < 0.05) delta = 0.0f;  // a little noise
    float r = (action == 4 && x[2] == 1.0f && x[0] == 3.0f) ? 10.0f : 0.0f;
    d.inputs.push_back(x);
    d.featureDelta.push_back(delta);
    d.reward.push_back(r);
  }
  return d;
}

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 5000;
  const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
  const Data d = makeData(n, seed);

  for (double featPct : {0.0, 0.2}) {
    rl_agent::C45Tree::Config config;
    config.featPct = featPct;
    rl_agent::C45Tree tree(config, seed);
    int rebuilds = 0;
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < n; ++k) rebuilds += tree.addInstance(d.inputs[k], d.featureDelta[k]);
    const double t = seconds(start);
    const auto snap = tree.snapshot();
    std::printf(
        "C45Tree featPct %.1f: %d instances x 23 inputs in %.3f s (%.1f us/instance), "
        "%d rebuilds, %zu nodes, depth %zu\n",
        featPct, n, t, 1e6 * t / n, rebuilds, snap.numNodes(), snap.depth());
  }

  {
    rl_agent::C45Tree::Config config;
    config.featPct = 0.0;
    rl_agent::C45Tree tree(config, seed);
    const auto start = std::chrono::steady_clock::now();
    tree.addInstances(d.inputs, d.featureDelta);
    std::printf("C45Tree batch build of %d instances: %.3f s\n", n, seconds(start));
  }

  rl_agent::RandomForest::Config fc;  // TEXPLORE defaults: 5 trees, w 0.55, featPct 0.2
  rl_agent::RandomForest forest(fc, seed);
  rl_agent::RandomForest rewards(fc, seed + 1);
  auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < n; ++k) {
    forest.addInstance(d.inputs[k], d.featureDelta[k]);
    rewards.addInstance(d.inputs[k], d.reward[k]);
  }
  const double tf = seconds(start);
  std::printf("2 forests x 5 trees: %d instances in %.3f s (%.1f us/instance/forest)\n", n, tf,
              1e6 * tf / n / 2);

  const auto snap = forest.snapshot();
  start = std::chrono::steady_clock::now();
  double sink = 0.0;
  const int queries = 200000;
  for (int q = 0; q < queries; ++q) {
    const auto& x = d.inputs[static_cast<std::size_t>(q % n)];
    sink += rl_agent::expectation(snap.predict(x));
  }
  const double tp = seconds(start);
  start = std::chrono::steady_clock::now();
  for (int q = 0; q < queries / 10; ++q) {
    sink += snap.variance(d.inputs[static_cast<std::size_t>(q % n)]);
  }
  const double tv = seconds(start);
  std::printf("forest snapshot: predict %.2f us, variance %.2f us (checksum %.3f)\n",
              1e6 * tp / queries, 1e6 * tv / (queries / 10), sink);
  return 0;
}
