// NaoBody: loading the seated Nao's URDF, clear errors, and link positions against
// hand-computed poses (shared/spec/NAO.md §1.3-1.4).
#include "nao_interface/kinematics/nao_body.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

using nao_interface::JointAngles;
using nao_interface::NaoBody;

namespace {

const std::string kUrdf = std::string(NAO_INTERFACE_URDF_DIR) + "/nao_upper_body.urdf";

JointAngles seated(double headYaw = 0.0, double headPitch = 0.0) {
  return {{"RShoulderPitch", 0.0},   {"RShoulderRoll", 0.0}, {"RElbowYaw", 0.0},
          {"RElbowRoll", 0.0349066}, {"RWristYaw", 0.0},     {"HeadYaw", headYaw},
          {"HeadPitch", headPitch},  {"RHipYawPitch", 0.0},  {"RHipRoll", 0.0},
          {"RHipPitch", -1.5},       {"RKneePitch", 0.0},    {"RAnklePitch", 0.0},
          {"RAnkleRoll", 0.0}};
}

std::string readUrdf() {
  std::ifstream in(kUrdf);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(NaoBody, CameraPoseMatchesHandComputation) {
  const NaoBody body = NaoBody::fromUrdfFile(kUrdf);
  // HeadPitch 0: camera at (58.71, 0, 126.5 + 63.64) mm (NAO.md: (58.7, 0, 190.1)).
  Eigen::Isometry3d cam = body.linkPose("CameraTop_optical_frame", seated());
  EXPECT_NEAR(cam.translation().x() * 1000, 58.71, 1e-3);
  EXPECT_NEAR(cam.translation().z() * 1000, 190.14, 1e-3);
  // The optical axis (z) looks forward, tilted 1.2 degrees down.
  EXPECT_NEAR(cam.linear().col(2).x(), std::cos(0.0209435), 1e-4);
  EXPECT_NEAR(cam.linear().col(2).z(), -std::sin(0.0209435), 1e-4);
  // Looking down (HeadPitch 0.515): (82.4, 0, 153.0) mm, axis (0.86, 0, -0.51).
  cam = body.linkPose("CameraTop_optical_frame", seated(0.0, 0.514872));
  EXPECT_NEAR(cam.translation().x() * 1000, 82.4, 0.2);
  EXPECT_NEAR(cam.translation().z() * 1000, 153.0, 0.2);
  EXPECT_NEAR(cam.linear().col(2).x(), 0.86, 0.01);
  EXPECT_NEAR(cam.linear().col(2).z(), -0.51, 0.01);
}

TEST(NaoBody, FootBumperOfTheStretchedLeg) {
  const NaoBody body = NaoBody::fromUrdfFile(kUrdf);
  // Hip (0, -50, -85) + Ry(-1.5) (0, 0, -202.9) + Ry(-1.5) (87.6, -2.5, -35.3), by hand.
  const double c = std::cos(-1.5), s = std::sin(-1.5);
  const Eigen::Vector3d expect(-202.9 * s + 87.6 * c - 35.3 * s, -52.5,
                               -85.0 - 202.9 * c - 87.6 * s - 35.3 * c);
  const Eigen::Vector3d p = body.position("RFootBumper", seated()) * 1000.0;
  EXPECT_NEAR((p - expect).norm(), 0.0, 1e-6);
  EXPECT_NEAR(p.x(), 244, 1.0);  // NAO.md §1.4: about (244, -53, -14)
  EXPECT_NEAR(p.z(), -14, 1.0);
}

TEST(NaoBody, ClampsToJointLimits) {
  const NaoBody body = NaoBody::fromUrdfFile(kUrdf);
  EXPECT_NEAR(body.clamp("RShoulderRoll", -3.0), -1.32645, 1e-9);
  EXPECT_NEAR(body.clamp("RShoulderRoll", 1.0), 0.314159, 1e-9);
  EXPECT_NEAR(body.clamp("HeadPitch", 0.3), 0.3, 1e-12);
  EXPECT_NEAR(body.joint("RShoulderPitch").velocity, 8.26797, 1e-9);
  EXPECT_THROW(body.joint("LShoulderPitch"), std::invalid_argument);
}

TEST(NaoBody, ErrorsNameTheFileAndTheMissingElement) {
  try {
    NaoBody::fromUrdfFile("/nonexistent/nao.urdf");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/nao.urdf"), std::string::npos);
  }
  std::string urdf = readUrdf();
  const std::string from = "name=\"HeadPitch\"", to = "name=\"HeadTilt\"";
  urdf.replace(urdf.find(from), from.size(), to);
  try {
    NaoBody::fromUrdfString(urdf, "broken.urdf");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("broken.urdf"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("no joint 'HeadPitch'"), std::string::npos);
  }
  EXPECT_THROW(NaoBody::fromUrdfString("<robot name='x'><link", "bad.urdf"), std::runtime_error);
  const NaoBody body = NaoBody::fromUrdfFile(kUrdf);
  JointAngles q = seated();
  q.erase("HeadYaw");
  EXPECT_THROW(body.linkPose("CameraTop_optical_frame", q), std::invalid_argument);
  EXPECT_NO_THROW(body.linkPose("r_gripper", q));  // the arm does not need the head
}
