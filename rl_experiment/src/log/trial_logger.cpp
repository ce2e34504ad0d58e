#include "rl_experiment/log/trial_logger.h"

#include <cmath>

#include <cstdio>

#include "rl_experiment/runner/agent_probe.h"

namespace rl_experiment {

namespace {

std::string numbered(const char* prefix, int trial) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%s-%03d.csv", prefix, trial);
  return buf;
}

std::string join(const std::string& folder, const std::string& file) {
  return folder.empty() ? file : folder + "/" + file;
}

}  // namespace

std::string TrialLogger::stepsFile(int trial) { return numbered("steps", trial); }
std::string TrialLogger::episodesFile(int trial) { return numbered("episodes", trial); }
std::string TrialLogger::accuracyFile(int trial) { return numbered("accuracy", trial); }
std::string TrialLogger::groupsFile(int trial) { return numbered("groups", trial); }
std::string TrialLogger::summaryFile(int trial) { return numbered("trial", trial); }

TrialLogger::TrialLogger(const std::string& folder, TrialInfo info, EvalSettings eval,
                         bool perStepStream, std::ostream* original)
    : folder_(folder),
      info_(std::move(info)),
      eval_(eval),
      perStepStream_(perStepStream),
      original_(original),
      evalRng_(info_.evalSeed) {
  if (folder_.empty()) return;
  steps_ = std::make_unique<CsvFile>(
      join(folder_, stepsFile(info_.trial)),
      std::vector<std::string>{"trial", "step", "phase", "episode", "action", "reward",
                               "reward_seen", "variance", "novelty", "other", "target", "terminal",
                               "planned_q", "q_spread"});
  episodes_ = std::make_unique<CsvFile>(
      join(folder_, episodesFile(info_.trial)),
      std::vector<std::string>{"trial", "episode", "phase", "steps", "reward", "terminal"});
}

void TrialLogger::beforeStep(const rl_common::Environment& env, long /*step*/, int action) {
  pendingTarget_ = locationOf(env, action);
  pendingKeyOnFloor_ = keyOnFloor(env);
  locations_.add(env, action);
}

namespace {
std::string value(double x) { return std::isnan(x) ? std::string() : formatNumber(x); }
}  // namespace

void TrialLogger::onStep(const StepRecord& r) {
  if (steps_) {
    const std::string t = std::to_string(info_.trial);
    steps_->row({t, std::to_string(r.step), phaseName(r.phase), std::to_string(r.episode),
                 std::to_string(r.action), formatNumber(r.reward), formatNumber(r.rewardSeen),
                 r.hasBreakdown ? formatNumber(r.variance) : "",
                 r.hasBreakdown ? formatNumber(r.novelty) : "",
                 r.hasBreakdown ? formatNumber(r.other) : "", locationName(pendingTarget_),
                 r.terminal ? "1" : "0", r.hasBreakdown ? value(r.plannedValue) : "",
                 r.hasBreakdown ? value(r.valueSpread) : ""});
  }
  pendingTarget_ = Location::kNone;
  if (pendingKeyOnFloor_ && r.phase == Phase::kExplore) {
    exploreKeyOnFloor_ = exploreKeyOnFloor_.value_or(0) + (*pendingKeyOnFloor_ ? 1 : 0);
  }
  pendingKeyOnFloor_.reset();
  if (original_ != nullptr && perStepStream_) *original_ << r.reward << "\n";
}

void TrialLogger::onEpisode(const EpisodeRecord& r) {
  if (episodes_) {
    episodes_->row({std::to_string(info_.trial), std::to_string(r.episode), phaseName(r.phase),
                    std::to_string(r.steps), formatNumber(r.reward), r.terminal ? "1" : "0"});
  }
  if (original_ != nullptr && !perStepStream_) *original_ << r.reward << std::endl;
}

void TrialLogger::onCheckpoint(long stepsDone, Phase phase, const rl_common::Agent& agent,
                               const rl_common::Environment& env) {
  const auto* truth = dynamic_cast<const rl_common::TrueModel*>(&env);
  if (truth == nullptr) return;
  const auto model = learnedModelOf(agent);
  if (model == nullptr) return;
  if (!evaluatorTried_) {
    evaluatorTried_ = true;
    evaluator_ = std::make_unique<ModelAccuracy>(*truth, env.numActions());
    if (!folder_.empty()) {
      // Joint distance, then each feature's marginal and the joint per action (diagnosis).
      std::vector<std::string> header{"trial", "step", "phase", "variational_distance", "samples"};
      const std::size_t d = env.sensation().size();
      for (std::size_t j = 0; j < d; ++j) header.push_back("marginal_f" + std::to_string(j));
      for (int a = 0; a < env.numActions(); ++a) header.push_back("action_" + std::to_string(a));
      accuracy_ = std::make_unique<CsvFile>(join(folder_, accuracyFile(info_.trial)), header);
      if (!eval_.groupBy.empty()) {
        groups_ =
            std::make_unique<CsvFile>(join(folder_, groupsFile(info_.trial)),
                                      std::vector<std::string>{"trial", "step", "phase", "group",
                                                               "samples", "variational_distance"});
      }
    }
  }
  if (!evaluator_) return;
  const ModelAccuracy::Report report =
      evaluator_->evaluateDetailed(*model, evalRng_, eval_.samples, eval_.groupBy);
  lastAccuracy_ = report.joint;
  if (accuracy_) {
    std::vector<std::string> row{std::to_string(info_.trial), std::to_string(stepsDone),
                                 phaseName(phase), formatNumber(report.joint),
                                 std::to_string(eval_.samples)};
    for (double m : report.marginal) row.push_back(formatNumber(m));
    for (double a : report.perAction) row.push_back(value(a));
    accuracy_->row(row);
  }
  if (groups_) {
    for (const auto& [name, g] : report.groups) {
      groups_->row({std::to_string(info_.trial), std::to_string(stepsDone), phaseName(phase), name,
                    std::to_string(g.second), formatNumber(g.first / g.second)});
    }
  }
}

std::vector<std::pair<std::string, std::string>> TrialLogger::finish(const TrialSummary& s,
                                                                     double seconds,
                                                                     long peakRssKb) {
  if (original_ != nullptr) original_->flush();
  std::vector<std::pair<std::string, std::string>> row = {
      {"trial", std::to_string(info_.trial)},
      {"label", info_.label},
      {"agent", info_.agent},
      {"env", info_.env},
      {"agent_seed", std::to_string(info_.agentSeed)},
      {"env_seed", std::to_string(info_.envSeed)},
      {"eval_seed", std::to_string(info_.evalSeed)},
      {"steps", std::to_string(s.steps)},
      {"episodes", std::to_string(s.episodes)},
      {"total_reward", formatNumber(s.totalReward)},
      {"explore_reward", formatNumber(s.exploreReward)},
      {"task_reward", formatNumber(s.taskReward)},
      {"final_accuracy", lastAccuracy_ ? formatNumber(*lastAccuracy_) : ""},
  };
  for (int kind = 0; kind < 2; ++kind) {
    for (int l = 1; l < kNumLocations; ++l) {
      row.emplace_back(
          std::string(kind == 0 ? "press_" : "pickup_") + locationName(static_cast<Location>(l)),
          std::to_string(locations_.counts[kind][l]));
    }
  }
  row.emplace_back("explore_key_on_floor",
                   exploreKeyOnFloor_ ? std::to_string(*exploreKeyOnFloor_) : std::string());
  row.emplace_back("seconds", formatNumber(seconds));
  row.emplace_back("steps_per_second", formatNumber(seconds > 0 ? s.steps / seconds : 0.0));
  row.emplace_back("peak_rss_mb", formatNumber(peakRssKb / 1024.0));
  if (!folder_.empty()) {
    std::vector<std::string> names, values;
    for (const auto& [n, v] : row) {
      names.push_back(n);
      values.push_back(v);
    }
    writeFileAtomically(join(folder_, summaryFile(info_.trial)), csvLine(names) + csvLine(values));
  }
  return row;
}

}  // namespace rl_experiment
