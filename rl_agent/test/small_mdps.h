/**
 * Small hand-made MDPs for the agent and planner tests (rl_agent cannot depend on rl_env).
 *
 * TwoRoomGrid: a 7x5 grid split by a wall at x = 3 with a door at y = 2; start (0, 0), goal
 * (6, 4); actions 0 = N (y+1), 1 = S, 2 = E (x+1), 3 = W; reward −1 per step; reaching the goal
 * ends the episode. Optionally each move slips to a perpendicular direction with probability
 * `slip` (split evenly). The shortest path takes 10 steps. It is also a TrueModel.
 */
#pragma once

#include <map>
#include <memory>
#include <vector>

#include "rl_common/agent.h"
#include "rl_common/environment.h"
#include "rl_common/mdp_model.h"
#include "rl_common/random.h"
#include "rl_common/true_model.h"

namespace test_mdps {

using rl_common::State;

class TwoRoomGrid : public rl_common::TrueModel {
 public:
  static constexpr int kW = 7, kH = 5, kWallX = 3, kDoorY = 2;
  explicit TwoRoomGrid(double slip = 0.0, std::uint64_t seed = 1) : slip_(slip), rng_(seed) {}

  static bool open(int x, int y) {
    if (x < 0 || y < 0 || x >= kW || y >= kH) return false;
    return x != kWallX || y == kDoorY;
  }
  static bool goal(const State& s) { return s[0] == 6.0f && s[1] == 4.0f; }
  static State move(const State& s, int a) {
    static const int dx[] = {0, 0, 1, -1}, dy[] = {1, -1, 0, 0};
    const int x = static_cast<int>(s[0]) + dx[a], y = static_cast<int>(s[1]) + dy[a];
    return open(x, y) ? State{float(x), float(y)} : s;
  }
  static rl_common::EnvironmentDescription describe() {
    rl_common::EnvironmentDescription d;
    d.numActions = 4;
    d.minFeatures = {0.0f, 0.0f};
    d.maxFeatures = {6.0f, 4.0f};
    d.minReward = -1.0f;
    d.maxReward = -1.0f;
    d.episodic = true;
    return d;
  }

  State reset() {
    s_ = {0.0f, 0.0f};
    return s_;
  }
  /// Applies `a`; returns the reward and sets *terminal.
  float step(int a, bool* terminal) {
    int actual = a;
    if (slip_ > 0.0 && rng_.bernoulli(slip_)) {
      const bool vertical = a < 2;
      actual = vertical ? 2 + rng_.uniformInt(0, 1) : rng_.uniformInt(0, 1);
    }
    s_ = move(s_, actual);
    *terminal = goal(s_);
    return -1.0f;
  }
  const State& state() const { return s_; }

  std::vector<rl_common::Outcome> transitions(const State& s, int a) const override {
    std::map<State, double> p;
    p[move(s, a)] += 1.0 - slip_;
    if (slip_ > 0.0) {
      const int side[2] = {a < 2 ? 2 : 0, a < 2 ? 3 : 1};
      for (int b : side) p[move(s, b)] += slip_ / 2.0;
    }
    std::vector<rl_common::Outcome> out;
    for (const auto& [next, q] : p) out.push_back({next, -1.0f, goal(next), q});
    return out;
  }
  std::vector<State> reachableStates() const override {
    std::vector<State> out;
    for (int x = 0; x < kW; ++x) {
      for (int y = 0; y < kH; ++y) {
        if (open(x, y)) out.push_back({float(x), float(y)});
      }
    }
    return out;
  }
  void setState(const State& s) override { s_ = s; }

 private:
  double slip_;
  rl_common::Random rng_;
  State s_{0.0f, 0.0f};
};

/// Runs one episode of at most maxSteps; returns the number of steps taken.
inline int runEpisode(rl_common::Agent& agent, TwoRoomGrid& env, int maxSteps) {
  int a = agent.firstAction(env.reset());
  for (int t = 1; t <= maxSteps; ++t) {
    bool terminal = false;
    const float r = env.step(a, &terminal);
    if (terminal) {
      agent.lastAction(r);
      return t;
    }
    if (t == maxSteps) break;
    a = agent.nextAction(r, env.state());
  }
  return maxSteps;
}

/// A fixed model given as a table: (state, action) -> prediction.
class TableModelView : public rl_common::ModelView {
 public:
  std::map<std::pair<State, int>, rl_common::StateActionInfo> table;
  rl_common::StateActionInfo query(const State& s, int a) const override {
    return table.at({s, a});
  }
  void set(const State& s, int a, std::vector<std::pair<State, double>> next, float reward,
           float termProb = 0.0f) {
    rl_common::StateActionInfo info;
    info.transitions = std::move(next);
    info.reward = reward;
    info.termProb = termProb;
    info.known = true;
    table[{s, a}] = info;
  }
};

/// The two-state chain with hand-computed values (γ = 0.9):
///   A: a0 stays (r 0); a1 goes to B w.p. 0.8, stays w.p. 0.2 (r 0).
///   B: a0 stays (r 1); a1 goes to A (r 0).
///   V(B) = 10, V(A) = 7.2 / 0.82, Q(A,a0) = Q(B,a1) = 0.9 V(A).
/// C: every action ends the episode with reward 5 (Q = 5).
inline std::shared_ptr<TableModelView> chainModel() {
  auto m = std::make_shared<TableModelView>();
  const State A{0}, B{1}, C{2};
  m->set(A, 0, {{A, 1.0}}, 0.0f);
  m->set(A, 1, {{B, 0.8}, {A, 0.2}}, 0.0f);
  m->set(B, 0, {{B, 1.0}}, 1.0f);
  m->set(B, 1, {{A, 1.0}}, 0.0f);
  m->set(C, 0, {{C, 1.0}}, 5.0f, 1.0f);
  m->set(C, 1, {{A, 1.0}}, 5.0f, 1.0f);
  return m;
}
constexpr double kChainVA = 7.2 / 0.82;
constexpr double kChainVB = 10.0;

}  // namespace test_mdps
