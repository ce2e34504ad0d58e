// DriverSensorState: the bridge's view of the driver's topics (latched bumper edges,
// microphone maximum per step, staleness, malformed input).
#include "nao_interface/env/driver_sensor_state.h"

#include <gtest/gtest.h>

#include "nao_interface/sim/nao_arm_simulation.h"

using namespace nao_interface;

namespace {

NaoArmSimConfig config() {
  NaoArmSimConfig c;
  c.urdf = std::string(NAO_INTERFACE_URDF_DIR) + "/nao_upper_body.urdf";
  return c;
}

}  // namespace

TEST(DriverSensorState, WaitsUntilEverySourceIsFresh) {
  DriverSensorState s(seatedPosture(config()));
  EXPECT_NE(s.ready(10.0, 1.0).find("no joint states yet"), std::string::npos);
  s.onJointStates({"RShoulderPitch", "RShoulderRoll"}, {0.1, -0.2}, 10.0);
  s.onPinkCount(12, 10.0);
  EXPECT_NE(s.ready(10.2, 1.0).find("no audio yet"), std::string::npos);
  EXPECT_EQ(s.ready(10.2, 1.0, /*needAudio=*/false), "");
  s.onAudio({0, 2, 1, 4}, std::vector<std::int16_t>(8, 0), 10.1);
  EXPECT_EQ(s.ready(10.5, 1.0), "");
  EXPECT_NE(s.ready(11.5, 1.0).find("joint states stale"), std::string::npos);
}

TEST(DriverSensorState, ObservationFromDriverData) {
  const NaoBody body = NaoBody::fromUrdfFile(config().urdf);
  DriverSensorState s(seatedPosture(config()));
  s.onJointStates({"HeadYaw", "RShoulderPitch", "RShoulderRoll"}, {0.0, 0.0, 0.0}, 1.0);
  s.onPinkCount(321, 1.0);
  s.onBumper(true, true, 1.0);    // right foot pressed ...
  s.onBumper(false, false, 1.0);  // ... a left-foot event changes nothing
  // Front microphone (CHANNEL_FRONT_CENTER = 1) is the third channel of {0, 2, 1, 4}.
  s.onAudio({0, 2, 1, 4}, {9, 9, 1000, 9, 9, 9, -3000, 9}, 1.0);
  s.onAudio({0, 2, 1, 4}, {0, 0, 10, 0}, 1.1);
  NaoArmObservation o = s.observe(body);
  EXPECT_EQ(o.pinkPixels, 321);
  EXPECT_TRUE(o.bumper);
  EXPECT_DOUBLE_EQ(o.micEnergy, 2000.0);  // the loudest buffer of the step
  EXPECT_NEAR(o.handMm.x(), 219, 0.5);    // straight arm forward
  EXPECT_NEAR(o.handMm.y(), -109, 0.5);
  o = s.observe(body);
  EXPECT_DOUBLE_EQ(o.micEnergy, 0.0);  // a new window
  EXPECT_TRUE(o.bumper);               // latched until released
  s.onBumper(true, false, 2.0);
  EXPECT_FALSE(s.observe(body).bumper);
}

TEST(DriverSensorState, MalformedMessagesThrow) {
  DriverSensorState s(seatedPosture(config()));
  EXPECT_THROW(s.onJointStates({"RShoulderPitch"}, {0.1, 0.2}, 0.0), std::invalid_argument);
  EXPECT_THROW(s.onJointStates({"HeadYaw"}, {0.1}, 0.0), std::invalid_argument);
  EXPECT_THROW(s.onJointStates({"RShoulderPitch", "RShoulderRoll"}, {NAN, 0.0}, 0.0),
               std::invalid_argument);
  EXPECT_THROW(s.onAudio({}, {1, 2}, 0.0), std::invalid_argument);
  EXPECT_THROW(s.onAudio({0, 1}, {1, 2, 3}, 0.0), std::invalid_argument);
  EXPECT_NE(s.ready(0.0, 1.0).find("no joint states"), std::string::npos);  // nothing taken
}
