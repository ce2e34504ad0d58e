#include "nao_interface/kinematics/kinematic_chain.h"

#include <urdf_parser/urdf_parser.h>
#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace nao_interface {

namespace {

Eigen::Isometry3d toEigen(const urdf::Pose& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(p.position.x, p.position.y, p.position.z);
  t.linear() =
      Eigen::Quaterniond(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z).toRotationMatrix();
  return t;
}

}  // namespace

KinematicChain KinematicChain::fromUrdfFile(const std::string& urdfFile,
                                            const std::string& baseLink,
                                            const std::string& tipLink) {
  std::ifstream in(urdfFile);
  if (!in) {
    throw std::runtime_error("KinematicChain::fromUrdfFile(): cannot read URDF file '" + urdfFile +
                             "'");
  }
  std::stringstream text;
  text << in.rdbuf();
  return fromUrdfString(text.str(), baseLink, tipLink, urdfFile);
}

KinematicChain KinematicChain::fromUrdfString(const std::string& urdf, const std::string& baseLink,
                                              const std::string& tipLink,
                                              const std::string& source) {
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(urdf);
  if (!model) {
    throw std::runtime_error("KinematicChain::fromUrdfString(): malformed URDF in '" + source +
                             "'");
  }
  for (const std::string& link : {baseLink, tipLink}) {
    if (!model->getLink(link)) {
      throw std::runtime_error("KinematicChain::fromUrdfString(): URDF '" + source +
                               "' has no link '" + link + "'");
    }
  }
  KinematicChain chain;
  urdf::LinkConstSharedPtr link = model->getLink(tipLink);
  while (link->name != baseLink) {
    const urdf::JointSharedPtr j = link->parent_joint;
    if (!j) {
      throw std::runtime_error("KinematicChain::fromUrdfString(): in URDF '" + source +
                               "', link '" + tipLink + "' does not descend from '" + baseLink +
                               "'");
    }
    Joint joint;
    joint.name = j->name;
    joint.origin = toEigen(j->parent_to_joint_origin_transform);
    joint.axis = Eigen::Vector3d(j->axis.x, j->axis.y, j->axis.z);
    joint.movable = j->type == urdf::Joint::REVOLUTE || j->type == urdf::Joint::CONTINUOUS ||
                    j->type == urdf::Joint::PRISMATIC;
    joint.prismatic = j->type == urdf::Joint::PRISMATIC;
    if (joint.movable && joint.axis.norm() == 0.0) {
      throw std::runtime_error("KinematicChain::fromUrdfString(): joint '" + j->name +
                               "' in URDF '" + source + "' has a zero axis");
    }
    if (joint.movable) joint.axis.normalize();
    if (j->limits && j->type != urdf::Joint::CONTINUOUS) {
      joint.lower = j->limits->lower;
      joint.upper = j->limits->upper;
    } else if (joint.movable) {
      joint.lower = -M_PI;
      joint.upper = M_PI;
    }
    if (j->limits) joint.velocity = j->limits->velocity;
    chain.joints_.push_back(joint);
    link = model->getLink(j->parent_link_name);
  }
  std::reverse(chain.joints_.begin(), chain.joints_.end());
  return chain;
}

std::vector<std::string> KinematicChain::movableJointNames() const {
  std::vector<std::string> names;
  for (const Joint& j : joints_) {
    if (j.movable) names.push_back(j.name);
  }
  return names;
}

const KinematicChain::Joint& KinematicChain::joint(const std::string& name) const {
  for (const Joint& j : joints_) {
    if (j.movable && j.name == name) return j;
  }
  throw std::invalid_argument("KinematicChain::joint(): no movable joint '" + name +
                              "' in the chain");
}

Eigen::Isometry3d KinematicChain::tipPose(const std::vector<double>& angles) const {
  const std::size_t movable = movableJointNames().size();
  if (angles.size() != movable) {
    throw std::invalid_argument("KinematicChain::tipPose(): expected " + std::to_string(movable) +
                                " joint positions, got " + std::to_string(angles.size()));
  }
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  std::size_t i = 0;
  for (const Joint& j : joints_) {
    t = t * j.origin;
    if (!j.movable) continue;
    const double q = angles[i++];
    if (j.prismatic) {
      t = t * Eigen::Translation3d(q * j.axis);
    } else {
      t = t * Eigen::AngleAxisd(q, j.axis);
    }
  }
  return t;
}

}  // namespace nao_interface
