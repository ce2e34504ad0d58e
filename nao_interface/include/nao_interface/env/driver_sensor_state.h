/**
 * DriverSensorState: what the bridge knows of the robot from the Nao driver's topics, kept
 * ROS-free so it is tested without a master. It turns driver data into the paper's
 * observation (nao_arm_task.h), the way a bridge to a real Nao must:
 *   - joint angles from /joint_states (missing non-shoulder joints keep the seated posture),
 *     the hand position by forward kinematics of those angles (NaoBody);
 *   - the pink pixel count of the latest camera image (counted by the caller with
 *     PinkDetector);
 *   - the foot bumper latched from its press/release events (the driver sends edges only);
 *   - the microphone energy: the highest energy (audio_energy.h) of the audio buffers
 *     received since the last observation, taken from the front microphone.
 * Each source carries the time it was last heard from; ready() says whether all are fresh,
 * and what is missing or stale, so the bridge waits rather than inventing state.
 */
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "nao_interface/env/nao_arm_task.h"
#include "nao_interface/kinematics/nao_body.h"

namespace nao_interface {

class DriverSensorState {
 public:
  /// `posture` gives the joints a joint-state message may lack (the seated posture).
  explicit DriverSensorState(JointAngles posture);

  /// A joint-state message: names and positions (radians) at time `t` (seconds). Throws
  /// std::invalid_argument if the sizes differ, or a position is not finite, or the shoulder
  /// joints are missing; the caller logs and drops the message.
  void onJointStates(const std::vector<std::string>& names, const std::vector<double>& positions,
                     double t);
  /// The pink pixel count of a camera image received at `t`.
  void onPinkCount(int count, double t);
  /// A bumper event (right foot only; other bumpers are ignored).
  void onBumper(bool rightFoot, bool pressed, double t);
  /// An audio buffer: interleaved int16 samples with `channelMap` (AudioBuffer constants).
  /// Uses the front microphone (CHANNEL_FRONT_CENTER = 1) if present, else channel 0.
  /// Throws std::invalid_argument for a malformed buffer.
  void onAudio(const std::vector<std::uint8_t>& channelMap, const std::vector<std::int16_t>& data,
               double t);

  /// Empty if every source was heard from within `maxAge` seconds of `now` (audio counts
  /// only if `needAudio`), else a description of what is missing or stale.
  std::string ready(double now, double maxAge, bool needAudio = true) const;

  /// The observation now; resets the microphone maximum (a new listening window starts).
  NaoArmObservation observe(const NaoBody& body);
  /// The latest joint angles (posture joints filled in).
  const JointAngles& angles() const { return angles_; }
  bool bumperPressed() const { return bumper_; }
  /// The energy of the latest audio buffer (0 before the first).
  double lastAudioEnergy() const { return lastEnergy_; }

 private:
  JointAngles angles_;
  double jointsTime_ = -1.0, pinkTime_ = -1.0, audioTime_ = -1.0;
  int pink_ = 0;
  bool bumper_ = false;
  double micMax_ = 0.0;
  double lastEnergy_ = 0.0;
};

}  // namespace nao_interface
