/**
 * The run folder on disk (std::filesystem): which files the runner writes there, making it,
 * listing it, trials.csv collected from the finished trials' summaries, and what keeps a run
 * from resuming.
 */
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace rl_experiment {

/// True for the files of a run folder the runner writes (run.csv, seeds.csv, trials.csv,
/// steps-/episodes-/accuracy-/groups-/trial-NNN.csv, journal-NNN.rlj): what --force removes
/// and what makes a folder "hold results".
bool isRunnerFile(const std::string& name);

/// The names of the entries of `folder`, sorted (none if it does not exist).
std::vector<std::string> listFiles(const std::string& folder);

/// Makes `folder` and its parents. Throws std::runtime_error if it exists and is not a folder,
/// or cannot be made.
void makeRunFolder(const std::string& folder);

/// The summary row of a trial-NNN.csv file's text: (column, value) pairs (empty if the file
/// has no row).
std::vector<std::pair<std::string, std::string>> parseSummaryRow(const std::string& text);

/// The options whose values differ between a run's recorded configuration and the one given
/// now, both as name=value lines, as "name: recorded -> now", comma-separated (what a refused
/// --resume names).
std::string configurationDifference(const std::string& recorded, const std::string& now);

/// Rewrites FOLDER/trials.csv (atomically) from every trial-NNN.csv in `folder`.
void collectTrialSummaries(const std::string& folder);

}  // namespace rl_experiment
