#include "rl_env/env/fuel_rooms.h"

#include <algorithm>
#include <stdexcept>

#include "env_detail.h"

namespace rl_env {

namespace {

// Row and column change of each move, clockwise from north.
constexpr int kDns[FuelRooms::kNumActions] = {1, 1, 0, -1, -1, -1, 0, 1};
constexpr int kDew[FuelRooms::kNumActions] = {0, 1, 1, 1, 0, -1, -1, -1};

}  // namespace

FuelRooms::FuelRooms(std::uint64_t seed, bool stochastic, bool highVariance)
    : rng_(seed), stochastic_(stochastic), highVariance_(highVariance) {
  makeSeeds();
  reset();
}

rl_common::State FuelRooms::observe(const Pose& p) {
  return {static_cast<float>(p.ns), static_cast<float>(p.ew), static_cast<float>(p.energy)};
}

bool FuelRooms::isTerminal(const Pose& p) {
  return p.energy < 0 || (p.ns == kGoalNs && p.ew == kGoalEw);
}

bool FuelRooms::terminal() const { return isTerminal(pose_); }

void FuelRooms::reset() {
  pose_.ns = rng_.uniformInt(7, 12);
  pose_.ew = rng_.uniformInt(0, 4);
  pose_.energy = rng_.uniformInt(14, 18);
  obs_ = observe(pose_);
}

float FuelRooms::fuelCost(int ns, int ew) const {
  const float base = ns == 0 ? -13.0f : -10.0f;
  if (highVariance_) return base - 5.0f * static_cast<float>(ew % 5);
  return base - 8.0f - static_cast<float>(ew % 5);
}

float FuelRooms::step(Pose* p, int move) const {
  p->ns = std::clamp(p->ns + kDns[move], 0, kHeight - 1);
  p->ew = std::clamp(p->ew + kDew[move], 0, kWidth - 1);
  p->energy -= 1;
  const bool fuelRow = p->ns == 0 || p->ns == kHeight - 1;
  if (fuelRow) p->energy = std::min(kMaxEnergy, p->energy + kFuelGain);
  if (p->energy < 0) return kOutOfFuelReward;
  if (p->ns == kGoalNs && p->ew == kGoalEw) return 0.0f;
  if (fuelRow) return fuelCost(p->ns, p->ew);
  return move % 2 == 0 ? -1.0f : -1.4f;
}

float FuelRooms::apply(int action) {
  detail::checkAction(action, kNumActions, "FuelRooms::apply()");
  if (terminal()) return 0.0f;
  int move = action;
  if (stochastic_) {
    const double u = rng_.uniform();
    if (u >= kMoveSuccess) {
      move = (action + (u < kMoveSuccess + 0.5 * (1.0 - kMoveSuccess) ? kNumActions - 1 : 1)) %
             kNumActions;
    }
  }
  const float reward = step(&pose_, move);
  obs_ = observe(pose_);
  return reward;
}

void FuelRooms::setState(const rl_common::State& s) {
  const char* where = "FuelRooms::setState()";
  detail::checkStateSize(s, 3, where);
  pose_.ns = detail::integerFeature(s, 0, 0, kHeight - 1, where);
  pose_.ew = detail::integerFeature(s, 1, 0, kWidth - 1, where);
  pose_.energy = detail::integerFeature(s, 2, -1, kMaxEnergy, where);
  obs_ = observe(pose_);
}

rl_common::Experience FuelRooms::seed(Pose from, int move) const {
  rl_common::Experience e;
  e.s = observe(from);
  e.action = move;
  e.reward = step(&from, move);
  e.next = observe(from);
  e.terminal = isTerminal(from);
  return e;
}

void FuelRooms::makeSeeds() {
  rl_common::Random r = rng_.derive("seeds");
  // Reaching the goal from a random neighbour with some fuel left.
  const int toGoal = r.uniformInt(0, kNumActions - 1);
  seeds_.push_back(
      seed({kGoalNs - kDns[toGoal], kGoalEw - kDew[toGoal], r.uniformInt(1, 20)}, toGoal));
  // Fuelling on the north row (20) and on the south row (0).
  seeds_.push_back(seed({kHeight - 2, r.uniformInt(0, kWidth - 1), r.uniformInt(0, 40)}, kNorth));
  seeds_.push_back(seed({1, r.uniformInt(0, kWidth - 1), r.uniformInt(0, 40)}, kSouth));
  // Running out of fuel away from the fuel rows (out of fuel wins over reaching the goal).
  const Pose empty{r.uniformInt(2, kHeight - 3), r.uniformInt(0, kWidth - 1), 0};
  seeds_.push_back(seed(empty, r.uniformInt(0, kNumActions - 1)));
}

void FuelRooms::getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const {
  *min = {0.0f, 0.0f, -1.0f};
  *max = {kHeight - 1.0f, kWidth - 1.0f, static_cast<float>(kMaxEnergy)};
}

void FuelRooms::getMinMaxReward(float* min, float* max) const {
  *min = kOutOfFuelReward;
  *max = 0.0f;
}

}  // namespace rl_env
