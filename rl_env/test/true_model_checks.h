// Checks shared by the tests of the environments that offer a rl_common::TrueModel.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "rl_common/environment.h"
#include "rl_common/true_model.h"

namespace rl_env_test {

using rl_common::Outcome;
using rl_common::State;

/// Upper 0.1 % point of the chi-square distribution with `df` degrees of freedom
/// (Wilson–Hilferty approximation, accurate to a few percent for df >= 1).
inline double chiSquareCritical001(int df) {
  const double z = 3.090;  // upper 0.1 % point of N(0, 1)
  const double k = df;
  const double a = 2.0 / (9.0 * k);
  return k * std::pow(1.0 - a + z * std::sqrt(a), 3.0);
}

/// The total probability of the outcomes of `outcomes` that lead to `next` (0 if none).
inline double probabilityOf(const std::vector<Outcome>& outcomes, const State& next) {
  double p = 0.0;
  for (const Outcome& o : outcomes) {
    if (o.next == next) p += o.probability;
  }
  return p;
}

/// Probabilities of `outcomes` sum to 1 and are all positive; outcomes are distinct.
inline void expectDistribution(const std::vector<Outcome>& outcomes, const std::string& what) {
  double sum = 0.0;
  std::set<std::pair<State, std::pair<float, bool>>> seen;
  for (const Outcome& o : outcomes) {
    EXPECT_GT(o.probability, 0.0) << what;
    sum += o.probability;
    EXPECT_TRUE(seen.insert({o.next, {o.reward, o.terminal}}).second)
        << what << ": outcomes not merged";
  }
  EXPECT_NEAR(sum, 1.0, 1e-9) << what;
}

/// Puts `env` in `s`, applies `action` `n` times (resetting to `s` each time) and checks the
/// observed outcomes against transitions() with a chi-square test at the 0.1 % level, and that
/// no outcome outside the distribution ever occurs.
template <class Env>
void expectSamplingAgrees(Env& env, const State& s, int action, int n) {
  const std::vector<Outcome> outcomes = env.transitions(s, action);
  std::map<std::pair<State, float>, int> counts;
  for (int i = 0; i < n; ++i) {
    env.setState(s);
    const float r = env.apply(action);
    ++counts[{env.sensation(), r}];
  }
  double chi2 = 0.0;
  int matched = 0;
  for (const Outcome& o : outcomes) {
    const auto it = counts.find({o.next, o.reward});
    const double observed = it == counts.end() ? 0.0 : it->second;
    if (it != counts.end()) matched += it->second;
    const double expected = o.probability * n;
    chi2 += (observed - expected) * (observed - expected) / expected;
  }
  EXPECT_EQ(matched, n) << "an outcome outside transitions() occurred (action " << action << ")";
  if (outcomes.size() > 1) {
    const int df = static_cast<int>(outcomes.size()) - 1;
    EXPECT_LT(chi2, chiSquareCritical001(df)) << "chi-square " << chi2 << " with " << df
                                              << " degrees of freedom (action " << action << ")";
  } else {
    EXPECT_EQ(counts.size(), 1u);
  }
}

/// reachableStates() lists each state once, every distribution from a non-terminal reachable
/// state is a proper distribution over reachable states, and a breadth-first search over
/// transitions() from `starts` reaches exactly reachableStates().
template <class Env>
void expectReachableClosed(const Env& env, const std::vector<State>& starts) {
  const std::vector<State> all = env.reachableStates();
  const std::set<State> reachable(all.begin(), all.end());
  ASSERT_EQ(reachable.size(), all.size()) << "reachableStates() repeats a state";
  for (const State& s : starts) ASSERT_TRUE(reachable.count(s)) << "a start state is missing";

  std::set<State> visited(starts.begin(), starts.end());
  std::vector<State> frontier(starts.begin(), starts.end());
  int outsideCount = 0;
  while (!frontier.empty()) {
    const State s = frontier.back();
    frontier.pop_back();
    for (int a = 0; a < env.numActions(); ++a) {
      const std::vector<Outcome> outcomes = env.transitions(s, a);
      double sum = 0.0;
      for (const Outcome& o : outcomes) {
        sum += o.probability;
        if (!reachable.count(o.next)) ++outsideCount;
        if (!o.terminal && visited.insert(o.next).second) frontier.push_back(o.next);
        if (o.terminal) visited.insert(o.next);
      }
      ASSERT_NEAR(sum, 1.0, 1e-9);
    }
  }
  EXPECT_EQ(outsideCount, 0) << "transitions() leave reachableStates()";
  EXPECT_EQ(visited, reachable) << "reachableStates() differs from what the search reaches: "
                                << visited.size() << " reached, " << reachable.size() << " listed";
}

}  // namespace rl_env_test
