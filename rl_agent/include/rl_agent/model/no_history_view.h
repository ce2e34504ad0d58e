/**
 * NoHistoryView: a model learned with an action history in its input (--history k: the state,
 * then k one-hot action codes) queried with states alone, as an evaluation that knows only
 * states does. Each such query gets "none" for every past action (all-zero codes), the input
 * that experiences given before the first step (seeds) get. An input that already carries the
 * history is passed on unchanged.
 */
#pragma once

#include <cstddef>
#include <memory>

#include "rl_common/mdp_model.h"

namespace rl_agent {

class NoHistoryView : public rl_common::ModelView {
 public:
  /// `numFeatures`: features of a state; `historyInputs`: the k·A codes after them.
  NoHistoryView(std::shared_ptr<const rl_common::ModelView> base, std::size_t numFeatures,
                std::size_t historyInputs)
      : base_(std::move(base)), numFeatures_(numFeatures), historyInputs_(historyInputs) {}

  rl_common::StateActionInfo query(const rl_common::State& input, int action) const override {
    return base_->query(padded(input), action);
  }
  void refresh(const rl_common::State& input, int action, rl_common::StateActionInfo& info,
               rl_common::PredictionStamp& stamp) const override {
    base_->refresh(padded(input), action, info, stamp);
  }

 private:
  rl_common::State padded(const rl_common::State& input) const {
    if (input.size() != numFeatures_) return input;
    rl_common::State out = input;
    out.resize(numFeatures_ + historyInputs_, 0.0f);
    return out;
  }

  std::shared_ptr<const rl_common::ModelView> base_;
  std::size_t numFeatures_;
  std::size_t historyInputs_;
};

}  // namespace rl_agent
