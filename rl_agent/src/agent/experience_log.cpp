#include "rl_agent/agent/experience_log.h"

#include <stdexcept>
#include <string>

namespace rl_agent {

void ExperienceLog::record(bool on) {
  if (on && !recording_ && learned_ > 0) {
    throw std::logic_error("ModelBasedAgent::recordExperiences(): " + std::to_string(learned_) +
                           " experiences were learned before recording started");
  }
  recording_ = on;
}

void ExperienceLog::addStep(const rl_common::Experience& e) {
  ++learned_;
  if (!recording_) return;
  entries_.push_back({e, true});
  ++steps_;
}

void ExperienceLog::addSeeds(const std::vector<rl_common::Experience>& seeds) {
  learned_ += seeds.size();
  if (!recording_) return;
  for (const auto& e : seeds) entries_.push_back({e, false});
}

std::vector<rl_common::Experience> ExperienceLog::relabel(const std::vector<float>& rewards) {
  if (!recording_) {
    throw std::logic_error(
        "ModelBasedAgent::relabelRewards(): experiences were not recorded "
        "(recordExperiences(true) before the first experience)");
  }
  if (rewards.size() != steps_) {
    throw std::invalid_argument(
        "ModelBasedAgent::relabelRewards(): " + std::to_string(rewards.size()) + " rewards for " +
        std::to_string(steps_) + " recorded steps");
  }
  std::vector<rl_common::Experience> replay;
  replay.reserve(entries_.size());
  std::size_t next = 0;
  for (auto& entry : entries_) {
    if (entry.step) entry.experience.reward = rewards[next++];
    replay.push_back(entry.experience);
  }
  return replay;
}

}  // namespace rl_agent
