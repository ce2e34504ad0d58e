// The paper's Nao task: actions, features and rewards (TEXPLORE-VANIR §5.2).
#include "nao_interface/env/nao_arm_task.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace nao_interface;

TEST(NaoArmTask, RewardsFollowThePaper) {
  NaoArmObservation o;
  o.pinkPixels = 5434;
  o.bumper = true;
  o.micEnergy = 6000;
  EXPECT_EQ(taskReward(NaoArmTask::kExplore, o), 0.0f);
  EXPECT_EQ(taskReward(NaoArmTask::kPink, o), 5434.0f);
  EXPECT_EQ(taskReward(NaoArmTask::kButton, o), 200.0f);
  EXPECT_EQ(taskReward(NaoArmTask::kMic, o), 4000.0f);  // capped
  o.bumper = false;
  EXPECT_EQ(taskReward(NaoArmTask::kButton, o), 0.0f);
  float lo, hi;
  naoArmRewardRange(NaoArmTask::kPink, &lo, &hi);
  EXPECT_EQ(hi, 153600.0f);
}

TEST(NaoArmTask, EightFeaturesInsideTheirRanges) {
  NaoArmObservation o;
  o.shoulderPitch = M_PI / 2;
  o.shoulderRoll = -M_PI / 4;
  o.handMm = Eigen::Vector3d(100, -200, 50);
  o.pinkPixels = 1234;
  o.bumper = true;
  o.micEnergy = 9000;
  const auto s = toState(o);
  ASSERT_EQ(s.size(), 8u);
  EXPECT_NEAR(s[0], 90.0f, 1e-4);
  EXPECT_NEAR(s[1], -45.0f, 1e-4);
  EXPECT_EQ(s[3], -200.0f);
  EXPECT_EQ(s[5], 1234.0f);
  EXPECT_EQ(s[6], 1.0f);
  EXPECT_EQ(s[7], 4000.0f);
  std::vector<float> mn, mx;
  naoArmFeatureRanges(&mn, &mx);
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_GE(s[i], mn[i]);
    EXPECT_LE(s[i], mx[i]);
  }
}

TEST(NaoArmTask, ActionsStepEightDegreesWithinLimits) {
  const NaoBody body =
      NaoBody::fromUrdfFile(std::string(NAO_INTERFACE_URDF_DIR) + "/nao_upper_body.urdf");
  const double d = 8 * M_PI / 180;
  const Eigen::Vector2d t(0.0, 0.0);
  EXPECT_NEAR(applyNaoArmAction(0, t, body)[0], d, 1e-12);
  EXPECT_NEAR(applyNaoArmAction(1, t, body)[0], -d, 1e-12);
  EXPECT_NEAR(applyNaoArmAction(2, t, body)[1], d, 1e-12);
  EXPECT_NEAR(applyNaoArmAction(3, t, body)[1], -d, 1e-12);
  EXPECT_EQ(applyNaoArmAction(4, t, body), t);
  EXPECT_NEAR(applyNaoArmAction(2, Eigen::Vector2d(0.0, 0.3), body)[1], 0.314159, 1e-9);
  EXPECT_THROW(applyNaoArmAction(5, t, body), std::out_of_range);
  EXPECT_EQ(parseNaoArmTask("button"), NaoArmTask::kButton);
  EXPECT_THROW(parseNaoArmTask("dance"), std::invalid_argument);
}
