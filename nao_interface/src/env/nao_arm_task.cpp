#include "nao_interface/env/nao_arm_task.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace nao_interface {

namespace {
constexpr double kDeg = M_PI / 180.0;
}

const std::vector<std::string>& naoArmTaskNames() {
  static const std::vector<std::string> names = {"explore", "pink", "button", "mic"};
  return names;
}

NaoArmTask parseNaoArmTask(const std::string& name) {
  if (name == "explore") return NaoArmTask::kExplore;
  if (name == "pink") return NaoArmTask::kPink;
  if (name == "button") return NaoArmTask::kButton;
  if (name == "mic") return NaoArmTask::kMic;
  throw std::invalid_argument("parseNaoArmTask(): unknown task '" + name +
                              "'; valid tasks: explore, pink, button, mic");
}

std::string toString(NaoArmTask task) {
  switch (task) {
    case NaoArmTask::kExplore:
      return "explore";
    case NaoArmTask::kPink:
      return "pink";
    case NaoArmTask::kButton:
      return "button";
    case NaoArmTask::kMic:
      return "mic";
  }
  return "explore";
}

rl_common::State toState(const NaoArmObservation& o) {
  rl_common::State s = {static_cast<float>(o.shoulderPitch / kDeg),
                        static_cast<float>(o.shoulderRoll / kDeg),
                        static_cast<float>(o.handMm.x()),
                        static_cast<float>(o.handMm.y()),
                        static_cast<float>(o.handMm.z()),
                        static_cast<float>(o.pinkPixels),
                        o.bumper ? 1.0f : 0.0f,
                        static_cast<float>(o.micEnergy)};
  // Sensors may read a little beyond the declared ranges: clamp, so states stay inside them.
  std::vector<float> min, max;
  naoArmFeatureRanges(&min, &max);
  for (std::size_t i = 0; i < s.size(); ++i) s[i] = std::clamp(s[i], min[i], max[i]);
  return s;
}

float taskReward(NaoArmTask task, const NaoArmObservation& o) {
  switch (task) {
    case NaoArmTask::kExplore:
      return 0.0f;
    case NaoArmTask::kPink:
      return static_cast<float>(std::clamp(o.pinkPixels, 0.0, double{naoarm::kPinkMax}));
    case NaoArmTask::kButton:
      return o.bumper ? naoarm::kButtonReward : 0.0f;
    case NaoArmTask::kMic:
      return static_cast<float>(std::clamp(o.micEnergy, 0.0, double{naoarm::kMicCap}));
  }
  return 0.0f;
}

void naoArmFeatureRanges(std::vector<float>* min, std::vector<float>* max) {
  // Shoulder limits (NAO.md §1.2) with 1.5° for sensor noise; the hand's reach around the
  // shoulder at (0, -98, 100) mm.
  *min = {-121.0f, -77.5f, -250.0f, -350.0f, -150.0f, 0.0f, 0.0f, 0.0f};
  *max = {121.0f, 19.5f, 250.0f, 150.0f, 350.0f, naoarm::kPinkMax, 1.0f, naoarm::kMicCap};
}

void naoArmRewardRange(NaoArmTask task, float* min, float* max) {
  *min = 0.0f;
  switch (task) {
    case NaoArmTask::kExplore:
      *max = 1.0f;  // no reward at all; a nominal range, as agents divide by its width
      break;
    case NaoArmTask::kPink:
      *max = naoarm::kPinkMax;
      break;
    case NaoArmTask::kButton:
      *max = naoarm::kButtonReward;
      break;
    case NaoArmTask::kMic:
      *max = naoarm::kMicCap;
      break;
  }
}

Eigen::Vector2d applyNaoArmAction(int action, const Eigen::Vector2d& pitchRoll,
                                  const NaoBody& body) {
  if (action < 0 || action >= naoarm::kNumActions) {
    throw std::out_of_range("applyNaoArmAction(): action " + std::to_string(action) +
                            " outside 0.." + std::to_string(naoarm::kNumActions - 1));
  }
  Eigen::Vector2d t = pitchRoll;
  const double step = naoarm::kStepDeg * kDeg;
  if (action == 0) t[0] += step;
  if (action == 1) t[0] -= step;
  if (action == 2) t[1] += step;
  if (action == 3) t[1] -= step;
  t[0] = body.clamp("RShoulderPitch", t[0]);
  t[1] = body.clamp("RShoulderRoll", t[1]);
  return t;
}

std::string naoArmActionName(int action) {
  static const char* names[] = {"RShoulderPitch +8", "RShoulderPitch -8", "RShoulderRoll +8",
                                "RShoulderRoll -8", "nothing"};
  if (action < 0 || action >= naoarm::kNumActions) return "invalid";
  return names[action];
}

}  // namespace nao_interface
