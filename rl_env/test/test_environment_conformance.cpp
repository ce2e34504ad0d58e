// Conformance of every environment rl_env registers (rl_env/testing/environment_conformance.h).
#include "rl_env/testing/environment_conformance.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace {

using rl_env::testing::Expectation;

// What each environment is, by definition (shared/spec/ORIGINAL.md §4, §8).
const std::map<std::string, Expectation>& expectations() {
  static const std::map<std::string, Expectation> kExpect = {
      {"taxi", {true, true, true, 0}},       {"tworooms", {true, true, true, 2}},
      {"fourrooms", {true, true, true, 0}},  {"energy", {true, true, true, 0}},
      {"fuelworld", {true, true, true, 4}},  {"mcar", {true, true, true, 4}},
      {"cartpole", {true, true, true, 4}},   {"car2to7", {true, false, false, 25}},
      {"car7to2", {true, false, false, 25}}, {"carrandom", {true, false, true, 25}},
      {"stocks", {false, false, true, 0}},   {"lightworld", {false, false, true, 0}},
  };
  return kExpect;
}

TEST(ConformanceSetup, EveryBuiltinEnvironmentHasExpectations) {
  EXPECT_EQ(rl_env::testing::conformanceCases(rl_env::builtinEnvironments(), expectations()).size(),
            expectations().size());
}

}  // namespace

namespace rl_env::testing {

INSTANTIATE_TEST_SUITE_P(Builtin, EnvironmentConformance,
                         ::testing::ValuesIn(conformanceCases(builtinEnvironments(),
                                                              expectations())),
                         conformanceCaseName);

}  // namespace rl_env::testing
