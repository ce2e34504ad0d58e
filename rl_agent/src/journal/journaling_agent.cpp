#include "rl_agent/journal/journaling_agent.h"

#include <stdexcept>

namespace rl_agent {

JournalingAgent::JournalingAgent(std::unique_ptr<rl_common::Agent> inner,
                                 std::shared_ptr<ExperienceJournalWriter> journal)
    : inner_(std::move(inner)), journal_(std::move(journal)) {
  if (inner_ == nullptr || journal_ == nullptr) {
    throw std::invalid_argument("JournalingAgent: needs an agent and a journal");
  }
}

int JournalingAgent::firstAction(const rl_common::State& s) {
  lastAction_ = inner_->firstAction(s);
  last_ = s;
  return lastAction_;
}

int JournalingAgent::nextAction(float reward, const rl_common::State& s) {
  if (lastAction_ < 0) return inner_->nextAction(reward, s);  // the agent's own error
  journal_->append({last_, lastAction_, reward, s, false});
  lastAction_ = inner_->nextAction(reward, s);
  last_ = s;
  return lastAction_;
}

void JournalingAgent::lastAction(float reward) {
  if (lastAction_ >= 0) journal_->append({last_, lastAction_, reward, last_, true});
  lastAction_ = -1;
  inner_->lastAction(reward);
}

void JournalingAgent::seedExperiences(const std::vector<rl_common::Experience>& seeds) {
  inner_->seedExperiences(seeds);
}

}  // namespace rl_agent
