/**
 * TrialLogger: writes one trial's logs into a run folder as the trial happens, and its summary
 * when it ends. Files (NNN = the trial number, zero-padded):
 *
 *   steps-NNN.csv     trial,step,phase,episode,action,reward,reward_seen,variance,novelty,other,
 *                     target,terminal,planned_q,q_spread   (one line per step; target: where
 *                                              PRESS/PICKUP was tried, LightWorld only;
 *                                              planned_q: the planner's Q of the chosen action,
 *                                              q_spread: max - min Q at the state)
 *   episodes-NNN.csv  trial,episode,phase,steps,reward,terminal
 *   accuracy-NNN.csv  trial,step,phase,variational_distance,samples,marginal_f0..f(d-1),
 *                     action_0..action_(A-1)   (agents with a model, on environments with a
 *                                              true model: the joint distance, each feature's
 *                                              marginal, the joint per action)
 *   groups-NNN.csv    trial,step,phase,group,samples,variational_distance   (with
 *                     EvalSettings::groupBy: the joint distance per group of sampled states)
 *   trial-NNN.csv     the trial's summary (one header line, one row), written atomically at the
 *                     end: its presence marks the trial as finished.
 *
 * Every line is flushed as it is written. The original's bare-number stream (one reward per step
 * for non-episodic tasks, per episode otherwise) can be copied to a stream as well.
 */
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "rl_common/random.h"
#include "rl_experiment/eval/action_location.h"
#include "rl_experiment/eval/model_accuracy.h"
#include "rl_experiment/log/csv_file.h"
#include "rl_experiment/runner/trial_runner.h"

namespace rl_experiment {

/// Identity of a trial, written into its summary.
struct TrialInfo {
  int trial = 0;
  std::string label;  ///< the run's label (e.g. "texplore-vanir")
  std::string agent;
  std::string env;
  std::uint64_t agentSeed = 0;
  std::uint64_t envSeed = 0;
  std::uint64_t evalSeed = 0;
};

/// Accuracy evaluation settings.
struct EvalSettings {
  int samples = 5000;  ///< state-actions per evaluation
  /// Features whose values group the samples (groups-NNN.csv); empty: no groups.
  std::vector<int> groupBy;
};

class TrialLogger : public TrialObserver {
 public:
  /// Opens the trial's files in `folder` (an empty folder disables the files: the logger then
  /// only counts and, with `original`, prints). `original` receives the original's bare-number
  /// stream if not null.
  TrialLogger(const std::string& folder, TrialInfo info, EvalSettings eval, bool perStepStream,
              std::ostream* original = nullptr);

  void beforeStep(const rl_common::Environment& env, long step, int action) override;
  void onStep(const StepRecord& r) override;
  void onEpisode(const EpisodeRecord& r) override;
  void onCheckpoint(long stepsDone, Phase phase, const rl_common::Agent& agent,
                    const rl_common::Environment& env) override;

  /// Writes trial-NNN.csv atomically (no-op without a folder) and returns its row as
  /// name/value pairs.
  std::vector<std::pair<std::string, std::string>> finish(const TrialSummary& summary,
                                                          double seconds, long peakRssKb);

  const LocationCounts& locations() const { return locations_; }
  /// The last accuracy measured, if any.
  std::optional<double> lastAccuracy() const { return lastAccuracy_; }

  /// File names of trial `trial` in a run folder.
  static std::string stepsFile(int trial);
  static std::string episodesFile(int trial);
  static std::string accuracyFile(int trial);
  static std::string groupsFile(int trial);
  static std::string summaryFile(int trial);

 private:
  std::string folder_;
  TrialInfo info_;
  EvalSettings eval_;
  bool perStepStream_;
  std::ostream* original_;
  std::unique_ptr<CsvFile> steps_, episodes_, accuracy_, groups_;
  Location pendingTarget_ = Location::kNone;
  std::optional<bool> pendingKeyOnFloor_;
  std::optional<long> exploreKeyOnFloor_;  ///< exploration steps taken with the key on the floor
  LocationCounts locations_;
  rl_common::Random evalRng_;
  std::unique_ptr<ModelAccuracy> evaluator_;
  bool evaluatorTried_ = false;
  std::optional<double> lastAccuracy_;
};

}  // namespace rl_experiment
