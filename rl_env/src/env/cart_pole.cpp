#include "rl_env/env/cart_pole.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "env_detail.h"

namespace rl_env {

namespace {

constexpr double kGravity = 9.8;
constexpr double kCartMass = 1.0;
constexpr double kPoleMass = 0.1;
constexpr double kTotalMass = kCartMass + kPoleMass;
constexpr double kHalfLength = 0.5;
constexpr double kPoleMassLength = kPoleMass * kHalfLength;
constexpr double kPi = 3.14159265358979323846;
// Declared ranges of x, ẋ, θ, θ̇.
constexpr std::array<double, 4> kLimits = {2.5, 3.0, CartPole::kFailAngle, kPi};

}  // namespace

CartPole::CartPole(std::uint64_t seed, bool stochastic) : rng_(seed), stochastic_(stochastic) {
  reset();
}

CartPole::Physics CartPole::step(const Physics& p, double force) {
  const double x = p[0], xDot = p[1], theta = p[2], thetaDot = p[3];
  const double cosT = std::cos(theta);
  const double sinT = std::sin(theta);
  const double temp = (force + kPoleMassLength * thetaDot * thetaDot * sinT) / kTotalMass;
  const double thetaAcc = (kGravity * sinT - cosT * temp) /
                          (kHalfLength * (4.0 / 3.0 - kPoleMass * cosT * cosT / kTotalMass));
  const double xAcc = temp - kPoleMassLength * thetaAcc * cosT / kTotalMass;
  return {x + kTau * xDot, xDot + kTau * xAcc, theta + kTau * thetaDot, thetaDot + kTau * thetaAcc};
}

bool CartPole::failed(const Physics& p) {
  return std::abs(p[0]) > kFailPosition || std::abs(p[2]) > kFailAngle;
}

rl_common::State CartPole::observe(const Physics& p) {
  rl_common::State s(4);
  for (std::size_t i = 0; i < 4; ++i) {
    s[i] = std::clamp(static_cast<float>(p[i]), static_cast<float>(-kLimits[i]),
                      static_cast<float>(kLimits[i]));
  }
  return s;
}

void CartPole::reset() {
  for (double& v : physics_) v = stochastic_ ? rng_.uniform(-0.05, 0.05) : 0.0;
  obs_ = observe(physics_);
}

float CartPole::apply(int action) {
  detail::checkAction(action, kNumActions, "CartPole::apply()");
  if (terminal()) return 0.0f;
  double force = action == kRight ? kForce : -kForce;
  if (stochastic_) force += kForce * rng_.uniform(-0.5, 0.5);
  physics_ = step(physics_, force);
  obs_ = observe(physics_);
  return terminal() ? 0.0f : 1.0f;
}

void CartPole::setState(const rl_common::State& s) {
  detail::checkStateSize(s, 4, "CartPole::setState()");
  for (std::size_t i = 0; i < 4; ++i) {
    if (!std::isfinite(s[i])) {
      throw std::invalid_argument("CartPole::setState(): feature " + std::to_string(i) +
                                  " is not finite");
    }
    physics_[i] = s[i];
  }
  obs_ = observe(physics_);
}

std::vector<rl_common::Experience> CartPole::seedExperiences() const {
  struct Start {
    Physics p;
    int action;
  };
  // Pole falling right and left, cart leaving right and left.
  const Start starts[] = {{{0.0, 0.0, 0.2, 1.0}, kLeft},
                          {{0.0, 0.0, -0.2, -1.0}, kRight},
                          {{2.38, 2.0, 0.0, 0.0}, kRight},
                          {{-2.38, -2.0, 0.0, 0.0}, kLeft}};
  std::vector<rl_common::Experience> out;
  for (const Start& st : starts) {
    rl_common::Experience e;
    e.s = observe(st.p);
    e.action = st.action;
    const Physics next = step(st.p, st.action == kRight ? kForce : -kForce);
    e.next = observe(next);
    e.terminal = failed(next);
    e.reward = e.terminal ? 0.0f : 1.0f;
    out.push_back(e);
  }
  return out;
}

void CartPole::getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const {
  min->resize(4);
  max->resize(4);
  for (std::size_t i = 0; i < 4; ++i) {
    (*min)[i] = static_cast<float>(-kLimits[i]);
    (*max)[i] = static_cast<float>(kLimits[i]);
  }
}

void CartPole::getMinMaxReward(float* min, float* max) const {
  *min = 0.0f;
  *max = 1.0f;
}

}  // namespace rl_env
