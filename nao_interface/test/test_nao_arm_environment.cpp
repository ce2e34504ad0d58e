// NaoArmEnvironment: the in-process domain (conformance: ranges, actions, seeding) and its
// dynamics (actions move the joints, the pink count changes, the task sets the reward).
#include "nao_interface/env/nao_arm_environment.h"

#include <gtest/gtest.h>

using namespace nao_interface;

namespace {

NaoArmSimConfig config() {
  NaoArmSimConfig c;
  c.urdf = std::string(NAO_INTERFACE_URDF_DIR) + "/nao_upper_body.urdf";
  return c;
}

}  // namespace

TEST(NaoArmEnvironment, StatesStayInRangeAndSameSeedSameTrajectory) {
  NaoArmEnvironment a(config(), NaoArmTask::kExplore, 3), b(config(), NaoArmTask::kExplore, 3);
  std::vector<float> mn, mx;
  a.getMinMaxFeatures(&mn, &mx);
  EXPECT_EQ(a.numActions(), 5);
  EXPECT_FALSE(a.isEpisodic());
  rl_common::Random pick(11);
  for (int i = 0; i < 60; ++i) {
    const int action = pick.uniformInt(0, 4);
    EXPECT_EQ(a.apply(action), 0.0f);
    b.apply(action);
    ASSERT_EQ(a.sensation(), b.sensation());
    ASSERT_EQ(a.sensation().size(), 8u);
    for (std::size_t f = 0; f < 8; ++f) {
      EXPECT_GE(a.sensation()[f], mn[f]) << "feature " << f;
      EXPECT_LE(a.sensation()[f], mx[f]) << "feature " << f;
    }
  }
  EXPECT_THROW(a.apply(5), std::out_of_range);
  EXPECT_THROW(a.apply(-1), std::out_of_range);
}

TEST(NaoArmEnvironment, ActionsMoveTheArmAndBringPinkIntoView) {
  NaoArmEnvironment env(config(), NaoArmTask::kPink, 1);
  const float pitch0 = env.sensation()[0];
  EXPECT_NEAR(pitch0, -72.0f, 0.5f);
  EXPECT_EQ(env.sensation()[5], 0.0f);
  env.apply(0);  // pitch +8
  EXPECT_NEAR(env.sensation()[0], pitch0 + 8.0f, 0.5f);
  env.apply(3);  // roll -8
  EXPECT_NEAR(env.sensation()[1], -20.0f, 0.5f);
  env.apply(2);
  float reward = 0.0f;
  for (int i = 0; i < 8; ++i) reward = env.apply(0);  // down to pitch 0: hand in view
  EXPECT_NEAR(env.sensation()[0], 0.0f, 0.5f);
  EXPECT_GT(env.sensation()[5], 500.0f);
  EXPECT_EQ(reward, env.sensation()[5]);
  env.setTask(NaoArmTask::kButton);
  EXPECT_EQ(env.apply(4), 0.0f);
  env.reset();
  EXPECT_NEAR(env.sensation()[0], -72.0f, 0.5f);
}
