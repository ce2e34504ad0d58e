#include "nao_interface/env/driver_sensor_state.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "nao_interface/sensors/microphone_model.h"

namespace nao_interface {

namespace {
constexpr std::uint8_t kFrontCenter = 1;  // AudioBuffer::CHANNEL_FRONT_CENTER
}

DriverSensorState::DriverSensorState(JointAngles posture) : angles_(std::move(posture)) {}

void DriverSensorState::onJointStates(const std::vector<std::string>& names,
                                      const std::vector<double>& positions, double t) {
  if (names.size() != positions.size()) {
    throw std::invalid_argument(
        "DriverSensorState::onJointStates(): " + std::to_string(names.size()) + " names but " +
        std::to_string(positions.size()) + " positions");
  }
  bool pitch = false, roll = false;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (!std::isfinite(positions[i])) {
      throw std::invalid_argument("DriverSensorState::onJointStates(): position of '" + names[i] +
                                  "' is not finite");
    }
    pitch = pitch || names[i] == "RShoulderPitch";
    roll = roll || names[i] == "RShoulderRoll";
  }
  if (!pitch || !roll) {
    throw std::invalid_argument(
        "DriverSensorState::onJointStates(): no RShoulderPitch or RShoulderRoll position");
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (angles_.count(names[i]) > 0) angles_[names[i]] = positions[i];
  }
  jointsTime_ = t;
}

void DriverSensorState::onPinkCount(int count, double t) {
  pink_ = std::max(0, count);
  pinkTime_ = t;
}

void DriverSensorState::onBumper(bool rightFoot, bool pressed, double /*t*/) {
  if (rightFoot) bumper_ = pressed;
}

void DriverSensorState::onAudio(const std::vector<std::uint8_t>& channelMap,
                                const std::vector<std::int16_t>& data, double t) {
  if (channelMap.empty()) {
    throw std::invalid_argument("DriverSensorState::onAudio(): empty channel map");
  }
  const auto front = std::find(channelMap.begin(), channelMap.end(), kFrontCenter);
  const int channel = front == channelMap.end() ? 0 : static_cast<int>(front - channelMap.begin());
  lastEnergy_ = audioEnergy(data, static_cast<int>(channelMap.size()), channel);
  micMax_ = std::max(micMax_, lastEnergy_);
  audioTime_ = t;
}

std::string DriverSensorState::ready(double now, double maxAge, bool needAudio) const {
  std::string problems;
  auto check = [&](const char* what, double t) {
    if (t < 0) {
      problems += std::string(problems.empty() ? "" : "; ") + "no " + what + " yet";
    } else if (now - t > maxAge) {
      problems += std::string(problems.empty() ? "" : "; ") + what + " stale (" +
                  std::to_string(now - t) + " s old)";
    }
  };
  check("joint states", jointsTime_);
  check("camera image", pinkTime_);
  if (needAudio) check("audio", audioTime_);
  return problems;
}

NaoArmObservation DriverSensorState::observe(const NaoBody& body) {
  NaoArmObservation o;
  o.shoulderPitch = angles_.at("RShoulderPitch");
  o.shoulderRoll = angles_.at("RShoulderRoll");
  o.handMm = body.position("r_gripper", angles_) * 1000.0;
  o.pinkPixels = pink_;
  o.bumper = bumper_;
  o.micEnergy = micMax_;
  micMax_ = 0.0;
  return o;
}

}  // namespace nao_interface
