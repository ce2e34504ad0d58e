#include "rl_env/env/mountain_car.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "env_detail.h"

namespace rl_env {

MountainCar::MountainCar(std::uint64_t seed, bool stochastic, int delay)
    : rng_(seed), stochastic_(stochastic), delay_(delay) {
  if (delay < 0) {
    throw std::invalid_argument("MountainCar::MountainCar(): delay must be >= 0, got " +
                                std::to_string(delay));
  }
  reset();
}

rl_common::State MountainCar::trueState() const {
  return {static_cast<float>(position_), static_cast<float>(velocity_)};
}

void MountainCar::reset() {
  if (stochastic_) {
    position_ = rng_.uniform(kMinPosition, 0.59);
    velocity_ = rng_.uniform(-kMaxVelocity, kMaxVelocity);
  } else {
    position_ = 0.0;
    velocity_ = 0.0;
  }
  history_.assign(static_cast<std::size_t>(delay_) + 1, trueState());
}

float MountainCar::step(double* position, double* velocity, double force) {
  *velocity += 0.001 * force - 0.0025 * std::cos(3.0 * *position);
  *velocity = std::clamp(*velocity, -kMaxVelocity, kMaxVelocity);
  *position += *velocity;
  if (*position <= kMinPosition) {
    *position = kMinPosition;
    if (*velocity < 0.0) *velocity = 0.0;
  }
  *position = std::min(*position, kMaxPosition);
  return *position >= kGoalPosition ? 0.0f : -1.0f;
}

float MountainCar::apply(int action) {
  detail::checkAction(action, kNumActions, "MountainCar::apply()");
  float reward = 0.0f;
  if (!terminal()) {
    double force = action - 1.0;
    if (stochastic_) force += rng_.uniform(-0.5, 0.5);
    reward = step(&position_, &velocity_, force);
  }
  history_.push_back(trueState());
  history_.pop_front();
  return reward;
}

void MountainCar::setState(const rl_common::State& s) {
  detail::checkStateSize(s, 2, "MountainCar::setState()");
  if (!(s[0] >= static_cast<float>(kMinPosition) && s[0] <= static_cast<float>(kMaxPosition) &&
        s[1] >= static_cast<float>(-kMaxVelocity) && s[1] <= static_cast<float>(kMaxVelocity))) {
    throw std::invalid_argument("MountainCar::setState(): state outside the declared ranges");
  }
  position_ = s[0];
  velocity_ = s[1];
  history_.assign(static_cast<std::size_t>(delay_) + 1, trueState());
}

std::vector<rl_common::Experience> MountainCar::seedExperiences() const {
  if (delay_ > 0) return {};  // with a delay, the observed (s, a) does not determine s'
  struct Start {
    double position, velocity;
    int action;
  };
  const Start starts[] = {{0.55, 0.05, 2}, {0.58, 0.03, 1}, {0.59, 0.02, 0}, {-1.19, -0.05, 0}};
  std::vector<rl_common::Experience> out;
  for (const Start& st : starts) {
    rl_common::Experience e;
    double p = st.position;
    double v = st.velocity;
    e.s = {static_cast<float>(p), static_cast<float>(v)};
    e.action = st.action;
    e.reward = step(&p, &v, st.action - 1.0);
    e.next = {static_cast<float>(p), static_cast<float>(v)};
    e.terminal = p >= kGoalPosition;
    out.push_back(e);
  }
  return out;
}

void MountainCar::getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const {
  *min = {static_cast<float>(kMinPosition), static_cast<float>(-kMaxVelocity)};
  *max = {static_cast<float>(kMaxPosition), static_cast<float>(kMaxVelocity)};
}

void MountainCar::getMinMaxReward(float* min, float* max) const {
  *min = -1.0f;
  *max = 0.0f;
}

}  // namespace rl_env
