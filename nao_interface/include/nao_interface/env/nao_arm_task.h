/**
 * The Nao arm task of the TEXPLORE-VANIR paper (Hester & Stone, §5.2), shared by the
 * in-process environment (NaoArmEnvironment) and the ROS bridge (nao_arm_bridge), so both
 * present the agent the same features, actions and rewards.
 *
 * Actions (5): 0 RShoulderPitch +8°, 1 RShoulderPitch -8°, 2 RShoulderRoll +8°,
 * 3 RShoulderRoll -8°, 4 do nothing; targets are clamped to the URDF joint limits.
 * State (8 features): RShoulderPitch and RShoulderRoll (degrees), the hand position x, y, z
 * (mm, torso frame), the number of pink pixels in the camera image, the right foot bumper
 * (0/1) and the microphone energy (capped at 4000).
 * Rewards by task: explore 0 (declared range [0, 1]); pink = pink pixel count (at most 153,600, the
 * paper's 320 x 240 x 2-byte image); button = +200 while the bumper is pressed; mic = microphone
 * energy capped at 4000.
 */
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "nao_interface/kinematics/nao_body.h"
#include "rl_common/experience.h"

namespace nao_interface {

enum class NaoArmTask { kExplore, kPink, kButton, kMic };

namespace naoarm {
constexpr int kNumActions = 5;
constexpr int kNumFeatures = 8;
constexpr double kStepDeg = 8.0;
constexpr float kMicCap = 4000.0f;
constexpr float kButtonReward = 200.0f;
constexpr float kPinkMax = 153600.0f;  ///< the paper's image size (320 x 240 x 2 bytes)
}  // namespace naoarm

/// "explore", "pink", "button", "mic".
const std::vector<std::string>& naoArmTaskNames();
/// Parses a task name; throws std::invalid_argument listing the valid names.
NaoArmTask parseNaoArmTask(const std::string& name);
std::string toString(NaoArmTask task);

/// What the robot senses at one step.
struct NaoArmObservation {
  double shoulderPitch = 0.0;  ///< rad
  double shoulderRoll = 0.0;   ///< rad
  Eigen::Vector3d handMm = Eigen::Vector3d::Zero();
  double pinkPixels = 0.0;
  bool bumper = false;
  double micEnergy = 0.0;  ///< raw; capped in the state
};

/// The 8 state features of an observation.
rl_common::State toState(const NaoArmObservation& o);
/// The task's reward for an observation.
float taskReward(NaoArmTask task, const NaoArmObservation& o);
/// Declared range of each feature.
void naoArmFeatureRanges(std::vector<float>* min, std::vector<float>* max);
/// Declared reward range of a task.
void naoArmRewardRange(NaoArmTask task, float* min, float* max);

/// Shoulder targets (rad) after `action`, clamped to the joint limits of `body`. Throws
/// std::out_of_range for an action outside 0..4.
Eigen::Vector2d applyNaoArmAction(int action, const Eigen::Vector2d& pitchRoll,
                                  const NaoBody& body);
/// A readable name of an action, e.g. "RShoulderPitch +8".
std::string naoArmActionName(int action);

}  // namespace nao_interface
