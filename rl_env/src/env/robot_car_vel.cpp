#include "rl_env/env/robot_car_vel.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "env_detail.h"

namespace rl_env {

namespace {

constexpr int kSubSteps = 10;
constexpr double kDt = 0.01;                // s per sub-step (10 Hz actions)
constexpr double kThrottleGain = 6.0;       // m/s² per unit throttle
constexpr double kBrakeGain = 5.0;          // m/s² per unit brake
constexpr double kDrag = 0.2;               // 1/s
constexpr double kPedalTimeConstant = 0.2;  // s, first-order pedal lag
constexpr double kLagFrequency = 4.0;       // rad/s, second-order brake (--lag)

// Pedal targets move in steps of 0.1; rounding keeps them on that grid exactly.
double onGrid(double v) { return std::round(v * 10.0) / 10.0; }

}  // namespace

RobotCarVel::RobotCarVel(std::uint64_t seed, Task task, bool lag)
    : rng_(seed), task_(task), lag_(lag) {
  makeSeeds();
  reset();
}

rl_common::State RobotCarVel::observe(const Physics& p) {
  return {static_cast<float>(p.targetVel), static_cast<float>(p.velocity),
          static_cast<float>(p.throttleTarget), static_cast<float>(p.brakeTarget)};
}

void RobotCarVel::reset() {
  physics_ = Physics{};
  switch (task_) {
    case Task::kUp2To7:
      physics_.velocity = 2.0;
      physics_.targetVel = 7.0;
      break;
    case Task::kDown7To2:
      physics_.velocity = 7.0;
      physics_.targetVel = 2.0;
      break;
    case Task::kRandom:
      physics_.targetVel = rng_.uniformInt(0, 11);
      physics_.velocity = rng_.uniformInt(0, 11);
      break;
  }
  obs_ = observe(physics_);
}

float RobotCarVel::step(Physics* p, int action, bool lag) {
  const float reward = static_cast<float>(-10.0 * std::abs(p->velocity - p->targetVel));
  switch (action) {
    case kThrottleUp:
      p->throttleTarget = onGrid(std::min(kMaxThrottle, p->throttleTarget + kPedalStep));
      break;
    case kThrottleDown:
      p->throttleTarget = onGrid(std::max(0.0, p->throttleTarget - kPedalStep));
      break;
    case kBrakeUp:
      p->brakeTarget = onGrid(std::min(kMaxBrake, p->brakeTarget + kPedalStep));
      break;
    case kBrakeDown:
      p->brakeTarget = onGrid(std::max(0.0, p->brakeTarget - kPedalStep));
      break;
    default:
      break;
  }
  for (int i = 0; i < kSubSteps; ++i) {
    p->throttle += (p->throttleTarget - p->throttle) * kDt / kPedalTimeConstant;
    if (lag) {
      const double w = kLagFrequency;
      const double acc = w * w * (p->brakeTarget - p->brake) - 2.0 * w * p->brakeRate;
      p->brakeRate += kDt * acc;
      p->brake = std::clamp(p->brake + kDt * p->brakeRate, 0.0, kMaxBrake);
    } else {
      p->brake += (p->brakeTarget - p->brake) * kDt / kPedalTimeConstant;
    }
    const double accel = kThrottleGain * p->throttle - kBrakeGain * p->brake - kDrag * p->velocity;
    p->velocity = std::clamp(p->velocity + kDt * accel, 0.0, kMaxVelocity);
  }
  return reward;
}

float RobotCarVel::apply(int action) {
  detail::checkAction(action, kNumActions, "RobotCarVel::apply()");
  const float reward = step(&physics_, action, lag_);
  obs_ = observe(physics_);
  return reward;
}

void RobotCarVel::setState(const rl_common::State& s) {
  detail::checkStateSize(s, 4, "RobotCarVel::setState()");
  const double limits[4] = {kMaxVelocity, kMaxVelocity, kMaxThrottle, kMaxBrake};
  for (std::size_t i = 0; i < 4; ++i) {
    if (!(s[i] >= 0.0f && s[i] <= static_cast<float>(limits[i]))) {
      throw std::invalid_argument("RobotCarVel::setState(): feature " + std::to_string(i) +
                                  " outside its declared range");
    }
  }
  physics_ = Physics{};
  physics_.targetVel = s[0];
  physics_.velocity = s[1];
  physics_.throttleTarget = onGrid(s[2]);
  physics_.brakeTarget = onGrid(s[3]);
  physics_.throttle = physics_.throttleTarget;
  physics_.brake = physics_.brakeTarget;
  obs_ = observe(physics_);
}

void RobotCarVel::makeSeeds() {
  rl_common::Random r = rng_.derive("seeds");
  for (int i = 0; i < 25; ++i) {
    Physics p;
    switch (task_) {
      case Task::kUp2To7:
        p.targetVel = 7.0;
        break;
      case Task::kDown7To2:
        p.targetVel = 2.0;
        break;
      case Task::kRandom:
        p.targetVel = r.uniformInt(0, 11);
        break;
    }
    // Float-valued so that the seed replays exactly from its observed state.
    p.velocity = static_cast<float>(r.uniform(0.0, kMaxVelocity));
    p.throttleTarget = r.uniformInt(0, 4) / 10.0;
    p.brakeTarget = r.uniformInt(0, 10) / 10.0;
    p.throttle = p.throttleTarget;
    p.brake = p.brakeTarget;
    rl_common::Experience e;
    e.s = observe(p);
    e.action = r.uniformInt(0, kNumActions - 1);
    e.reward = step(&p, e.action, lag_);
    e.next = observe(p);
    e.terminal = false;
    seeds_.push_back(e);
  }
}

void RobotCarVel::getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const {
  *min = {0.0f, 0.0f, 0.0f, 0.0f};
  *max = {static_cast<float>(kMaxVelocity), static_cast<float>(kMaxVelocity),
          static_cast<float>(kMaxThrottle), static_cast<float>(kMaxBrake)};
}

void RobotCarVel::getMinMaxReward(float* min, float* max) const {
  *min = static_cast<float>(-10.0 * kMaxVelocity);
  *max = 0.0f;
}

}  // namespace rl_env
