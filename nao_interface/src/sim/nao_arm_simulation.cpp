#include "nao_interface/sim/nao_arm_simulation.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace nao_interface {

namespace {

constexpr double kSubstep = 0.005;  // s
constexpr double kDeg = M_PI / 180.0;

/// Seated posture of the joints that do not move (legs stretched forward, arm straight).
const JointAngles& fixedPosture() {
  static const JointAngles p = {
      {"RElbowYaw", 0.0},    {"RElbowRoll", 0.0349066}, {"RWristYaw", 0.0},
      {"RHipYawPitch", 0.0}, {"RHipRoll", 0.0},         {"RHipPitch", -1.5},
      {"RKneePitch", 0.0},   {"RAnklePitch", 0.0},      {"RAnkleRoll", 0.0}};
  return p;
}

bool insideBox(const Eigen::Vector3d& p, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all();
}

double segmentDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                       const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / std::max(1e-12, ab.squaredNorm()), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

}  // namespace

JointAngles seatedPosture(const NaoArmSimConfig& config) {
  JointAngles q = fixedPosture();
  q["RShoulderPitch"] = config.startPitch;
  q["RShoulderRoll"] = config.startRoll;
  q["HeadYaw"] = config.headYaw;
  q["HeadPitch"] = config.headPitch;
  return q;
}

std::string defaultUrdfFile() {
  for (const char* path : {NAO_INTERFACE_SOURCE_URDF, NAO_INTERFACE_INSTALL_URDF}) {
    if (std::ifstream(path).good()) return path;
  }
  return NAO_INTERFACE_SOURCE_URDF;
}

void addSimOptions(rl_common::OptionParser& parser, NaoArmSimConfig* c) {
  parser.value("urdf", &c->urdf, "URDF of the seated Nao");
  parser.value("head-yaw", &c->headYaw, "HeadYaw held during the experiment (rad)",
               rl_common::inRange(-2.08567, 2.08567));
  parser.value("head-pitch", &c->headPitch, "HeadPitch held during the experiment (rad)",
               rl_common::inRange(-0.671952, 0.514872));
  parser.value("start-pitch", &c->startPitch, "RShoulderPitch at start (rad)",
               rl_common::inRange(-2.08567, 2.08567));
  parser.value("start-roll", &c->startRoll, "RShoulderRoll at start (rad)",
               rl_common::inRange(-1.32645, 0.314159));
  parser.value("joint-speed", &c->speed,
               "default fraction of the joint velocity limit for commands",
               rl_common::inRange(0.001, 1.0));
  parser.value("bumper-radius", &c->bumperRadius, "fingertip contact radius of the bumper (m)",
               rl_common::greaterThan(0.0));
  parser.value("joint-noise", &c->jointNoise, "std of measured joint angles (degrees)",
               rl_common::atLeast(0.0));
  parser.value("pixel-noise", &c->pixelNoise, "std of camera pixel noise", rl_common::atLeast(0.0));
  parser.flag("stochastic", &c->stochastic, true, "sensor noise (the default)");
  parser.flag("deterministic", &c->stochastic, false, "no sensor noise");
}

const std::vector<std::string>& NaoArmSimulation::armJoints() {
  static const std::vector<std::string> j = {"RShoulderPitch", "RShoulderRoll", "RElbowYaw",
                                             "RElbowRoll", "RWristYaw"};
  return j;
}

NaoArmSimulation::NaoArmSimulation(const NaoArmSimConfig& config, std::uint64_t seed)
    : config_(config),
      body_(NaoBody::fromUrdfFile(config.urdf)),
      renderer_([&config] {
        RenderOptions o;
        o.pixelNoise = config.stochastic ? config.pixelNoise : 0.0;
        return o;
      }()),
      microphone_(config.microphone, rl_common::Random::deriveSeed(seed, "microphone")),
      sensorRandom_(rl_common::Random::deriveSeed(seed, "joint_sensors")),
      cameraRandom_(rl_common::Random::deriveSeed(seed, "camera")) {
  if (!(config.speed > 0.0 && config.speed <= 1.0)) {
    throw std::invalid_argument("NaoArmSimulation::NaoArmSimulation(): speed must be in (0, 1]");
  }
  angles_ = seatedPosture(config);
  for (auto& [name, value] : angles_) {
    value = body_.clamp(name, value);
    targets_[name] = value;
    speeds_[name] = config.speed;
  }
  lastContacts_ = contacts();
  bumperPressed_ = lastContacts_.bumper;
}

void NaoArmSimulation::setTarget(const std::string& joint, double angle, double speed) {
  if (targets_.count(joint) == 0) {
    throw std::invalid_argument("NaoArmSimulation::setTarget(): unknown joint '" + joint + "'");
  }
  if (!(speed > 0.0 && speed <= 1.0) || !std::isfinite(angle)) {
    throw std::invalid_argument("NaoArmSimulation::setTarget(): bad angle or speed for '" + joint +
                                "' (speed must be in (0, 1])");
  }
  targets_[joint] = body_.clamp(joint, angle);
  speeds_[joint] = speed;
}

void NaoArmSimulation::changeTarget(const std::string& joint, double delta, double speed) {
  setTarget(joint, target(joint) + delta, speed);
}

double NaoArmSimulation::target(const std::string& joint) const {
  const auto t = targets_.find(joint);
  if (t == targets_.end()) {
    throw std::invalid_argument("NaoArmSimulation::target(): unknown joint '" + joint + "'");
  }
  return t->second;
}

NaoArmSimulation::Contacts NaoArmSimulation::contacts() const {
  Contacts c;
  const Eigen::Vector3d tip = body_.position("r_fingertip", angles_);
  const Eigen::Vector3d bumper = body_.position("RFootBumper", angles_);
  c.bumper = (tip - bumper).norm() < config_.bumperRadius;

  // Points along the forearm and hand, every centimetre or so.
  const Eigen::Vector3d chain[] = {body_.position("RElbow", angles_),
                                   body_.position("r_wrist", angles_),
                                   body_.position("r_gripper", angles_), tip};
  std::vector<Eigen::Vector3d> pts;
  for (int s = 0; s < 3; ++s) {
    const int n = std::max(1, static_cast<int>((chain[s + 1] - chain[s]).norm() / 0.01));
    for (int i = 0; i < n; ++i) pts.push_back(chain[s] + (chain[s + 1] - chain[s]) * i / n);
  }
  pts.push_back(tip);

  const Eigen::Isometry3d cymbalInv = body_.linkPose("cymbal", angles_).inverse();
  const Eigen::Vector3d hip(0.0, -0.05, -0.085);
  const Eigen::Vector3d ankle = body_.position("r_ankle", angles_);
  const double floorZ = renderer_.options().floorZ;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Eigen::Vector3d& p = pts[i];
    const Eigen::Vector3d q = cymbalInv * p;
    if (std::abs(q.y()) < 0.01 && std::hypot(q.x(), q.z()) < config_.cymbalRadius) c.cymbal = true;
    // The wrist and beyond can knock on the torso, the head, the leg or the floor.
    if (i + 1 < pts.size() / 2) continue;
    if (insideBox(p, {-0.055, -0.07, -0.09}, {0.06, 0.07, 0.12}) ||
        (p - Eigen::Vector3d(0, 0, 0.185)).norm() < 0.065 ||
        segmentDistance(p, hip, ankle) < 0.04 || p.z() < floorZ + 0.005) {
      c.body = true;
    }
  }
  return c;
}

void NaoArmSimulation::advance(double dt) {
  if (!(dt >= 0.0) || !std::isfinite(dt)) {
    throw std::invalid_argument("NaoArmSimulation::advance(): dt must be finite and >= 0");
  }
  double left = dt;
  while (left > 1e-12) {
    const double h = std::min(kSubstep, left);
    left -= h;
    const Eigen::Vector3d tipBefore = body_.position("r_fingertip", angles_);
    for (auto& [name, q] : angles_) {
      const double maxStep = speeds_[name] * body_.joint(name).velocity * h;
      const double err = targets_[name] - q;
      q += std::clamp(err, -maxStep, maxStep);
    }
    time_ += h;
    const double tipSpeed = (body_.position("r_fingertip", angles_) - tipBefore).norm() / h;
    const double strength = std::min(1.0, tipSpeed / 0.2);
    const Contacts now = contacts();
    if (now.cymbal && !lastContacts_.cymbal) microphone_.cymbalHit(time_, strength);
    if (now.body && !lastContacts_.body) microphone_.knock(time_, strength);
    if (now.bumper != bumperPressed_) {
      bumperPressed_ = now.bumper;
      edges_.push_back({time_, bumperPressed_});
    }
    lastContacts_ = now;
  }
}

JointAngles NaoArmSimulation::measuredAngles() {
  JointAngles m = angles_;
  if (config_.stochastic && config_.jointNoise > 0.0) {
    for (auto& [name, q] : m) q += sensorRandom_.normal(0.0, config_.jointNoise * kDeg);
  }
  return m;
}

std::vector<BumperEdge> NaoArmSimulation::takeBumperEdges() {
  std::vector<BumperEdge> out;
  out.swap(edges_);
  return out;
}

std::optional<std::vector<std::int16_t>> NaoArmSimulation::nextAudioBuffer() {
  const double d = microphone_.bufferDuration();
  if (audioTime_ + d > time_ + 1e-9) return std::nullopt;
  std::vector<std::int16_t> b = microphone_.buffer(audioTime_);
  audioTime_ += d;
  return b;
}

SceneGeometry NaoArmSimulation::scene() const {
  SceneGeometry s;
  s.camera = body_.linkPose("CameraTop_optical_frame", angles_);
  s.arm = {body_.position("RShoulder", angles_), body_.position("RElbow", angles_),
           body_.position("r_wrist", angles_), body_.position("r_gripper", angles_)};
  s.pinkSquare = body_.linkPose("pink_square", angles_);
  s.squareSize = config_.squareSize;
  s.hip = Eigen::Vector3d(0.0, -0.05, -0.085);
  s.ankle = body_.position("r_ankle", angles_);
  s.bumper = body_.position("RFootBumper", angles_);
  s.cymbal = body_.linkPose("cymbal", angles_);
  s.cymbalRadius = config_.cymbalRadius;
  return s;
}

cv::Mat NaoArmSimulation::renderCamera() {
  return renderer_.render(scene(), config_.stochastic ? &cameraRandom_ : nullptr);
}

}  // namespace nao_interface
