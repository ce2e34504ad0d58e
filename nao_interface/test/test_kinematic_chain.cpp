// Forward kinematics of the Nao right arm against hand-computed poses (NAO.md §1.2):
// T = Tr(0,-98,100) Ry(sp) Rz(sr) Tr(105,-15,0) Rx(ey) Rz(er) Tr(55.95,0,0) Rx(wy)
//     Tr(57.75,0,-12.13)   (millimetres, torso frame)
#include "nao_interface/kinematics/kinematic_chain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using nao_interface::KinematicChain;

namespace {

const std::string kUrdf = std::string(NAO_INTERFACE_URDF_DIR) + "/nao_upper_body.urdf";

Eigen::Vector3d handMm(const KinematicChain& c, double sp, double sr, double ey, double er,
                       double wy) {
  return c.tipPose({sp, sr, ey, er, wy}).translation() * 1000.0;
}

}  // namespace

TEST(KinematicChain, RightArmJointsInOrderWithLimits) {
  const auto arm = KinematicChain::fromUrdfFile(kUrdf, "torso", "r_gripper");
  EXPECT_EQ(arm.movableJointNames(),
            (std::vector<std::string>{"RShoulderPitch", "RShoulderRoll", "RElbowYaw", "RElbowRoll",
                                      "RWristYaw"}));
  EXPECT_NEAR(arm.joint("RShoulderPitch").lower, -119.5 * M_PI / 180, 1e-4);
  EXPECT_NEAR(arm.joint("RShoulderRoll").lower, -76.0 * M_PI / 180, 1e-4);
  EXPECT_NEAR(arm.joint("RShoulderRoll").upper, 18.0 * M_PI / 180, 1e-4);
  EXPECT_THROW(arm.joint("RHand"), std::invalid_argument);  // fixed, not movable
}

TEST(KinematicChain, StraightArmPointsForward) {
  const auto arm = KinematicChain::fromUrdfFile(kUrdf, "torso", "r_gripper");
  // All zero but RElbowRoll = 0.0349: the arm points along +x (NAO.md: (219, -109, 88)).
  const Eigen::Vector3d p = handMm(arm, 0, 0, 0, 0.0349066, 0);
  const double er = 0.0349066;
  // By hand: x = 105 + 55.95 cos(er) + 57.75 cos(er); y = -98 - 15 + (55.95 + 57.75) sin(er);
  // z = 100 - 12.13.
  EXPECT_NEAR(p.x(), 105 + 113.7 * std::cos(er), 1e-6);
  EXPECT_NEAR(p.y(), -113 + 113.7 * std::sin(er), 1e-6);
  EXPECT_NEAR(p.z(), 87.87, 1e-6);
  EXPECT_NEAR(p.x(), 219, 0.5);
  EXPECT_NEAR(p.y(), -109, 0.5);
}

TEST(KinematicChain, ShoulderPitchDownAndRollOut) {
  const auto arm = KinematicChain::fromUrdfFile(kUrdf, "torso", "r_gripper");
  // Pitch +90 deg about y turns the arm's +x into -z: hand below the shoulder.
  Eigen::Vector3d p = handMm(arm, M_PI / 2, 0, 0, 0, 0);
  EXPECT_NEAR(p.x(), -12.13, 1e-6);  // the hand offset's -z turns into -x
  EXPECT_NEAR(p.y(), -113, 1e-6);
  EXPECT_NEAR(p.z(), 100 - 218.7, 1e-6);
  // Roll -76 deg about z with pitch 0: far right (NAO.md: (42, -313, 88)).
  p = handMm(arm, 0, -76 * M_PI / 180, 0, 0.0349066, 0);
  EXPECT_NEAR(p.x(), 42, 1.0);
  EXPECT_NEAR(p.y(), -313, 1.0);
  EXPECT_NEAR(p.z(), 88, 1.0);
}

TEST(KinematicChain, ClearErrorsNameFileAndLink) {
  try {
    KinematicChain::fromUrdfFile("/nonexistent/nao.urdf", "torso", "r_gripper");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/nao.urdf"), std::string::npos);
  }
  try {
    KinematicChain::fromUrdfFile(kUrdf, "torso", "l_gripper");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no link 'l_gripper'"), std::string::npos);
  }
  EXPECT_THROW(KinematicChain::fromUrdfString("<robot name='x'><link", "a", "b", "bad.urdf"),
               std::runtime_error);
  const auto arm = KinematicChain::fromUrdfFile(kUrdf, "torso", "r_gripper");
  EXPECT_THROW(arm.tipPose({0.0}), std::invalid_argument);
}
