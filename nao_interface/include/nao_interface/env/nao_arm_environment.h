/**
 * NaoArmEnvironment: the paper's Nao arm domain (Hester & Stone, TEXPLORE-VANIR, §5.2) as an
 * rl_common::Environment for the standalone runner, registered as `naoarm` by
 * addNaoArmEnvironment (nao_arm_registration.h).
 *
 * It runs the same NaoArmSimulation the nao_arm_sim node serves, in simulated time: each step
 * moves the shoulder targets by the action (nao_arm_task.h), advances the simulation by
 * 1 / rate seconds (the paper acts at 3 Hz), then senses as the bridge does: joint angles from
 * the joint sensors, the hand position by forward kinematics of those angles, pink pixels
 * counted with HSV thresholds in the rendered camera image, the latched bumper state and the
 * highest microphone energy of the audio buffers of the step. A step takes a few milliseconds
 * of computer time. Non-episodic. The task (and so the reward) can change between phases.
 */
#pragma once

#include <cstdint>
#include <memory>

#include "nao_interface/env/nao_arm_task.h"
#include "nao_interface/sim/nao_arm_simulation.h"
#include "rl_common/environment.h"
#include "rl_common/random.h"

namespace nao_interface {

class NaoArmEnvironment : public rl_common::Environment {
 public:
  /// `rate` in Hz (actions per simulated second). Throws std::runtime_error if the URDF
  /// cannot be loaded, std::invalid_argument for a bad rate.
  NaoArmEnvironment(NaoArmSimConfig config, NaoArmTask task, std::uint64_t seed, double rate = 3.0);

  const rl_common::State& sensation() const override { return state_; }
  float apply(int action) override;
  bool terminal() const override { return false; }
  /// Puts the arm back in its start posture (a fresh simulation on the next seed stream).
  void reset() override;
  int numActions() const override { return naoarm::kNumActions; }
  void getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const override;
  void getMinMaxReward(float* min, float* max) const override;
  bool isEpisodic() const override { return false; }
  std::string name() const override { return "NaoArm"; }
  bool isStochastic() const override { return config_.stochastic; }

  /// Changes the task (and so the reward) from the next step on.
  void setTask(NaoArmTask task) { task_ = task; }
  NaoArmTask task() const { return task_; }
  /// The last observation (raw microphone energy, pink count ...).
  const NaoArmObservation& observation() const { return observation_; }
  const NaoArmSimulation& simulation() const { return *sim_; }

 private:
  void sense(double micEnergy);

  NaoArmSimConfig config_;
  NaoArmTask task_;
  double rate_;
  rl_common::Random seeds_;
  std::unique_ptr<NaoArmSimulation> sim_;
  Eigen::Vector2d targets_;
  NaoArmObservation observation_;
  rl_common::State state_;
};

}  // namespace nao_interface
