/**
 * M5Model: the original's `--model m5tree` (M5ALLMULTI, ORIGINAL.md §3.4, §6.4): a factored
 * model of a continuous domain with one M5 regression tree (M5Tree, Quinlan 1992, leaf models
 * over all features) per output.
 *
 * Input x = [s (plus history features), onehot(a)]. Tree j predicts s'_j − s_j (relative
 * transitions) or s'_j; the reward tree predicts r; in episodic tasks a terminal tree predicts
 * the terminal flag (0/1). Feature trees learn only from non-terminal transitions. A query is
 * deterministic: one next state s'_j = clip(s_j + Δ_j, min_j, max_j) with probability 1,
 * reward = the reward tree's prediction, termProb = clip(terminal tree, 0, 1). Before any data
 * it predicts a self-transition with reward −0.001 and known = false, as the other models.
 * Trees rebuild when an example's prediction is off by more than 1e-4 of the output's range
 * (the original's treeRangePct). view() is cheap (immutable shared trees).
 */
#pragma once

#include <memory>
#include <vector>

#include "rl_agent/model/m5_tree.h"
#include "rl_common/mdp_model.h"

namespace rl_agent {

class M5Model : public rl_common::MDPModel {
 public:
  struct Config {
    int numActions = 0;
    std::vector<float> featMin;
    std::vector<float> featMax;
    int extraInputs = 0;  ///< history features appended to states
    bool relativeTransitions = true;
    bool episodic = true;
    float rewardRange = 1.0f;
  };

  class View : public rl_common::ModelView {
   public:
    rl_common::StateActionInfo query(const rl_common::State& input, int action) const override;

   private:
    friend class M5Model;
    std::shared_ptr<const Config> config_;
    std::vector<M5Tree::Snapshot> features_;
    M5Tree::Snapshot reward_, terminal_;
    std::size_t experiences_ = 0;
  };

  /// Throws std::invalid_argument for a bad configuration.
  explicit M5Model(const Config& config);

  bool update(const std::vector<rl_common::Experience>& experiences) override;
  std::shared_ptr<const rl_common::ModelView> view() const override;
  std::size_t numExperiences() const { return experiences_; }

 private:
  std::vector<float> treeInput(const rl_common::State& s, int action) const;

  std::shared_ptr<const Config> config_;
  std::vector<M5Tree> features_;
  M5Tree reward_, terminal_;
  std::size_t experiences_ = 0;
};

}  // namespace rl_agent
