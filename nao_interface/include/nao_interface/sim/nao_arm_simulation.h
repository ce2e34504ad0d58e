/**
 * NaoArmSimulation: the seated Nao of the paper's robot experiment (Hester & Stone,
 * TEXPLORE-VANIR, §5.2, Fig. 9) in simulated time: joint servos, the top camera, the right
 * foot bumper and the microphones, with a cymbal to the right and a pink square on the hand.
 *
 * Joints follow position commands as ALMotion.setAngles/changeAngles do: each moves toward
 * its target at `speed` times its URDF velocity limit and stops at its URDF limits (targets
 * are clamped). The arm joints other than the shoulders, the head and the legs hold the
 * configured posture (legs stretched forward, see the URDF). advance(dt) integrates in 5 ms
 * substeps and detects contacts along the way:
 *   - bumper: pressed while the fingertip is within `bumperRadius` of the foot bumper; every
 *     change is kept as an edge event (the driver publishes edges only);
 *   - cymbal: the forearm or hand entering the cymbal's disc (thickness 2 cm) hits it, with a
 *     strength growing with the arm's speed; a knock on the body (torso box, head sphere, leg)
 *     or the floor makes a quieter sound (MicrophoneModel);
 *   the arm passes through obstacles (no collision response), only their sounds are modelled.
 * Measured joint angles carry Gaussian sensor noise when stochastic. Everything random comes
 * from one seed (rl_common::Random streams derived from it).
 */
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "nao_interface/camera/pink_detector.h"
#include "nao_interface/camera/scene_renderer.h"
#include "nao_interface/kinematics/nao_body.h"
#include "nao_interface/sensors/microphone_model.h"
#include "rl_common/option_parser.h"
#include "rl_common/random.h"

namespace nao_interface {

/// The URDF shipped with the package (source tree, else install space).
std::string defaultUrdfFile();

struct NaoArmSimConfig {
  std::string urdf = defaultUrdfFile();
  double headYaw = -0.5;           ///< rad: head turned to the right ...
  double headPitch = 0.45;         ///< rad: ... and down, so the hand can come into view
  double startPitch = -1.2566371;  ///< RShoulderPitch at start (rad, -72°: hand raised)
  double startRoll = -0.2094395;   ///< RShoulderRoll at start (rad, -12°)
  double speed = 0.1;              ///< default fraction of the velocity limit for commands
  double squareSize = 0.06;        ///< side of the pink square (m)
  double bumperRadius = 0.035;     ///< fingertip contact radius of the foot bumper (m)
  double cymbalRadius = 0.12;      ///< m
  double jointNoise = 0.1;         ///< std of measured joint angles (degrees), if stochastic
  double pixelNoise = 3.0;         ///< std of camera pixel noise, if stochastic
  bool stochastic = true;
  MicrophoneConfig microphone;
};

/// The start posture: every joint of the body (legs stretched forward, arm straight, head and
/// shoulders as configured), unclamped.
JointAngles seatedPosture(const NaoArmSimConfig& config);

/// Declares the simulator's options (--urdf, --head-yaw, ...) on `parser`.
void addSimOptions(rl_common::OptionParser& parser, NaoArmSimConfig* config);

struct BumperEdge {
  double time = 0.0;
  bool pressed = false;
};

class NaoArmSimulation {
 public:
  /// Names of the arm joints driven by the shoulders and held in posture, in URDF order.
  static const std::vector<std::string>& armJoints();

  /// Loads the URDF (throws std::runtime_error naming file and element) and puts the robot in
  /// its start posture.
  NaoArmSimulation(const NaoArmSimConfig& config, std::uint64_t seed);

  /// Sets an absolute target (ALMotion.setAngles); `speed` is a fraction of the velocity
  /// limit in (0, 1]. Throws std::invalid_argument for an unknown joint or bad speed.
  void setTarget(const std::string& joint, double angle, double speed);
  /// Changes a target by `delta` relative to the current target (ALMotion.changeAngles).
  void changeTarget(const std::string& joint, double delta, double speed);
  /// Advances the simulated time by `dt` seconds.
  void advance(double dt);

  double time() const { return time_; }
  /// True joint positions (every joint of the body, radians).
  const JointAngles& angles() const { return angles_; }
  /// Joint positions as the joint sensors report them (with noise if stochastic).
  JointAngles measuredAngles();
  double target(const std::string& joint) const;

  bool bumperPressed() const { return bumperPressed_; }
  /// Bumper edges since the last call.
  std::vector<BumperEdge> takeBumperEdges();

  /// The next audio buffer if the simulated time has passed its end, else nothing.
  std::optional<std::vector<std::int16_t>> nextAudioBuffer();
  /// Start time of the next audio buffer.
  double audioTime() const { return audioTime_; }

  /// The top camera's view now (8-bit BGR).
  cv::Mat renderCamera();
  /// Pink pixels in a fresh camera image.
  int countPink() { return detector_.count(renderCamera()); }
  /// The scene's geometry now (torso frame).
  SceneGeometry scene() const;
  /// Hand (r_gripper) position in the torso frame, millimetres.
  Eigen::Vector3d handMm() const { return body_.position("r_gripper", angles_) * 1000.0; }

  const NaoBody& body() const { return body_; }
  const NaoArmSimConfig& config() const { return config_; }
  const PinholeCamera& camera() const { return renderer_.options().camera; }

 private:
  struct Contacts {
    bool bumper = false;
    bool cymbal = false;
    bool body = false;
  };
  Contacts contacts() const;

  NaoArmSimConfig config_;
  NaoBody body_;
  SceneRenderer renderer_;
  PinkDetector detector_;
  MicrophoneModel microphone_;
  rl_common::Random sensorRandom_;
  rl_common::Random cameraRandom_;
  JointAngles angles_;
  std::map<std::string, double> targets_;
  std::map<std::string, double> speeds_;
  double time_ = 0.0;
  double audioTime_ = 0.0;
  bool bumperPressed_ = false;
  Contacts lastContacts_;
  std::vector<BumperEdge> edges_;
};

}  // namespace nao_interface
