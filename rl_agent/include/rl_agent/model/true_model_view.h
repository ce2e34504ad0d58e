/**
 * TrueModelView: an environment's exact dynamics (rl_common::TrueModel) seen as a ModelView,
 * so that the planners can plan on the true model (the `optimal` agent).
 *
 * For (s, a) with outcomes {(s'_i, r_i, terminal_i, p_i)}:
 *   reward = Σ p_i r_i,  termProb = Σ_{terminal} p_i,
 *   transitions = the non-terminal outcomes' next states with p_i / (1 − termProb) (merged),
 *   or the terminal ones' if every outcome is terminal;  known = true.
 * The TrueModel must outlive the view; its transitions() must be safe to call (it is const).
 */
#pragma once

#include "rl_common/mdp_model.h"
#include "rl_common/true_model.h"

namespace rl_agent {

class TrueModelView : public rl_common::ModelView {
 public:
  explicit TrueModelView(const rl_common::TrueModel& model) : model_(model) {}
  rl_common::StateActionInfo query(const rl_common::State& input, int action) const override;

 private:
  const rl_common::TrueModel& model_;
};

}  // namespace rl_agent
