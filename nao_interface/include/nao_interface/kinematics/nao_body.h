/**
 * NaoBody: the seated Nao's kinematics from its URDF (nao_interface/urdf/nao_upper_body.urdf):
 * the pose, in the torso frame, of every link the simulator and the bridge need (hand,
 * fingertip, elbow, pink square, top camera, foot bumper, cymbal) for given joint angles.
 *
 * The URDF is parsed with urdfdom at start-up; each needed link gets a KinematicChain from the
 * torso (T = prod_j T_origin(j) R(axis_j, q_j), see kinematic_chain.h). A missing or malformed
 * file, a missing link or a missing joint is a std::runtime_error naming the file and the
 * element. Joint names and limits are the real robot's (shared/spec/NAO.md §1.2-1.4).
 */
#pragma once

#include <Eigen/Geometry>
#include <map>
#include <string>
#include <vector>

#include "nao_interface/kinematics/kinematic_chain.h"

namespace nao_interface {

/// Joint positions by name, in radians.
using JointAngles = std::map<std::string, double>;

class NaoBody {
 public:
  /// Link names the body resolves (all must be in the URDF).
  static const std::vector<std::string>& requiredLinks();
  /// Joint names the body needs (all must be in the URDF as movable joints).
  static const std::vector<std::string>& requiredJoints();

  /// Parses `urdfFile`. Throws std::runtime_error naming the file and the missing link or joint.
  static NaoBody fromUrdfFile(const std::string& urdfFile);
  /// Same, from URDF text; `source` names it in error messages.
  static NaoBody fromUrdfString(const std::string& urdf, const std::string& source = "<string>");

  /// Pose of `link` in the torso frame. Throws std::invalid_argument if the link is unknown or
  /// a joint of its chain has no value in `q`.
  Eigen::Isometry3d linkPose(const std::string& link, const JointAngles& q) const;
  /// Position of `link` in the torso frame, in metres.
  Eigen::Vector3d position(const std::string& link, const JointAngles& q) const {
    return linkPose(link, q).translation();
  }

  /// The movable joint `name` (origin, axis, limits). Throws std::invalid_argument if unknown.
  const KinematicChain::Joint& joint(const std::string& name) const;
  /// `value` clamped to the limits of joint `name`.
  double clamp(const std::string& name, double value) const;

  const std::string& source() const { return source_; }

 private:
  std::string source_;
  std::map<std::string, KinematicChain> chains_;         ///< torso to each required link
  std::map<std::string, KinematicChain::Joint> joints_;  ///< every movable joint of the chains
};

}  // namespace nao_interface
