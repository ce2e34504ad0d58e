/**
 * Model predictions as a table: what a learned model believes happens after each action in a
 * set of states, written as CSV so that a run's model can be read, plotted or compared with
 * another's (the agent node's `--model-predictions FILE`; a model rebuilt from a journal is
 * checked against one that learned online this way).
 *
 * One row per state and action:
 *
 *     s0,...,s<n-1>,action,known,reward,term_prob,next0,...,next<n-1>
 *
 * `next<j>` is feature j's predicted next value distribution, `value:probability` pairs joined
 * by spaces in the model's order: a factored model's per-feature distribution as it predicts
 * it, a tabular model's listed next states as their per-feature marginals. Floats are written
 * with 9 significant digits and probabilities with 17, so equal predictions give equal text and
 * any difference shows.
 */
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "rl_common/mdp_model.h"

namespace rl_agent {

/// Writes the CSV above for every state in `states` (in that order) and every action
/// 0..numActions-1. Throws std::invalid_argument if a state's length differs from the first's
/// or numActions < 1.
void writeModelPredictions(const rl_common::ModelView& view,
                           const std::vector<rl_common::State>& states, int numActions,
                           std::ostream& out);

/// The same into `path`, replacing it only once the whole table is written (a kill mid-write
/// leaves the previous file). Throws std::runtime_error naming the file if it cannot be written.
void saveModelPredictions(const rl_common::ModelView& view,
                          const std::vector<rl_common::State>& states, int numActions,
                          const std::string& path);

}  // namespace rl_agent
