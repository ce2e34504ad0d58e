// Camera rendering + pink counting: poses that put the square in and out of view, the count
// growing as the square comes closer, and shading out when it is too close to the lens.
#include "nao_interface/camera/scene_renderer.h"

#include <gtest/gtest.h>

#include "nao_interface/camera/pink_detector.h"
#include "nao_interface/sim/nao_arm_simulation.h"

using namespace nao_interface;

namespace {

/// A scene with the camera at the origin looking along torso +x (optical z = torso x).
SceneGeometry facingSquareAt(double distance) {
  SceneGeometry s;
  s.camera.linear() << 0, 0, 1, -1, 0, 0, 0, -1, 0;  // optical x=-y, y=-z, z=+x
  s.pinkSquare.translation() = Eigen::Vector3d(distance, 0, 0);
  s.pinkSquare.linear() << 0, 0, 1, 1, 0, 0, 0, 1, 0;  // normal (z) along torso x
  s.squareSize = 0.06;
  s.cymbal.translation() = Eigen::Vector3d(-5, 0, 0);  // behind the camera
  s.hip = s.ankle = s.bumper = Eigen::Vector3d(-5, 0, 0);
  return s;
}

int pinkAt(double distance) {
  const SceneRenderer r;
  return PinkDetector().count(r.render(facingSquareAt(distance)));
}

}  // namespace

TEST(SceneRenderer, SquareFacingTheCameraCoversItsProjectedArea) {
  const PinholeCamera cam = PinholeCamera::naoTopQvga();
  EXPECT_NEAR(cam.fx, 272.0, 1.0);
  // At 0.3 m a 6 cm square spans 0.06 * fx / 0.3 = 54 pixels a side.
  const double side = 0.06 * cam.fx / 0.3;
  EXPECT_NEAR(pinkAt(0.3), side * side, 0.08 * side * side);
}

TEST(SceneRenderer, CloserIsBiggerUntilTheSquareShadesOut) {
  EXPECT_GT(pinkAt(0.2), pinkAt(0.3));
  EXPECT_GT(pinkAt(0.3), pinkAt(0.5));
  EXPECT_EQ(pinkAt(0.07), 0);  // too close to the lens: shaded, not pink
  EXPECT_EQ(pinkAt(-0.3), 0);  // behind the camera
}

TEST(SceneRenderer, SimulatedArmBringsTheSquareInAndOutOfView) {
  NaoArmSimConfig config;
  config.urdf = std::string(NAO_INTERFACE_URDF_DIR) + "/nao_upper_body.urdf";
  config.stochastic = false;
  NaoArmSimulation sim(config, 1);
  EXPECT_EQ(sim.countPink(), 0);  // start: hand raised in front, the head looks down-right
  sim.setTarget("RShoulderPitch", 0.0, 1.0);  // arm forward, in front of the right leg
  sim.setTarget("RShoulderRoll", 0.0, 1.0);
  sim.advance(1.0);
  const int inView = sim.countPink();
  EXPECT_GT(inView, 500);
  EXPECT_LT(inView, 10000);                       // the paper's highest count was 5434
  sim.setTarget("RShoulderRoll", -1.32645, 1.0);  // far right, out of the image
  sim.advance(1.0);
  EXPECT_EQ(sim.countPink(), 0);
  const cv::Mat img = sim.renderCamera();
  EXPECT_EQ(img.cols, 320);
  EXPECT_EQ(img.rows, 240);
}
