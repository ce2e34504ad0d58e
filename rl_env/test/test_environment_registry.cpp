// The environment registry: the original's names, descriptions, options reaching the
// environments, unknown names.
#include "rl_env/env/environment_registry.h"

#include <gtest/gtest.h>

#include "rl_common/true_model.h"

#include <stdexcept>
#include <string>
#include <vector>

#include "rl_env/env/mountain_car.h"
#include "rl_env/env/robot_car_vel.h"
#include "rl_env/env/two_rooms.h"

namespace {

TEST(EnvironmentRegistry, HasTheOriginalNamesWithDescriptions) {
  const std::vector<std::string> expected = {"car2to7", "car7to2",   "carrandom", "cartpole",
                                             "energy",  "fourrooms", "fuelworld", "lightworld",
                                             "mcar",    "stocks",    "taxi",      "tworooms"};
  EXPECT_EQ(rl_env::builtinEnvironments().registry().names(), expected);
  for (const std::string& name : expected) {
    EXPECT_FALSE(rl_env::builtinEnvironments().registry().description(name).empty()) << name;
    rl_env::EnvironmentOptions o;
    o.env = name;
    EXPECT_NE(rl_env::builtinEnvironments().make(o), nullptr) << name;
  }
}

TEST(EnvironmentRegistry, UnknownNameListsTheValidOnes) {
  rl_env::EnvironmentOptions o;
  o.env = "gridworld";
  try {
    rl_env::builtinEnvironments().make(o);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("gridworld"), std::string::npos);
    EXPECT_NE(what.find("lightworld"), std::string::npos);
    EXPECT_NE(what.find("taxi"), std::string::npos);
  }
}

TEST(EnvironmentRegistry, OptionsReachTheEnvironments) {
  rl_env::EnvironmentOptions o;
  o.env = "stocks";
  o.nsectors = 2;
  o.nstocks = 4;
  EXPECT_EQ(rl_env::builtinEnvironments().make(o)->sensation().size(), 10u);
  EXPECT_EQ(rl_env::builtinEnvironments().make(o)->numActions(), 3);

  o.env = "mcar";
  o.delay = 3;
  o.stochastic = false;
  const auto mcar = rl_env::builtinEnvironments().make(o);
  EXPECT_EQ(dynamic_cast<rl_env::MountainCar&>(*mcar).delay(), 3);
  EXPECT_FALSE(mcar->isStochastic());

  o.env = "tworooms";
  EXPECT_EQ(dynamic_cast<rl_env::TwoRooms&>(*rl_env::builtinEnvironments().make(o)).delay(), 3);

  o.env = "carrandom";
  o.lag = true;
  const auto car = rl_env::builtinEnvironments().make(o);
  EXPECT_TRUE(dynamic_cast<rl_env::RobotCarVel&>(*car).lag());
  EXPECT_EQ(dynamic_cast<rl_env::RobotCarVel&>(*car).task(), rl_env::RobotCarVel::Task::kRandom);

  // The seed reaches the environment: two seeds, two different start states.
  o.env = "lightworld";
  o.seed = 1;
  const rl_common::State a = rl_env::builtinEnvironments().make(o)->sensation();
  o.seed = 2;
  const rl_common::State b = rl_env::builtinEnvironments().make(o)->sensation();
  o.seed = 1;
  EXPECT_EQ(rl_env::builtinEnvironments().make(o)->sensation(), a);
  EXPECT_NE(a, b);
}

}  // namespace

// The registry's "true-model" fact is what `--agent optimal` and the model-accuracy measurement
// are offered: it must hold exactly for the environments that are an rl_common::TrueModel.
TEST(EnvironmentRegistry, TheTrueModelFactHoldsExactlyForTrueModels) {
  const auto& reg = rl_env::builtinEnvironments().registry();
  for (const auto& name : reg.names()) {
    rl_env::EnvironmentOptions o;
    o.env = name;
    const auto env = rl_env::builtinEnvironments().make(o);
    const bool isTrueModel = dynamic_cast<const rl_common::TrueModel*>(env.get()) != nullptr;
    EXPECT_EQ(reg.hasFact(name, rl_env::kTrueModelFact), isTrueModel) << name;
  }
  EXPECT_EQ(rl_env::builtinEnvironments().trueModelNames(),
            "fourrooms, lightworld, taxi, tworooms");
  EXPECT_THROW(reg.hasFact("nosuchenv", rl_env::kTrueModelFact), std::invalid_argument);
}
