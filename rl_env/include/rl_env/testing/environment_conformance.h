/**
 * The environment conformance suite: declared ranges respected, action range enforced, seed
 * experiences valid, terminal handling per the environment's definition, seeded
 * reproducibility. A package that registers environments runs it over its own: include this
 * header in one test file and instantiate EnvironmentConformance with conformanceCases() over
 * its catalog and what each environment is by definition (shared/spec/ORIGINAL.md §4, §8).
 */
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "rl_common/random.h"
#include "rl_env/env/environment_registry.h"

namespace rl_env::testing {

using rl_common::Environment;
using rl_common::State;

/// What an environment is, by definition.
struct Expectation {
  bool episodic;
  bool terminates;  ///< a random policy reaches a terminal state
  bool stochastic;  ///< random dynamics or start states under the default options
  std::size_t seeds;
  bool slow = false;  ///< milliseconds per step (e.g. a rendered camera image): fewer steps
};

struct ConformanceCase {
  std::string name;
  const EnvironmentCatalog* catalog;
  Expectation expect;
};

/// One case per environment of `catalog`; throws std::logic_error naming an environment
/// without an expectation or an expectation without an environment.
inline std::vector<ConformanceCase> conformanceCases(
    const EnvironmentCatalog& catalog, const std::map<std::string, Expectation>& expectations) {
  std::vector<ConformanceCase> out;
  for (const std::string& name : catalog.registry().names()) {
    const auto it = expectations.find(name);
    if (it == expectations.end()) {
      throw std::logic_error("conformance: no expectation for environment '" + name + "'");
    }
    out.push_back({name, &catalog, it->second});
  }
  if (out.size() != expectations.size()) {
    throw std::logic_error("conformance: an expectation names an unregistered environment");
  }
  return out;
}

/// Test names: the environment's.
inline std::string conformanceCaseName(const ::testing::TestParamInfo<ConformanceCase>& info) {
  return info.param.name;
}

inline ::testing::AssertionResult inRange(const State& s, const std::vector<float>& min,
                                          const std::vector<float>& max) {
  if (s.size() != min.size()) {
    return ::testing::AssertionFailure()
           << "state has " << s.size() << " features, declared " << min.size();
  }
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!(s[i] >= min[i] && s[i] <= max[i])) {
      return ::testing::AssertionFailure()
             << "feature " << i << " = " << s[i] << " outside [" << min[i] << ", " << max[i] << "]";
    }
  }
  return ::testing::AssertionSuccess();
}

class EnvironmentConformance : public ::testing::TestWithParam<ConformanceCase> {
 protected:
  const Expectation& expect() const { return GetParam().expect; }
  /// `n` steps, or a twentieth of them for a slow environment.
  int steps(int n) const { return expect().slow ? n / 20 : n; }
  std::unique_ptr<Environment> make(std::uint64_t seed, bool stochastic = true) const {
    EnvironmentOptions o;
    o.env = GetParam().name;
    o.seed = seed;
    o.stochastic = stochastic;
    return GetParam().catalog->make(o);
  }
};

TEST_P(EnvironmentConformance, DescriptionIsConsistent) {
  const auto env = make(1);
  const rl_common::EnvironmentDescription d = env->describe();
  EXPECT_GT(d.numActions, 0);
  ASSERT_EQ(d.minFeatures.size(), d.maxFeatures.size());
  ASSERT_GT(d.numFeatures(), 0u);
  for (std::size_t i = 0; i < d.numFeatures(); ++i) EXPECT_LT(d.minFeatures[i], d.maxFeatures[i]);
  EXPECT_LT(d.minReward, d.maxReward);
  EXPECT_EQ(env->sensation().size(), d.numFeatures());
  EXPECT_EQ(d.episodic, expect().episodic);
  EXPECT_EQ(d.title, "Environment: " + env->name() + "\n");
}

TEST_P(EnvironmentConformance, StatesAndRewardsStayInsideTheDeclaredRanges) {
  for (bool stochastic : {true, false}) {
    const auto env = make(3, stochastic);
    std::vector<float> min, max;
    env->getMinMaxFeatures(&min, &max);
    float rmin = 0, rmax = 0;
    env->getMinMaxReward(&rmin, &rmax);
    rl_common::Random actions(17);
    ASSERT_TRUE(inRange(env->sensation(), min, max)) << "start state";
    for (int step = 0; step < steps(4000); ++step) {
      const float r = env->apply(actions.uniformInt(0, env->numActions() - 1));
      ASSERT_GE(r, rmin) << "step " << step;
      ASSERT_LE(r, rmax) << "step " << step;
      ASSERT_TRUE(inRange(env->sensation(), min, max)) << "step " << step;
      if (env->terminal()) {
        env->reset();
        ASSERT_TRUE(inRange(env->sensation(), min, max)) << "after reset";
      }
    }
  }
}

TEST_P(EnvironmentConformance, ApplyRejectsActionsOutOfRange) {
  const auto env = make(1);
  const State before = env->sensation();
  for (int a : {-1, env->numActions(), env->numActions() + 7}) {
    try {
      env->apply(a);
      ADD_FAILURE() << "no exception for action " << a;
    } catch (const std::out_of_range& e) {
      EXPECT_NE(std::string(e.what()).find("::apply():"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(env->sensation(), before);
}

TEST_P(EnvironmentConformance, SeedExperiencesAreValid) {
  const auto env = make(5);
  std::vector<float> min, max;
  env->getMinMaxFeatures(&min, &max);
  float rmin = 0, rmax = 0;
  env->getMinMaxReward(&rmin, &rmax);
  const std::vector<rl_common::Experience> seeds = env->seedExperiences();
  EXPECT_EQ(seeds.size(), expect().seeds);
  for (const rl_common::Experience& e : seeds) {
    EXPECT_TRUE(inRange(e.s, min, max));
    EXPECT_TRUE(inRange(e.next, min, max));
    EXPECT_GE(e.action, 0);
    EXPECT_LT(e.action, env->numActions());
    EXPECT_GE(e.reward, rmin);
    EXPECT_LE(e.reward, rmax);
    if (!expect().episodic) {
      EXPECT_FALSE(e.terminal);
    }
  }
  // Seeds are a function of the seed: asking twice gives the same list.
  const std::vector<rl_common::Experience> again = env->seedExperiences();
  ASSERT_EQ(again.size(), seeds.size());
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    EXPECT_EQ(again[i].s, seeds[i].s);
    EXPECT_EQ(again[i].next, seeds[i].next);
  }
}

TEST_P(EnvironmentConformance, TerminalHandlingFollowsTheDefinition) {
  const auto env = make(7);
  rl_common::Random actions(8);
  EXPECT_FALSE(env->terminal()) << "a start state is terminal";
  int terminals = 0;
  const int budget = steps(expect().terminates ? 200000 : 5000);
  for (int step = 0; step < budget && terminals < 3; ++step) {
    env->apply(actions.uniformInt(0, env->numActions() - 1));
    if (env->terminal()) {
      ++terminals;
      env->reset();
      ASSERT_FALSE(env->terminal()) << "terminal right after reset";
    }
  }
  if (expect().terminates) {
    EXPECT_EQ(terminals, 3) << "a random policy never ended an episode";
  } else {
    EXPECT_EQ(terminals, 0) << "an environment without terminal states reported one";
  }
}

// Runs `steps` random actions (from an action stream seeded independently of the
// environment) with resets, recording every state and reward.
inline std::vector<State> trajectory(Environment& env, int steps) {
  rl_common::Random actions(99);
  std::vector<State> out{env.sensation()};
  for (int i = 0; i < steps; ++i) {
    const float r = env.apply(actions.uniformInt(0, env.numActions() - 1));
    out.push_back(env.sensation());
    out.back().push_back(r);
    if (env.terminal()) {
      env.reset();
      out.push_back(env.sensation());
    }
  }
  return out;
}

TEST_P(EnvironmentConformance, SameSeedSameTrajectoryDifferentSeedsDiffer) {
  const auto a = make(42);
  const auto b = make(42);
  const auto c = make(43);
  const int n = steps(1000);
  const std::vector<State> ta = trajectory(*a, n);
  EXPECT_EQ(ta, trajectory(*b, n));
  if (expect().stochastic) {
    EXPECT_NE(ta, trajectory(*c, n));
  } else {
    EXPECT_EQ(ta, trajectory(*c, n)) << "deterministic environment depends on its seed";
  }
}

}  // namespace rl_env::testing
