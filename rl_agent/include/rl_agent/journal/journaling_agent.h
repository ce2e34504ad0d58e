/**
 * JournalingAgent: an agent that appends every experience it learns from to an experience
 * journal (experience_journal.h) before passing it on to the agent it wraps, so the journal
 * always holds at least what the agent learned. Seed experiences are passed on but not
 * journaled: the environment sends them again to a restarted agent.
 *
 * A step is the experience (previous state, its action, the reward, the new state, false);
 * an episode's end is (previous state, its action, the reward, previous state, true), as the
 * agents learn it.
 */
#pragma once

#include <memory>
#include <vector>

#include "rl_agent/journal/experience_journal.h"
#include "rl_common/agent.h"

namespace rl_agent {

class JournalingAgent : public rl_common::Agent {
 public:
  /// Throws std::invalid_argument for a null agent or journal.
  JournalingAgent(std::unique_ptr<rl_common::Agent> inner,
                  std::shared_ptr<ExperienceJournalWriter> journal);

  int firstAction(const rl_common::State& s) override;
  int nextAction(float reward, const rl_common::State& s) override;
  void lastAction(float reward) override;
  void seedExperiences(const std::vector<rl_common::Experience>& seeds) override;
  void savePolicy(const std::string& filename) override { inner_->savePolicy(filename); }

  /// The wrapped agent (for its other interfaces, e.g. the reward breakdown).
  rl_common::Agent& inner() { return *inner_; }
  const rl_common::Agent& inner() const { return *inner_; }

 private:
  std::unique_ptr<rl_common::Agent> inner_;
  std::shared_ptr<ExperienceJournalWriter> journal_;
  rl_common::State last_;
  int lastAction_ = -1;
};

}  // namespace rl_agent
