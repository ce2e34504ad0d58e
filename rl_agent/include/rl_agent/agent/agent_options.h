/**
 * Options of every agent: the original agent node's options and defaults (§3.1 of
 * shared/spec/ORIGINAL.md), one default each, and their command-line declaration.
 */
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rl_agent/learning_defaults.h"
#include "rl_common/option_parser.h"

namespace rl_agent {

struct AgentOptions {
  std::string agent = "texplore";      ///< registry name (--agent)
  std::uint64_t seed = 1;              ///< seed of the agent's own random source
  float gamma = defaults::kGamma;      ///< discount factor (--gamma, --discountfactor)
  float epsilon = defaults::kEpsilon;  ///< exploration rate of epsilon-greedy action selection
  float alpha = defaults::kAlpha;      ///< learning rate (qlearner, sarsa, dyna)
  float initialvalue = defaults::kInitialValue;  ///< initial Q-value (qlearner, sarsa, dyna)
  float actrate = 10.0f;                         ///< actions per second of the real-time agent (Hz)
  float lambda = defaults::kLambda;  ///< UCT(lambda) mixing, or Sarsa(lambda) trace decay
  int m = defaults::kKnownVisits;    ///< R-MAX visits before a state-action is known
  std::string model = "tree";        ///< model type
  std::string explore = "greedy";    ///< exploration type
  std::string combo = "best";        ///< forest combination
  std::string planner = "parallel-uct";
  int nmodels = 1;                      ///< trees per forest
  bool reltrans = true;                 ///< predict relative changes (--reltrans / --abstrans)
  float v = 0.0f;                       ///< VANIR variance coefficient (--v, --b)
  float n = 0.0f;                       ///< VANIR novelty coefficient (--n)
  std::string novelty = "stateaction";  ///< VANIR novelty: "stateaction" (original) or "state"
  int history = 0;                      ///< action-history length
  /// Bins per feature (--nstates): one count for every feature, as the original's option, or
  /// one per feature (a feature with 0 is not binned); {0}: no discretisation.
  std::vector<int> nstates{0};
  int k = 1000;          ///< Dyna model updates per step
  std::string filename;  ///< policy file (savedpolicy reads it; others write it at shutdown)
  long rollouts = 0;     ///< UCT rollouts per step, synchronously (0: real time at actrate)
  /// Real-time UCT: planning threads, each searching its own tree (root-parallel search);
  /// 0: one per core (the model thread beside them is idle most of the time).
  int searchthreads = 0;
  /// Boltzmann temperature (--explore boltzmann; 0.2 in the paper)
  float tau = defaults::kBoltzmannTau;
  /// UCT: count the path's choices at a state met again on a rollout (UctPlanner::Config::
  /// countPathVisits); off by default, as the original.
  bool pathvisits = false;
  /// UCT: intrinsic bonus once per state-action per rollout (UctPlanner::Config::
  /// bonusOncePerPath).
  bool bonusonce = false;
  float minprob = 0.0f;  ///< UctPlanner::Config::minOutcomeProbability
  /// While exploring, put off one-way steps for this many steps after each one (StepDeferral);
  /// 0: never, as the original (and the default since the separate forest: with it VANIR
  /// explores as well without the deferral, docs/science/lightworld-curiosity.md §12).
  long defer = 0;
  /// With the deferral, defer only in the first this many regions (StepDeferral's maxRegions);
  /// 0: in every region.
  long deferregions = 0;
  int depth = 200;  ///< UCT's rollout depth cap (the original's MAX_DEPTH)
  /// UCT's bound (UctPlanner::UcbBound): "range" (the original's) or "normalized".
  std::string ucb = "range";
  float ucbc = 1.0f;  ///< c of the normalized bound
  /// UCT's bound once intrinsic rewards are off (setIntrinsicEnabled(false)): "same" (--ucb),
  /// "range" or "normalized" (with taskucbc).
  std::string taskucb = "same";
  float taskucbc = 1.0f;
  /// The planner once intrinsic rewards are off (a task phase): "same" (--planner) or "vi"
  /// (value iteration over the states the learned model reaches from the visited ones).
  std::string taskplanner = "same";
  int taskdepth = 100;  ///< --taskplanner vi: model steps expanded from the current state
  /// --taskplanner vi: joint outcomes of the learned model below this probability are not
  /// planned through (StateSpacePlanner::Config::minTransitionProbability).
  float taskminprob = 0.1f;
  /// --taskplanner vi: value-iteration sweeps per task step (0: to convergence); the values
  /// carry over from step to step, so a cap spreads the solve over steps.
  long tasksweeps = 0;
  /// --taskplanner vi: the last this many observed states are roots and their entries'
  /// representatives (0: only the current state).
  int taskrecent = 50;
  /// --taskplanner vi: the features that tell the planner's states apart (empty: all).
  std::vector<int> taskkey;
  /// --taskplanner vi with --taskkey: the learned model's outcomes planned through are "key"
  /// (the key features' joint values, the others at their most likely values;
  /// StateSpacePlanner::Config::keyMarginal) or "joint" (full states, each a product over all
  /// features: the runs before this option). Without --taskkey every feature is a key.
  std::string taskoutcomes = "key";
  /// --taskplanner vi: how the forests combine their trees for the task phase's planning:
  /// "same" (--combo) or a --combo value (e.g. average: explore on tree 0 with --combo
  /// separate, then plan the task on the whole forest, whose spread keeps rare outcomes such
  /// as a door opening above --taskminprob).
  std::string taskcombo = "same";
};

/// True if --nstates bins some feature.
bool binsStates(const AgentOptions& options);

/// True if the options plan in real time: a model-based agent whose planner is real-time UCT,
/// without --rollouts (the only case that reads --searchthreads).
bool plansInRealTime(const AgentOptions& options);

/// The most planning threads --searchthreads takes.
constexpr int kMaxSearchThreads = 64;
/// --searchthreads resolved: the option, or one per core (at least 1) for 0.
int searchThreads(const AgentOptions& o);

/// Throws std::invalid_argument unless --nstates has one entry or `numFeatures` entries.
void checkStatesPerDim(const AgentOptions& options, std::size_t numFeatures);

/// Declares every agent option but --seed on `parser`, writing into `options`. Programs declare
/// --seed themselves: the agent node uses it as is, the experiment runner derives the agent's
/// and the environment's seeds from one run seed.
void addAgentOptions(rl_common::OptionParser& parser, AgentOptions* options);

/// Gives options the user did not set the defaults of the chosen agent (the original's
/// overrides, ORIGINAL.md §3.1): rmax plans with value iteration on a tabular model and
/// explores unknown state-actions; texplore uses 5-tree forests, relative transitions, the
/// real-time UCT planner, and variance-novelty exploration when --v or --n is given (greedy
/// otherwise). Unlike the original (--combo average), texplore's forests are separate (one full
/// tree plans, the forest gives the variance; best with --nmodels 1), and with --taskplanner vi
/// the task is planned on the forest's average (--taskcombo average). The competence and
/// prederror explorers weigh their bonus with --v, 1 unless given.
void applyAgentDefaults(const rl_common::OptionParser& parser, AgentOptions* options);

/// The original's option rules without its bugs: options apply only to the agents that use
/// them (e.g. --alpha for qlearner, sarsa, dyna; --v for the model-based agents); --epsilon is
/// accepted by every agent that acts epsilon-greedily; --combo other than best needs more than
/// one tree; rmax needs a tabular model and --explore unknown; an explorer's own options (--v,
/// --n, --novelty, --tau, --epsilon for model-based agents) need an explorer whose registry
/// entry reads them (e.g. --tau: boltzmann); the tabular model takes the explorers greedy,
/// epsilongreedy, random, boltzmann and unknown, the m5tree model the first four. Throws
/// rl_common::OptionError naming the option and where it applies.
void checkAgentOptions(const rl_common::OptionParser& parser, const AgentOptions& options);

}  // namespace rl_agent
