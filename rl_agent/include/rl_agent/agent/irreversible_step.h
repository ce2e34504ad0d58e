#pragma once
// One-way (irreversible) steps learned from the agent's own steps, and an explorer that defers
// them.
//
// On LightWorld, picking the key up ends what the agent can learn about the key's sensors in
// that room (docs/science/lightworld-curiosity.md §2.1): a random walk that leaves the key on
// the floor for its first 300 steps learns a model 0.066 more accurate than one that does not,
// twice VANIR's lead over random actions. None of the paper's bonuses sees that a step cannot
// be undone, and novelty pulls the agent into the region behind it.
//
// `StepDeferral` learns which steps are one-way from the agent's own steps. A real step that
// changed at least 3 features the learned model predicts no action to give back (one step of
// lookahead) is a candidate, unless the old values of those features held in most of the
// states before it (then they do not say where the step happens: a closed door's lights read 0
// everywhere); when no real step undid it for 100 steps and the model still cannot undo it, it
// becomes a rule: its action, where its features hold their old values, is one-way. For a number of
// steps after each one-way step (and after the start), the region the agent is in is explored
// first: the planner's model ends an imagined one-way step with no reward (`DeferringView`), and a
// real one-way action is replaced by the best other action. Measured in
// docs/science/lightworld-curiosity.md §4.1. Keeping track of reversibility while exploring is the
// idea of safe exploration (Moldovan & Abbeel, "Safe Exploration in Markov Decision Processes",
// ICML 2012) and of "Leave No Trace" (Eysenbach et al., ICLR 2018); the test and the rules here are
// ours.
#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <vector>

#include "rl_common/mdp_model.h"
#include "rl_common/random.h"

namespace rl_agent {

/// The features that going from `from` to `to` changed and that no action from `to` is
/// predicted to give back their old value (with probability at least 0.05). One step of
/// lookahead: a change that takes two steps to undo counts as one-way, which only defers it.
/// Empty when the model has no data for some action from `to`.
std::vector<std::size_t> unrestorableFeatures(const rl_common::ModelView& model,
                                              const rl_common::State& from,
                                              const rl_common::State& to, int numActions);

/// One recorded one-way step: the action, and the features it changed for good with their old
/// and new values. It is a rule learned from one real step: the action, taken where those
/// features hold their old values, does it again (in LightWorld: PICKUP standing on a key, in
/// any room). Keyed on the action and the old values, not on the model's prediction: one
/// pickup teaches the forest too little to predict the next room's.
struct OneWaySignature {
  struct Change {
    std::size_t feature;
    float from;
    float to;
    bool operator==(const Change& o) const {
      return feature == o.feature && from == o.from && to == o.to;
    }
  };
  int action = -1;
  std::vector<Change> changes;

  /// True if `s` holds the old values of more than half of its features.
  bool matches(const rl_common::State& s) const;
  /// True if `a` is this step's action and matches(s).
  bool appliesTo(const rl_common::State& s, int a) const { return a == action && matches(s); }
  bool operator==(const OneWaySignature& o) const {
    return action == o.action && changes == o.changes;
  }
};

/// A planner's model that ends, with no reward, every imagined step making a recorded one-way
/// change: a search on it explores the region it is in instead of planning to leave it.
class DeferringView : public rl_common::ModelView {
 public:
  DeferringView(std::shared_ptr<const rl_common::ModelView> base,
                std::shared_ptr<const std::vector<OneWaySignature>> signatures);
  rl_common::StateActionInfo query(const rl_common::State& input, int action) const override;
  /// The base view's refresh() where no one-way step applies; where one does, a query whose
  /// stamp is cleared (the ended step's info is not the base's, so nothing of it is reused).
  void refresh(const rl_common::State& input, int action, rl_common::StateActionInfo& info,
               rl_common::PredictionStamp& stamp) const override;

 private:
  /// The signature that ends (input, action), or null.
  const OneWaySignature* applying(const rl_common::State& input, int action) const;
  /// Ends the step: terminal, no reward.
  static void end(rl_common::StateActionInfo& info);
  std::shared_ptr<const rl_common::ModelView> base_;
  std::shared_ptr<const std::vector<OneWaySignature>> signatures_;
};

/// Defers one-way steps for the first `steps` steps after each one-way step the agent made
/// (and after the start of an episode). With `maxRegions` > 0 it defers in the first
/// `maxRegions` regions only: a region is counted when one begins at a one-way step, at a known
/// one-way step made or at a confirmed one (not at an episode's start). On LightWorld, 2 puts
/// off the key in the second room and nothing after (docs/science/lightworld-curiosity.md §7).
class StepDeferral {
 public:
  explicit StepDeferral(long steps, long maxRegions = 0);

  /// Call once per real step, with the previous state (empty at the start of an episode), the
  /// action taken there and the current state, on the model that has learned the step. A step the
  /// model cannot undo is a candidate; it becomes a signature when no real step undid it (more than
  /// half of its changes reversed) for kConfirmSteps steps and the model, which has learned more by
  /// then, still cannot undo it: early on, a model that knows little takes every move for one-way.
  /// Also forgets signatures a real step undid, and counts the steps since the last one-way
  /// step.
  void observe(const rl_common::ModelView& model, const rl_common::State& previous, int action,
               const rl_common::State& current, int numActions);

  /// True while one-way steps are put off: the region's steps last and some are known.
  bool active() const {
    return inRegion_ < steps_ && !signatures_->empty() &&
           (maxRegions_ == 0 || regions_ <= maxRegions_);
  }

  /// `base` wrapped in a DeferringView while active(), else `base`.
  std::shared_ptr<const rl_common::ModelView> planningView(
      std::shared_ptr<const rl_common::ModelView> base) const;

  /// What planningView() does, as a function that owns what it reads (for another thread); null
  /// while not active().
  std::function<
      std::shared_ptr<const rl_common::ModelView>(std::shared_ptr<const rl_common::ModelView>)>
  viewFilter() const;
  /// Changes whenever planningView() would wrap differently (for a caller that re-wraps only then).
  const void* planningKey() const { return active() ? signatures_.get() : nullptr; }

  /// True if `action` from `s` is a recorded one-way step.
  bool oneWay(const rl_common::State& s, int action) const;

  /// The action to take instead of `chosen` from `s`: while active(), when `chosen` is a
  /// one-way step, the highest-valued action of `q` that is not (ties drawn from `rng`, which
  /// is drawn from only then); otherwise `chosen`, as also when every action is one-way.
  int choose(const rl_common::State& s, int chosen, const std::vector<double>& q,
             rl_common::Random& rng);

  long steps() const { return steps_; }
  long stepsInRegion() const { return inRegion_; }
  long regions() const { return regions_; }    ///< regions begun so far (see the constructor)
  long deferred() const { return deferred_; }  ///< real actions replaced so far
  const std::vector<OneWaySignature>& signatures() const { return *signatures_; }

 private:
  /// Steps a candidate must stay undone (a room of LightWorld is crossed in about ten).
  static constexpr long kConfirmSteps = 100;
  static constexpr std::size_t kMaxCandidates = 256;
  struct Candidate {
    rl_common::State from, to;
    long step;
    OneWaySignature signature;
  };
  /// A one-way step changes an object and what senses it at once; fewer changes are a move
  /// whose way back a young model does not know yet (door sensors that just appeared).
  static constexpr std::size_t kMinChanges = 3;
  /// A rule must single out where its step happens: a pattern of old values that held in more
  /// than this share of the states before the step (a door's lights read 0 everywhere while it
  /// is closed) would put the action off everywhere.
  static constexpr double kMaxShare = 0.5;
  /// The states the share is measured on: those of the steps before a candidate.
  static constexpr std::size_t kPastStates = 100;

  long steps_;
  long maxRegions_;
  long step_ = 0;
  long inRegion_ = 0;
  long regions_ = 0;
  std::deque<Candidate> candidates_;
  std::deque<rl_common::State> past_;  ///< the last kPastStates states, oldest first
  long deferred_ = 0;
  /// Shared with the views handed out; replaced (never changed) when a signature is added.
  std::shared_ptr<const std::vector<OneWaySignature>> signatures_;
};

}  // namespace rl_agent
