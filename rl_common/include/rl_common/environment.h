/**
 * The Environment interface: the original package's episode protocol, ROS-free.
 *
 * An environment holds a current state (`sensation()`), applies one discrete action at a
 * time and returns its reward (`apply()`), says whether the state is terminal, and can be reset
 * to a start state. It also describes itself: number of actions, each feature's declared range,
 * the reward range, whether it is episodic, and optional seed experiences given to agents
 * before learning starts. Each environment owns its random source, seeded at construction.
 */
#pragma once

#include <string>
#include <vector>

#include "rl_common/experience.h"

namespace rl_common {

/// What an agent learns about a task before acting; mirrors rl_msgs/RLEnvDescription.
struct EnvironmentDescription {
  int numActions = 0;
  std::vector<float> minFeatures;  ///< declared minimum of each state feature
  std::vector<float> maxFeatures;  ///< declared maximum of each state feature
  float minReward = 0.0f;
  float maxReward = 0.0f;
  bool episodic = true;
  bool stochastic = true;
  std::string title;  ///< e.g. "Environment: LightWorld\n", as the original's description

  std::size_t numFeatures() const { return minFeatures.size(); }
  float rewardRange() const { return maxReward - minReward; }
};

class Environment {
 public:
  virtual ~Environment() = default;

  /// The current state.
  virtual const State& sensation() const = 0;
  /// Applies `action` (0 .. numActions()-1) and returns the reward. Throws
  /// std::out_of_range for an action outside that range.
  virtual float apply(int action) = 0;
  /// True if the current state ends the episode.
  virtual bool terminal() const = 0;
  /// Moves to a (possibly random) start state.
  virtual void reset() = 0;

  virtual int numActions() const = 0;
  /// Declared range of each feature: every state lies inside [min, max].
  virtual void getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const = 0;
  /// Declared range of the per-step reward.
  virtual void getMinMaxReward(float* min, float* max) const = 0;
  /// Episodic tasks end in terminal states; non-episodic ones run as one long episode.
  virtual bool isEpisodic() const { return true; }
  /// Transitions given to the agent before it acts (the original's getSeedings()).
  virtual std::vector<Experience> seedExperiences() const { return {}; }
  /// Human-readable name, used as the description's title.
  virtual std::string name() const = 0;
  /// Whether the dynamics are noisy (the --stochastic option).
  virtual bool isStochastic() const = 0;

  /// Everything an agent is told about this environment.
  EnvironmentDescription describe() const {
    EnvironmentDescription d;
    d.numActions = numActions();
    getMinMaxFeatures(&d.minFeatures, &d.maxFeatures);
    getMinMaxReward(&d.minReward, &d.maxReward);
    d.episodic = isEpisodic();
    d.stochastic = isStochastic();
    d.title = "Environment: " + name() + "\n";
    return d;
  }
};

}  // namespace rl_common
