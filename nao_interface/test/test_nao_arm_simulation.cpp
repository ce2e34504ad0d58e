// NaoArmSimulation: speed-limited joints that stop at their limits, bumper edges, cymbal and
// body sounds, seeded sensor noise.
#include "nao_interface/sim/nao_arm_simulation.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace nao_interface;

namespace {

constexpr double kDeg = M_PI / 180.0;

NaoArmSimConfig config(bool stochastic = false) {
  NaoArmSimConfig c;
  c.urdf = std::string(NAO_INTERFACE_URDF_DIR) + "/nao_upper_body.urdf";
  c.stochastic = stochastic;
  return c;
}

/// Highest front-microphone energy of the buffers completed so far.
double drainEnergy(NaoArmSimulation& sim) {
  double e = 0.0;
  while (auto b = sim.nextAudioBuffer()) {
    e = std::max(e, audioEnergy(*b, MicrophoneModel::kChannels, MicrophoneModel::kFrontChannel));
  }
  return e;
}

}  // namespace

TEST(NaoArmSimulation, JointsMoveAtLimitedSpeedAndStopAtLimits) {
  NaoArmSimulation sim(config(), 1);
  const double start = sim.angles().at("RShoulderPitch");
  EXPECT_NEAR(start, -72 * kDeg, 1e-6);
  sim.setTarget("RShoulderPitch", start + 0.5, 0.1);  // 0.1 * 8.26797 rad/s
  sim.advance(0.2);
  EXPECT_NEAR(sim.angles().at("RShoulderPitch"), start + 0.2 * 0.826797, 1e-6);
  sim.advance(1.0);
  EXPECT_NEAR(sim.angles().at("RShoulderPitch"), start + 0.5, 1e-9);
  sim.changeTarget("RShoulderRoll", -5.0, 1.0);  // far beyond the limit
  EXPECT_NEAR(sim.target("RShoulderRoll"), -1.32645, 1e-9);
  sim.advance(1.0);
  EXPECT_NEAR(sim.angles().at("RShoulderRoll"), -1.32645, 1e-9);
  EXPECT_THROW(sim.setTarget("LShoulderPitch", 0.0, 0.5), std::invalid_argument);
  EXPECT_THROW(sim.setTarget("RShoulderPitch", 0.0, 0.0), std::invalid_argument);
}

TEST(NaoArmSimulation, BumperPressesWhenTheFingertipReachesItWithEdges) {
  NaoArmSimulation sim(config(), 1);
  EXPECT_FALSE(sim.bumperPressed());
  sim.setTarget("RShoulderPitch", 24 * kDeg, 0.5);  // the grid cell (24, 12) presses it
  sim.setTarget("RShoulderRoll", 12 * kDeg, 0.5);
  sim.advance(2.0);
  EXPECT_TRUE(sim.bumperPressed());
  auto edges = sim.takeBumperEdges();
  ASSERT_FALSE(edges.empty());
  EXPECT_TRUE(edges.back().pressed);
  EXPECT_TRUE(sim.takeBumperEdges().empty());  // taken
  sim.setTarget("RShoulderPitch", 0.0, 0.5);
  sim.advance(1.0);
  EXPECT_FALSE(sim.bumperPressed());
  edges = sim.takeBumperEdges();
  ASSERT_FALSE(edges.empty());
  EXPECT_FALSE(edges.back().pressed);
}

TEST(NaoArmSimulation, CymbalIsLoudBodyQuietOtherwiseNoiseFloor) {
  NaoArmSimulation sim(config(), 1);
  sim.setTarget("RShoulderPitch", 0.0, 0.2);
  sim.setTarget("RShoulderRoll", -60 * kDeg, 0.2);
  sim.advance(1.5);
  EXPECT_LT(drainEnergy(sim), 100.0);  // moving through the air: noise floor
  sim.advance(1.0);
  drainEnergy(sim);
  sim.setTarget("RShoulderRoll", -76 * kDeg, 0.2);  // into the cymbal
  sim.advance(0.4);
  EXPECT_GT(drainEnergy(sim), 800.0);

  NaoArmSimulation sim2(config(), 1);
  sim2.setTarget("RShoulderPitch", 90 * kDeg, 0.2);  // down onto the floor
  sim2.setTarget("RShoulderRoll", 0.0, 0.2);
  double most = 0.0;
  for (int i = 0; i < 20; ++i) {
    sim2.advance(0.1);
    most = std::max(most, drainEnergy(sim2));
  }
  EXPECT_GT(most, 100.0);
  EXPECT_LT(most, 800.0);
}

TEST(NaoArmSimulation, SensorNoiseIsSeeded) {
  NaoArmSimulation a(config(true), 5), b(config(true), 5), c(config(true), 6);
  const double qa = a.measuredAngles().at("RShoulderPitch");
  EXPECT_EQ(qa, b.measuredAngles().at("RShoulderPitch"));
  EXPECT_NE(qa, c.measuredAngles().at("RShoulderPitch"));
  EXPECT_NEAR(qa, -72 * kDeg, 0.5 * kDeg);
  NaoArmSimulation d(config(false), 5);
  EXPECT_EQ(d.measuredAngles().at("RShoulderPitch"), d.angles().at("RShoulderPitch"));
}
