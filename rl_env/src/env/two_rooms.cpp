#include "rl_env/env/two_rooms.h"

#include <stdexcept>

#include "env_detail.h"

namespace rl_env {

namespace {

Gridworld makeTwoRoomsGrid() {
  Gridworld g(TwoRooms::kHeight, TwoRooms::kWidth);
  for (int ns = 0; ns < TwoRooms::kHeight; ++ns) {
    if (ns != 2) g.block(ns, 5);  // the dividing wall, open only at the doorway (2, 5)
  }
  return g;
}

}  // namespace

TwoRooms::TwoRooms(std::uint64_t seed, bool stochastic, int delay)
    : rng_(seed), stochastic_(stochastic), delay_(delay), grid_(makeTwoRoomsGrid()) {
  if (delay < 0) {
    throw std::invalid_argument("TwoRooms::TwoRooms(): delay must be >= 0, got " +
                                std::to_string(delay));
  }
  reset();
}

bool TwoRooms::terminal() const { return ns_ == kGoalNs && ew_ == kGoalEw; }

void TwoRooms::reset() {
  ns_ = rng_.uniformInt(0, kHeight - 1);
  ew_ = rng_.uniformInt(6, kWidth - 1);
  pending_.assign(static_cast<std::size_t>(delay_), -1);
  obs_ = {static_cast<float>(ns_), static_cast<float>(ew_)};
}

rl_common::Experience TwoRooms::step(int ns, int ew, int dir) const {
  rl_common::Experience e;
  e.s = {static_cast<float>(ns), static_cast<float>(ew)};
  e.action = dir;
  const auto [toNs, toEw] = grid_.move(ns, ew, static_cast<Gridworld::Direction>(dir));
  e.next = {static_cast<float>(toNs), static_cast<float>(toEw)};
  e.terminal = toNs == kGoalNs && toEw == kGoalEw;
  e.reward = e.terminal ? 0.0f : -1.0f;
  return e;
}

float TwoRooms::apply(int action) {
  detail::checkAction(action, kNumActions, "TwoRooms::apply()");
  if (terminal()) return 0.0f;
  pending_.push_back(action);
  const int executed = pending_.front();
  pending_.pop_front();
  if (executed < 0) return -1.0f;  // nothing queued yet: time passes, no move
  const Gridworld::Direction dir = detail::sampleMove(
      rng_, static_cast<Gridworld::Direction>(executed), stochastic_, kMoveSuccess);
  const rl_common::Experience e = step(ns_, ew_, dir);
  ns_ = static_cast<int>(e.next[0]);
  ew_ = static_cast<int>(e.next[1]);
  obs_ = e.next;
  return e.reward;
}

std::vector<rl_common::Experience> TwoRooms::seedExperiences() const {
  if (delay_ > 0) return {};  // with a delay, (s, a) does not determine s'
  return {step(kGoalNs, kGoalEw + 1, kWest), step(2, 6, kWest)};
}

void TwoRooms::requireUndelayed(const char* where) const {
  if (delay_ > 0) {
    throw std::runtime_error(std::string(where) +
                             ": no true model with --delay > 0 (the queued actions are hidden)");
  }
}

std::pair<int, int> TwoRooms::decode(const rl_common::State& s, const char* where) const {
  detail::checkStateSize(s, 2, where);
  const int ns = detail::integerFeature(s, 0, 0, kHeight - 1, where);
  const int ew = detail::integerFeature(s, 1, 0, kWidth - 1, where);
  if (!grid_.open(ns, ew)) {
    throw std::invalid_argument(std::string(where) + ": (" + std::to_string(ns) + ", " +
                                std::to_string(ew) + ") is inside the wall");
  }
  return {ns, ew};
}

std::vector<rl_common::Outcome> TwoRooms::transitions(const rl_common::State& s, int action) const {
  requireUndelayed("TwoRooms::transitions()");
  detail::checkAction(action, kNumActions, "TwoRooms::transitions()");
  const auto [ns, ew] = decode(s, "TwoRooms::transitions()");
  std::vector<rl_common::Outcome> out;
  if (ns == kGoalNs && ew == kGoalEw) {
    detail::addOutcome(&out, s, 0.0f, true, 1.0);
    return out;
  }
  for (const auto& [dir, p] : detail::moveDistribution(static_cast<Gridworld::Direction>(action),
                                                       stochastic_, kMoveSuccess)) {
    rl_common::Experience e = step(ns, ew, dir);
    detail::addOutcome(&out, std::move(e.next), e.reward, e.terminal, p);
  }
  return out;
}

std::vector<rl_common::State> TwoRooms::reachableStates() const {
  requireUndelayed("TwoRooms::reachableStates()");
  return grid_.openCells();
}

void TwoRooms::setState(const rl_common::State& s) {
  const auto [ns, ew] = decode(s, "TwoRooms::setState()");
  ns_ = ns;
  ew_ = ew;
  pending_.assign(static_cast<std::size_t>(delay_), -1);
  obs_ = {static_cast<float>(ns_), static_cast<float>(ew_)};
}

void TwoRooms::getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const {
  *min = {0.0f, 0.0f};
  *max = {kHeight - 1.0f, kWidth - 1.0f};
}

void TwoRooms::getMinMaxReward(float* min, float* max) const {
  *min = -1.0f;
  *max = 0.0f;
}

}  // namespace rl_env
