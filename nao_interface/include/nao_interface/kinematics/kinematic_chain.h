/**
 * KinematicChain: forward kinematics over a joint chain parsed from a URDF with urdfdom.
 *
 * The chain runs from a base link to a tip link through the URDF's joints. Each joint
 * contributes its fixed origin transform, then (if movable) a rotation about its axis by the
 * joint angle (revolute) or a translation along it (prismatic):
 *   T(base, tip) = prod_j  T_origin(j) * R(axis_j, q_j).
 * Used for the Nao right arm: hand position in the torso frame (NAO.md §1.2).
 */
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace nao_interface {

class KinematicChain {
 public:
  struct Joint {
    std::string name;
    Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();  ///< in the parent link
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
    bool movable = false;
    bool prismatic = false;
    double lower = 0.0;  ///< limits of movable joints
    double upper = 0.0;
    double velocity = 0.0;  ///< velocity limit (rad/s or m/s), 0 if the URDF gives none
  };

  /// Parses `urdfFile` and extracts the chain from `baseLink` to `tipLink`. Throws
  /// std::runtime_error naming the file and the missing or malformed element.
  static KinematicChain fromUrdfFile(const std::string& urdfFile, const std::string& baseLink,
                                     const std::string& tipLink);
  /// Same, from URDF text; `source` names it in error messages.
  static KinematicChain fromUrdfString(const std::string& urdf, const std::string& baseLink,
                                       const std::string& tipLink,
                                       const std::string& source = "<string>");

  /// Names of the movable joints, base to tip: the order of `angles` below.
  std::vector<std::string> movableJointNames() const;
  /// The movable joint called `name`; throws std::invalid_argument if there is none.
  const Joint& joint(const std::string& name) const;

  /// Pose of the tip in the base frame for the given movable-joint positions (radians or
  /// metres). Throws std::invalid_argument if the count does not match.
  Eigen::Isometry3d tipPose(const std::vector<double>& angles) const;

 private:
  std::vector<Joint> joints_;  ///< base to tip, fixed joints included
};

}  // namespace nao_interface
