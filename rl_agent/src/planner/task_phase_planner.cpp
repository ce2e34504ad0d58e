#include "rl_agent/planner/task_phase_planner.h"

#include <utility>

#include "rl_common/planner.h"
#include "rl_common/random.h"

namespace rl_agent {

void TaskPhasePlanner::observe(const rl_common::State& s) {
  if (config_.recent <= 0) return;
  recent_.push_back(s);
  if (static_cast<int>(recent_.size()) > config_.recent) recent_.pop_front();
}

int TaskPhasePlanner::plan(const rl_common::State& s,
                           std::shared_ptr<const rl_common::ModelView> model) {
  // A fresh table every step, rooted at s: the model changed, and with key features the
  // table's representatives must be the states imagined from s, not from earlier visits.
  auto planner = std::make_unique<ValueIteration>(
      config_.table, rl_common::Random::deriveSeed(config_.seed, "task planner", steps_++));
  planner->warmStartFrom(last_.get());  // last step's values: far fewer sweeps
  planner->setModel(std::move(model));
  // The states just observed are their entries' representatives (oldest first, so the newest
  // of an entry wins; the current state last): imagined ones alone let each of two cells
  // promise a route through the other that the model gets wrong from the real state, and the
  // greedy agent oscillates between them (docs/science/lightworld-curiosity.md §5.2).
  planner->addStates(std::vector<rl_common::State>(recent_.begin(), recent_.end()));
  lastIterations_ =
      planner->plan(s, config_.sweeps > 0 ? rl_common::PlanningBudget::ofRollouts(config_.sweeps)
                                          : rl_common::PlanningBudget{});
  planner->warmStartFrom(nullptr);
  last_ = std::move(planner);
  return last_->bestAction(s);
}

std::vector<double> TaskPhasePlanner::qValues(const rl_common::State& s) const {
  return last_ != nullptr ? last_->qValues(s) : std::vector<double>{};
}

}  // namespace rl_agent
