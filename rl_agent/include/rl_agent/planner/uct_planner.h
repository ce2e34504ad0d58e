/**
 * UctPlanner: TEXPLORE's UCT(λ) planner (the original's ETUCT), rollouts on a learned model.
 *
 * UCT (Kocsis & Szepesvári, "Bandit based Monte-Carlo planning", ECML 2006) as modified by
 * TEXPLORE (Hester & Stone, "TEXPLORE: real-time sample-efficient reinforcement learning for
 * robots", Machine Learning 90(3), 2013, Alg. 3). Each rollout starts at the root state and
 * samples its way through the model (a ModelView) for at most `maxDepth` actions (the
 * original's `depth > MAX_DEPTH` test allowed one more):
 *
 *   action      a = argmax_a Q(s,a) + B·2·sqrt(ln N(s) / N(s,a)),  B = max(R_range,1)/(1−γ)
 *               (ties broken at random; the original takes the first maximum)
 *   outcome     r = the model's reward (intrinsic bonuses included); terminal with
 *               probability termProb; s' ~ transitions. A successor with a feature outside
 *               [featMin−ε, featMax+ε] (or not finite) is replaced by the current state.
 *   backup      α = 10/(N(s,a)+10);  terminal: Q(s,a) += α(r − Q(s,a)), return r;
 *               otherwise q = r + γ·G(s'), Q(s,a) += α(q − Q(s,a)) and N(s)++, N(s,a)++ only at
 *               the first occurrence of s on the rollout's path, and
 *               G(s) = λ·q + (1−λ)·max_a Q(s,a)  (λ = 1: Monte-Carlo return, λ = 0: one-step
 *               backup of max Q). At the depth cap G = max_a Q(s,a).
 *
 * Records are keyed by the (optionally discretised) state followed, with an action history of
 * k actions, by the k one-hot action codes (oldest first); that key is also the model's query
 * input. Q starts U(0, 0.01), N(s) and N(s,a) start at 1. Discretisation is the original's
 * DiscretizationAgent binning: factor = (max−min)/n, bin = int((s ± factor/2)/factor) (+ for
 * s > 0), ds = factor·bin. With trackActual and discretisation, the rollout carries the
 * continuous state: s'_actual = s_actual + (s' − disc(s)).
 *
 * Selection at a state met again on the same rollout (countPathVisits, off by default) counts
 * the actions already chosen there on this rollout: N(s) + k and N(s,a) + k_a, for k_a
 * choices of a on the path so far (k their sum). The original counted only when the rollout
 * returned, so a repeated state chose the same action again; a self-loop (PICKUP off the
 * key, a step into a wall) then repeated to the depth cap. With the UCB constant making
 * selection nearly uniform, about a third of LightWorld's actions are self-loops, so most
 * rollouts stopped moving within two or three steps, the planner could not see novelty further
 * away, and TEXPLORE-VANIR stayed put; the first visit of a state is selected as before.
 *
 * setModel() starts a new model version: each record's counts are capped lazily, when the
 * record is next touched, at N(s,a) ≤ 10 and N(s) ≤ 10·A, and each cached model prediction is
 * refreshed lazily when next used (ModelView::refresh(): a learned model re-reads only its
 * parts that changed; the values are those of a new query). Unlike the original, memory is bounded,
 * at O(1) cost per step: a new record beyond `maxStates` evicts the least recently visited record
 * (never one on the current rollout), and beyond `maxCachedPredictions` cached predictions, the
 * record whose predictions were used least recently loses them.
 *
 * Deterministic: every random draw comes from the planner's own rl_common::Random, so the same
 * seed, model and calls give the same values and actions. Not thread-safe: callers serialise
 * all calls (RealTimePlanner does so with a mutex); the ModelView is only read.
 */
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "rl_agent/planner/state_grid.h"
#include "rl_agent/planner/state_hash.h"
#include "rl_agent/planner/state_index.h"
#include "rl_common/mdp_model.h"
#include "rl_common/planner.h"
#include "rl_common/random.h"

namespace rl_agent {

class UctPlanner : public rl_common::Planner {
 public:
  /// How the UCB term is weighed against Q.
  enum class UcbBound {
    /// The original's Q + B·2·sqrt(ln N(s)/N(s,a)), B = max(R_range,1)/(1−γ): the bound of a
    /// return that can reach R_range on every step.
    Range,
    /// (Q − min_a Q)/(max_a Q − min_a Q) + c·sqrt(ln N(s)/N(s,a)): Q normalised by the
    /// state's own Q range (the min-max normalisation of MuZero, Schrittwieser et al., Nature
    /// 588, 2020), so the search concentrates on the best actions whatever the scale of the
    /// rewards. With intrinsic rewards of order 0.01–1 the Range bound is hundreds of times
    /// the Q differences and selection is uniform.
    Normalized,
  };
  struct Config {
    int numActions = 0;        ///< A, at least 1
    double gamma = 0.99;       ///< discount, in [0, 1)
    double lambda = 0.1;       ///< return mixing λ, in [0, 1]
    double rewardRange = 1.0;  ///< R_max − R_min of the task, for the UCB constant
    int maxDepth = 200;        ///< at most this many simulated actions per rollout (≥ 1)
    /// Declared feature ranges (both empty, or one entry per state feature). Needed for
    /// discretisation; when given, successors outside the range are replaced by the state.
    std::vector<float> featMin;
    std::vector<float> featMax;
    /// Bins per feature (empty: no discretisation; one entry: every feature; 0: that feature
    /// stays continuous).
    std::vector<int> statesPerDim;
    int history = 0;                ///< k, the number of past actions in the key and model input
    bool trackActual = true;        ///< carry the continuous state through discretised rollouts
    float rangeEpsilon = 1e-5f;     ///< tolerance of the feature range check
    std::size_t maxStates = 25000;  ///< state records kept (least recent evicted)
    std::size_t maxCachedPredictions = 15000;  ///< cached model predictions (state-actions)
    /// At a state met again on the same rollout, count the actions already chosen there on
    /// this rollout in the UCB term. The original's counts change only when the rollout
    /// returns, so at a repeated state it chose the same action again: one self-loop (PICKUP
    /// off the key, a step into a wall) then repeated to the depth cap, and rollouts rarely
    /// got further than the first self-loop (see the comment at the top). false: as the
    /// original (the default, for faithfulness). The first visit of a state on a rollout is
    /// the same either way. The agents' --pathvisits.
    bool countPathVisits = false;
    /// A rollout collects a state-action's intrinsic bonus (variance, novelty, other) only the
    /// first time it takes that action at that state; a repeat earns the external reward
    /// only. The original collects it on every repeat, so a self-loop whose trees disagree
    /// (PICKUP away from the key) is worth bonus/(1−γ), a hundred times a bonus elsewhere,
    /// and a search that follows its values sits on the self-loop. false: as the original.
    bool bonusOncePerPath = false;
    /// Rollouts sample each feature of a factored prediction only among its values of at
    /// least this probability (renormalised; the most likely value if none is). A forest that
    /// is unsure puts a little mass on values one tree predicts, and sampling the 17 features
    /// independently then produces imagined states that no tree predicts and that cannot
    /// occur, which are novel and uncertain in turn; the variance bonus already pays for the
    /// disagreement at the state-action itself. 0: sample every value (the original).
    double minOutcomeProbability = 0.0;
    UcbBound ucbBound = UcbBound::Range;  ///< the original's bound by default
    double ucbC = 1.0;                    ///< c of the Normalized bound (≥ 0)
  };

  /// Throws std::invalid_argument, naming the option, if the configuration is invalid.
  UctPlanner(const Config& config, std::uint64_t seed);
  // Records link to each other: neither copyable nor movable.
  UctPlanner(const UctPlanner&) = delete;
  UctPlanner& operator=(const UctPlanner&) = delete;

  /// Plans on `model` from now on: a new model version (counts capped, predictions stale).
  /// Throws std::invalid_argument if `model` is null.
  void setModel(std::shared_ptr<const rl_common::ModelView> model) override;

  /// Runs rollouts from `s` (a state, not discretised) and the current action history until
  /// the budget is spent (at least one rollout); returns the number of rollouts. Throws
  /// std::runtime_error without a model, std::invalid_argument for a bad state or a budget
  /// with neither a rollout limit nor a deadline.
  long plan(const rl_common::State& s, const rl_common::PlanningBudget& budget) override;

  /// The greedy action in `s` with the current action history: random among actions whose Q
  /// is within 1e-4 of the best; a uniformly random action if `s` was never planned from.
  int bestAction(const rl_common::State& s) override;

  /// Switches the UCB bound (and the Normalized bound's c) for the next rollouts, e.g. when the
  /// agent moves from exploring to a task. Throws std::invalid_argument for c < 0 or not finite.
  void setUcbBound(UcbBound bound, double c);

  /// Sets the last k actions taken (oldest first), the history of the root of the next
  /// plan() and bestAction() calls. Fewer than k actions: the missing oldest ones are "none"
  /// (an all-zero code). Throws std::invalid_argument for an action out of range or more than
  /// k actions.
  void setActionHistory(const std::vector<int>& lastActions);
  /// The current root history: k entries, oldest first, −1 for "none".
  const std::vector<int>& actionHistory() const { return rootHistory_; }

  /// `s` binned as the planner bins it (a copy of `s` without discretisation).
  rl_common::State discretize(const rl_common::State& s) const;
  /// The model's query input (and record key) for `s` with the current action history.
  rl_common::State modelInput(const rl_common::State& s) const;

  /// Q(s, ·) with the current action history; empty if `s` has no record.
  std::vector<double> qValues(const rl_common::State& s) const override;
  /// N(s) (counts as capped by the latest model version); 0 if `s` has no record.
  long stateVisits(const rl_common::State& s) const;
  /// N(s, a), as stateVisits(); 0 if `s` has no record.
  long actionVisits(const rl_common::State& s, int action) const;

  /// Calls f(key, Q, N) for every record, in no particular order: key is the record's
  /// modelInput() (the possibly discretised state, then k·A action-history codes), Q its
  /// action values and N its state visits as stateVisits() gives them.
  void forEachRecord(const std::function<void(const rl_common::State& key,
                                              const std::vector<double>& q, long visits)>& f) const;

  /// Number of state records.
  std::size_t numStates() const { return index_.size(); }
  /// Number of cached model predictions.
  std::size_t numCachedPredictions() const { return cachedPredictions_; }
  /// Number of setModel() calls so far.
  std::uint64_t modelVersion() const { return modelVersion_; }
  const Config& config() const { return config_; }

  /// Per-record cap of N(s,a) on a model change (the original's MIN_VISITS).
  static constexpr long kVisitCap = 10;
  /// Greedy ties: actions within this of the best value are equally good.
  static constexpr double kTieTolerance = 1e-4;

 private:
  struct Prediction {
    rl_common::StateActionInfo info;
    rl_common::PredictionStamp stamp;  // what the view needs to refresh info
    std::uint64_t version = 0;         // 0: not cached
  };
  struct Record;
  /// Links of an intrusive doubly-linked list of records (most recent first).
  struct Links {
    Record* prev = nullptr;
    Record* next = nullptr;
  };
  struct List {
    Record* head = nullptr;
    Record* tail = nullptr;
  };
  struct Record {
    std::vector<double> q;
    std::vector<long> actionVisits;
    long visits = 1;
    std::uint64_t version = 0;            // model version whose count cap has been applied
    std::uint64_t lastTouched = 0;        // rollout stamp: records of the current rollout stay
    int onPath = 0;                       // occurrences on the current rollout's path
    std::vector<int> pathChosen;          // per action: chosen on the path (trackPath_)
    int cached = 0;                       // predictions cached (version != 0)
    std::vector<Prediction> predictions;  // empty, or A entries
    rl_common::State key;                 // the record's key (the model's query input)
    std::uint64_t hash = 0;               // StateHash of key
    std::uint32_t slot = 0;               // index in records_
    bool live = false;                    // false: a free slot
    Links recent;                         // in recent_: every record
    Links cachedRecent;                   // in cachedRecent_: records with cached > 0
  };

  struct Step {
    Record* record;
    int action;
    double reward;
    double alpha;
    bool terminal;
    bool first;
  };

  void rollout(const rl_common::State& root);
  /// Resets the path marks (onPath, pathChosen) of the records on the current rollout.
  void clearPath();
  void sampleSuccessor(const rl_common::StateActionInfo& info);
  bool inRange(const rl_common::State& s) const;
  /// One value of `dist` among those of probability >= minOutcomeProbability.
  float samplePlausible(const rl_common::FeatureDistribution& dist);
  void appendDiscretized(const rl_common::State& s, rl_common::State& out) const;
  void buildKey(const rl_common::State& actual, const std::vector<int>& history,
                rl_common::State& key) const;
  Record& touch(const rl_common::State& key);
  const Record* find(const rl_common::State& s, const char* where) const;
  int selectUcbAction(const Record& r);
  const rl_common::StateActionInfo& prediction(Record& r, const rl_common::State& key, int action);
  void evictRecord(Record& r);
  void dropPredictions(Record& r);
  static void unlink(List& list, Links Record::*links, Record& r);
  static void pushFront(List& list, Links Record::*links, Record& r);
  void validateState(const rl_common::State& s, const char* where) const;
  long cappedVisits(const Record& r) const;
  long cappedActionVisits(const Record& r, int action) const;
  static double maxQ(const Record& r);

  Config config_;
  rl_common::Random rng_;
  double ucbConstant_;  // B·2
  StateGrid grid_;      ///< statesPerDim's bins (precomputed widths)
  bool discretising_ = false;
  bool trackPath_ = false;  ///< pathChosen is kept (countPathVisits or bonusOncePerPath)
  std::shared_ptr<const rl_common::ModelView> model_;
  std::uint64_t modelVersion_ = 0;
  std::uint64_t stamp_ = 0;
  // The records, in slots that are reused after an eviction (a deque: addresses stay valid),
  // and the hash index over their keys.
  std::deque<Record> records_;
  std::vector<std::uint32_t> freeSlots_;
  StateIndex index_;
  List recent_;        // every record, most recently touched first
  List cachedRecent_;  // records holding predictions, most recently used first
  std::size_t cachedPredictions_ = 0;
  std::vector<int> rootHistory_;

  // Scratch space reused across rollouts.
  std::vector<Step> path_;
  rl_common::State key_, actual_, next_;
  std::vector<int> history_;
  std::vector<double> values_;
};

}  // namespace rl_agent
