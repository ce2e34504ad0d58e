#include "nao_interface/env/nao_arm_environment.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace nao_interface {

NaoArmEnvironment::NaoArmEnvironment(NaoArmSimConfig config, NaoArmTask task, std::uint64_t seed,
                                     double rate)
    : config_(std::move(config)), task_(task), rate_(rate), seeds_(seed) {
  if (!(rate > 0.0) || !std::isfinite(rate)) {
    throw std::invalid_argument("NaoArmEnvironment::NaoArmEnvironment(): rate must be > 0");
  }
  reset();
}

void NaoArmEnvironment::reset() {
  sim_ = std::make_unique<NaoArmSimulation>(config_, seeds_.nextU64());
  targets_ = Eigen::Vector2d(sim_->target("RShoulderPitch"), sim_->target("RShoulderRoll"));
  sense(0.0);
}

float NaoArmEnvironment::apply(int action) {
  if (action < 0 || action >= naoarm::kNumActions) {
    throw std::out_of_range("NaoArmEnvironment::apply(): action " + std::to_string(action) +
                            " outside 0.." + std::to_string(naoarm::kNumActions - 1));
  }
  targets_ = applyNaoArmAction(action, targets_, sim_->body());
  sim_->setTarget("RShoulderPitch", targets_[0], config_.speed);
  sim_->setTarget("RShoulderRoll", targets_[1], config_.speed);
  // Advance one action period, listening to every audio buffer that ends in it.
  const double period = 1.0 / rate_;
  double energy = 0.0;
  const double end = sim_->time() + period;
  while (sim_->time() < end - 1e-9) {
    sim_->advance(std::min(0.02, end - sim_->time()));
    while (auto buffer = sim_->nextAudioBuffer()) {
      energy = std::max(
          energy, audioEnergy(*buffer, MicrophoneModel::kChannels, MicrophoneModel::kFrontChannel));
    }
  }
  sim_->takeBumperEdges();
  sense(energy);
  return taskReward(task_, observation_);
}

void NaoArmEnvironment::sense(double micEnergy) {
  JointAngles measured = sim_->measuredAngles();
  observation_.shoulderPitch = measured.at("RShoulderPitch");
  observation_.shoulderRoll = measured.at("RShoulderRoll");
  observation_.handMm = sim_->body().position("r_gripper", measured) * 1000.0;
  observation_.pinkPixels = sim_->countPink();
  observation_.bumper = sim_->bumperPressed();
  observation_.micEnergy = micEnergy;
  state_ = toState(observation_);
}

void NaoArmEnvironment::getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const {
  naoArmFeatureRanges(min, max);
}

void NaoArmEnvironment::getMinMaxReward(float* min, float* max) const {
  naoArmRewardRange(task_, min, max);
}

}  // namespace nao_interface
