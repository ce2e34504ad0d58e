/**
 * RobotCarVel ("car2to7", "car7to2", "carrandom"): velocity control of an autonomous car through
 * its throttle and brake pedals (Hester, Quinlan & Stone, "RTMBA: A Real-Time Model-Based
 * Reinforcement Learning Architecture for Robot Control", ICRA 2012), as the original package's
 * RobotCarVel (shared/spec/ORIGINAL.md §8).
 *
 * State [target velocity 0–12 m/s, current velocity 0–12 m/s, throttle target 0–0.4, brake
 * target 0–1]. Actions: NOTHING, THROTTLE_UP, THROTTLE_DOWN, BRAKE_UP, BRAKE_DOWN move a pedal
 * target by 0.1 within its range. The reward −10·|current − target| is computed before the
 * dynamics advance by one 10 Hz step. The true pedal positions are hidden and follow their
 * targets. Episodic but never terminal (experiment runners cap episodes at 100 steps). Tasks:
 * 2→7 m/s, 7→2 m/s, or random integer start and target velocities in 0–11 m/s. 25 seed
 * experiences from random states of the seed's own stream (pedals at their targets).
 *
 * The spec gives no vehicle numbers, so these are ours (a plain longitudinal model): each
 * 0.1 s step is integrated in 10 Euler sub-steps of 0.01 s; acceleration = 6·throttle −
 * 5·brake − 0.2·velocity (m/s², so full throttle 0.4 holds 12 m/s), velocity kept in [0, 12];
 * the throttle follows its target as a first-order lag of 0.2 s; the brake follows its target
 * as a first-order lag of 0.2 s, or with --lag as a critically damped second-order system
 * (natural frequency 4 rad/s, about 1.2 s to settle).
 */
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rl_common/environment.h"
#include "rl_common/random.h"

namespace rl_env {

class RobotCarVel : public rl_common::Environment {
 public:
  enum Action { kNothing = 0, kThrottleUp = 1, kThrottleDown = 2, kBrakeUp = 3, kBrakeDown = 4 };
  /// Which velocity change each episode asks for.
  enum class Task { kUp2To7, kDown7To2, kRandom };
  static constexpr int kNumActions = 5;
  static constexpr double kMaxVelocity = 12.0;
  static constexpr double kMaxThrottle = 0.4;
  static constexpr double kMaxBrake = 1.0;
  static constexpr double kPedalStep = 0.1;

  /// The hidden and visible physical state.
  struct Physics {
    double targetVel = 0.0;
    double velocity = 0.0;
    double throttleTarget = 0.0;
    double brakeTarget = 0.0;
    double throttle = 0.0;   ///< true throttle position (hidden)
    double brake = 0.0;      ///< true brake position (hidden)
    double brakeRate = 0.0;  ///< brake velocity of the second-order (lag) model (hidden)
  };

  RobotCarVel(std::uint64_t seed, Task task, bool lag);

  // rl_common::Environment
  const rl_common::State& sensation() const override { return obs_; }
  /// Returns −10·|velocity − target| of the current state, then moves a pedal target and
  /// advances the dynamics by 0.1 s.
  float apply(int action) override;
  bool terminal() const override { return false; }
  void reset() override;
  int numActions() const override { return kNumActions; }
  void getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const override;
  void getMinMaxReward(float* min, float* max) const override;
  std::vector<rl_common::Experience> seedExperiences() const override { return seeds_; }
  std::string name() const override { return "RobotCarVel"; }
  /// The dynamics are deterministic (only carrandom's start is random).
  bool isStochastic() const override { return false; }

  /// Sets [target, velocity, throttle target, brake target], with the hidden pedals at their
  /// targets. Throws std::invalid_argument outside the declared ranges.
  void setState(const rl_common::State& s);
  const Physics& physics() const { return physics_; }
  Task task() const { return task_; }
  bool lag() const { return lag_; }

  /// Applies `action` to `p`: pedal target change and 0.1 s of dynamics; returns the reward.
  static float step(Physics* p, int action, bool lag);

 private:
  static rl_common::State observe(const Physics& p);
  void makeSeeds();

  rl_common::Random rng_;
  Task task_;
  bool lag_;
  Physics physics_;
  rl_common::State obs_;
  std::vector<rl_common::Experience> seeds_;
};

}  // namespace rl_env
