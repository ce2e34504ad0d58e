#include "rl_env/env/taxi.h"

#include <stdexcept>

#include "env_detail.h"

namespace rl_env {

namespace {

Gridworld makeTaxiGrid() {
  Gridworld g(Taxi::kSize, Taxi::kSize);
  for (int ns : {0, 1}) {
    g.addWall(ns, 0, Gridworld::kEast);  // between columns 0|1
    g.addWall(ns, 2, Gridworld::kEast);  // between columns 2|3
  }
  for (int ns : {3, 4}) g.addWall(ns, 1, Gridworld::kEast);  // between columns 1|2
  return g;
}

}  // namespace

const std::array<std::pair<int, int>, 4>& Taxi::landmarks() {
  static const std::array<std::pair<int, int>, 4> kLandmarks = {{{4, 0}, {0, 3}, {4, 4}, {0, 0}}};
  return kLandmarks;
}

Taxi::Taxi(std::uint64_t seed, bool stochastic)
    : rng_(seed), stochastic_(stochastic), grid_(makeTaxiGrid()) {
  reset();
}

rl_common::State Taxi::observe(const Pose& p) {
  return {static_cast<float>(p.ns), static_cast<float>(p.ew), static_cast<float>(p.passenger),
          static_cast<float>(p.destination)};
}

bool Taxi::terminal() const { return isTerminal(pose_); }

void Taxi::reset() {
  pose_.ns = rng_.uniformInt(0, kSize - 1);
  pose_.ew = rng_.uniformInt(0, kSize - 1);
  pose_.passenger = rng_.uniformInt(0, 3);
  // A destination other than the passenger's landmark, uniformly.
  pose_.destination = (pose_.passenger + rng_.uniformInt(1, 3)) % 4;
  ficklePending_ = false;
  obs_ = observe(pose_);
}

float Taxi::applyEffect(Pose* p, int effect, bool* pickedUp) const {
  *pickedUp = false;
  if (effect == kPickup) {
    if (p->passenger != kInTaxi &&
        landmarks()[static_cast<std::size_t>(p->passenger)] == std::make_pair(p->ns, p->ew)) {
      p->passenger = kInTaxi;
      *pickedUp = true;
      return kStepReward;
    }
    return kIllegalReward;
  }
  if (effect == kPutdown) {
    if (p->passenger == kInTaxi &&
        landmarks()[static_cast<std::size_t>(p->destination)] == std::make_pair(p->ns, p->ew)) {
      p->passenger = p->destination;
      return kDeliveryReward;
    }
    return kIllegalReward;
  }
  const auto [ns, ew] = grid_.move(p->ns, p->ew, static_cast<Gridworld::Direction>(effect));
  p->ns = ns;
  p->ew = ew;
  return kStepReward;
}

float Taxi::apply(int action) {
  detail::checkAction(action, kNumActions, "Taxi::apply()");
  if (terminal()) return 0.0f;
  int effect = action;
  if (action <= kWest) {
    effect = detail::sampleMove(rng_, static_cast<Gridworld::Direction>(action), stochastic_,
                                kMoveSuccess);
  }
  bool pickedUp = false;
  const float reward = applyEffect(&pose_, effect, &pickedUp);
  if (action <= kWest && ficklePending_) {
    ficklePending_ = false;
    if (rng_.bernoulli(kFickleProbability)) {
      pose_.destination = (pose_.destination + rng_.uniformInt(1, 3)) % 4;
    }
  }
  if (pickedUp && stochastic_) ficklePending_ = true;
  obs_ = observe(pose_);
  return reward;
}

Taxi::Pose Taxi::decode(const rl_common::State& s, const char* where) const {
  detail::checkStateSize(s, 4, where);
  Pose p;
  p.ns = detail::integerFeature(s, kNs, 0, kSize - 1, where);
  p.ew = detail::integerFeature(s, kEw, 0, kSize - 1, where);
  p.passenger = detail::integerFeature(s, kPassenger, 0, kInTaxi, where);
  p.destination = detail::integerFeature(s, kDestination, 0, 3, where);
  if (isTerminal(p) &&
      landmarks()[static_cast<std::size_t>(p.destination)] != std::make_pair(p.ns, p.ew)) {
    throw std::invalid_argument(std::string(where) +
                                ": a delivered passenger requires the taxi on the destination");
  }
  return p;
}

void Taxi::setState(const rl_common::State& s) {
  pose_ = decode(s, "Taxi::setState()");
  ficklePending_ = false;
  obs_ = observe(pose_);
}

std::vector<rl_common::Outcome> Taxi::transitions(const rl_common::State& s, int action) const {
  detail::checkAction(action, kNumActions, "Taxi::transitions()");
  const Pose from = decode(s, "Taxi::transitions()");
  std::vector<rl_common::Outcome> out;
  if (isTerminal(from)) {
    detail::addOutcome(&out, s, 0.0f, true, 1.0);
    return out;
  }
  // Effective actions with their probabilities: the move noise, or PICKUP / PUTDOWN as given.
  std::vector<std::pair<int, double>> effects = {{action, 1.0}};
  if (action <= kWest) {
    effects.clear();
    for (const auto& [dir, p] : detail::moveDistribution(static_cast<Gridworld::Direction>(action),
                                                         stochastic_, kMoveSuccess)) {
      effects.emplace_back(dir, p);
    }
  }
  for (const auto& [effect, p] : effects) {
    Pose to = from;
    bool pickedUp = false;
    const float r = applyEffect(&to, effect, &pickedUp);
    detail::addOutcome(&out, observe(to), r, isTerminal(to), p);
  }
  return out;
}

std::vector<rl_common::State> Taxi::reachableStates() const {
  std::vector<rl_common::State> out;
  for (int ns = 0; ns < kSize; ++ns) {
    for (int ew = 0; ew < kSize; ++ew) {
      for (int pass = 0; pass <= kInTaxi; ++pass) {
        for (int dest = 0; dest < 4; ++dest) {
          const Pose p{ns, ew, pass, dest};
          if (isTerminal(p) &&
              landmarks()[static_cast<std::size_t>(dest)] != std::make_pair(ns, ew)) {
            continue;
          }
          out.push_back(observe(p));
        }
      }
    }
  }
  return out;
}

void Taxi::getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const {
  *min = {0.0f, 0.0f, 0.0f, 0.0f};
  *max = {kSize - 1.0f, kSize - 1.0f, static_cast<float>(kInTaxi), 3.0f};
}

void Taxi::getMinMaxReward(float* min, float* max) const {
  *min = kIllegalReward;
  *max = kDeliveryReward;
}

}  // namespace rl_env
