#include "nao_interface/kinematics/nao_body.h"

#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace nao_interface {

const std::vector<std::string>& NaoBody::requiredLinks() {
  static const std::vector<std::string> links = {"RShoulder",
                                                 "RElbow",
                                                 "r_wrist",
                                                 "r_gripper",
                                                 "r_fingertip",
                                                 "pink_square",
                                                 "CameraTop_optical_frame",
                                                 "RFootBumper",
                                                 "r_ankle",
                                                 "cymbal"};
  return links;
}

const std::vector<std::string>& NaoBody::requiredJoints() {
  static const std::vector<std::string> joints = {
      "RShoulderPitch", "RShoulderRoll", "RElbowYaw",    "RElbowRoll", "RWristYaw",
      "HeadYaw",        "HeadPitch",     "RHipYawPitch", "RHipRoll",   "RHipPitch",
      "RKneePitch",     "RAnklePitch",   "RAnkleRoll"};
  return joints;
}

NaoBody NaoBody::fromUrdfFile(const std::string& urdfFile) {
  std::ifstream in(urdfFile);
  if (!in) {
    throw std::runtime_error("NaoBody::fromUrdfFile(): cannot read URDF file '" + urdfFile + "'");
  }
  std::stringstream text;
  text << in.rdbuf();
  return fromUrdfString(text.str(), urdfFile);
}

NaoBody NaoBody::fromUrdfString(const std::string& urdf, const std::string& source) {
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(urdf);
  if (!model) {
    throw std::runtime_error("NaoBody::fromUrdfString(): malformed URDF in '" + source + "'");
  }
  for (const std::string& name : requiredJoints()) {
    const urdf::JointConstSharedPtr j = model->getJoint(name);
    if (!j) {
      throw std::runtime_error("NaoBody::fromUrdfString(): URDF '" + source + "' has no joint '" +
                               name + "'");
    }
    if (j->type != urdf::Joint::REVOLUTE) {
      throw std::runtime_error("NaoBody::fromUrdfString(): joint '" + name + "' in URDF '" +
                               source + "' is not revolute");
    }
  }
  NaoBody body;
  body.source_ = source;
  for (const std::string& link : requiredLinks()) {
    if (!model->getLink(link)) {
      throw std::runtime_error("NaoBody::fromUrdfString(): URDF '" + source + "' has no link '" +
                               link + "'");
    }
    KinematicChain chain = KinematicChain::fromUrdfString(urdf, "torso", link, source);
    for (const std::string& name : chain.movableJointNames()) {
      body.joints_.emplace(name, chain.joint(name));
    }
    body.chains_.emplace(link, std::move(chain));
  }
  return body;
}

Eigen::Isometry3d NaoBody::linkPose(const std::string& link, const JointAngles& q) const {
  const auto chain = chains_.find(link);
  if (chain == chains_.end()) {
    throw std::invalid_argument("NaoBody::linkPose(): unknown link '" + link + "'");
  }
  std::vector<double> angles;
  for (const std::string& name : chain->second.movableJointNames()) {
    const auto v = q.find(name);
    if (v == q.end()) {
      throw std::invalid_argument("NaoBody::linkPose(): no value for joint '" + name +
                                  "' (needed for link '" + link + "')");
    }
    angles.push_back(v->second);
  }
  return chain->second.tipPose(angles);
}

const KinematicChain::Joint& NaoBody::joint(const std::string& name) const {
  const auto j = joints_.find(name);
  if (j == joints_.end()) {
    throw std::invalid_argument("NaoBody::joint(): unknown joint '" + name + "'");
  }
  return j->second;
}

double NaoBody::clamp(const std::string& name, double value) const {
  const KinematicChain::Joint& j = joint(name);
  return std::min(j.upper, std::max(j.lower, value));
}

}  // namespace nao_interface
