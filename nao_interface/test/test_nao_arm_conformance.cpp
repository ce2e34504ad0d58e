// The simulated Nao arm passes rl_env's environment conformance suite, registered as the
// runner registers it (addNaoArmEnvironment), and its --task reaches the environment.
#include "rl_env/testing/environment_conformance.h"

#include <gtest/gtest.h>

#include <map>
#include <string>

#include "nao_interface/env/nao_arm_registration.h"

namespace {

const rl_env::EnvironmentCatalog& naoCatalog() {
  static const rl_env::EnvironmentCatalog catalog = [] {
    rl_env::EnvironmentCatalog c;
    nao_interface::addNaoArmEnvironment(c);
    return c;
  }();
  return catalog;
}

const std::map<std::string, rl_env::testing::Expectation>& expectations() {
  // Non-episodic, no terminal state, noisy joints, no seed experiences; renders a camera image.
  static const std::map<std::string, rl_env::testing::Expectation> kExpect = {
      {"naoarm", {false, false, true, 0, true}}};
  return kExpect;
}

TEST(NaoArmRegistration, TaskIsAnOptionOfNaoarmAlone) {
  const auto& catalog = naoCatalog();
  ASSERT_EQ(catalog.extraOptions().size(), 1u);
  EXPECT_EQ(catalog.extraOptions()[0].name, "task");
  EXPECT_EQ(catalog.extraOptions()[0].defaultValue, "explore");
  EXPECT_TRUE(catalog.registry().takesOption("naoarm", "task"));
  rl_env::EnvironmentCatalog twice;
  nao_interface::addNaoArmEnvironment(twice);
  EXPECT_THROW(nao_interface::addNaoArmEnvironment(twice), std::invalid_argument);
}

TEST(NaoArmRegistration, TheTaskReachesTheEnvironment) {
  rl_env::EnvironmentOptions o;
  o.env = "naoarm";
  float min = 0, max = 0;
  naoCatalog().make(o)->getMinMaxReward(&min, &max);
  EXPECT_EQ(max, 1.0f);  // explore: reward 0, declared range [0, 1]
  o.extra["task"] = "button";
  naoCatalog().make(o)->getMinMaxReward(&min, &max);
  EXPECT_EQ(max, 200.0f);
  o.extra["task"] = "dance";
  EXPECT_THROW(naoCatalog().make(o), std::invalid_argument);
}

}  // namespace

namespace rl_env::testing {

INSTANTIATE_TEST_SUITE_P(NaoArm, EnvironmentConformance,
                         ::testing::ValuesIn(conformanceCases(naoCatalog(), expectations())),
                         conformanceCaseName);

}  // namespace rl_env::testing
