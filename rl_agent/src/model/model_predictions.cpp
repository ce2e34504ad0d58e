#include "rl_agent/model/model_predictions.h"

#include <unistd.h>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

namespace rl_agent {

namespace {

std::string text(double x, int digits) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

/// Feature j's distribution of a prediction, in the model's order.
rl_common::FeatureDistribution featureDistribution(const rl_common::StateActionInfo& info,
                                                   std::size_t j) {
  if (!info.factored.empty())
    return j < info.factored.size() ? info.factored[j] : rl_common::FeatureDistribution{};
  // A tabular prediction lists whole next states: its per-feature marginals, values in order.
  std::map<float, double> marginal;
  for (const auto& [next, p] : info.transitions) {
    if (j < next.size()) marginal[next[j]] += p;
  }
  return {marginal.begin(), marginal.end()};
}

}  // namespace

void writeModelPredictions(const rl_common::ModelView& view,
                           const std::vector<rl_common::State>& states, int numActions,
                           std::ostream& out) {
  if (numActions < 1) {
    throw std::invalid_argument("writeModelPredictions(): numActions must be >= 1, got " +
                                std::to_string(numActions));
  }
  const std::size_t n = states.empty() ? 0 : states.front().size();
  for (std::size_t j = 0; j < n; ++j) out << 's' << j << ',';
  out << "action,known,reward,term_prob";
  for (std::size_t j = 0; j < n; ++j) out << ",next" << j;
  out << '\n';
  for (const auto& s : states) {
    if (s.size() != n) {
      throw std::invalid_argument("writeModelPredictions(): a state has " +
                                  std::to_string(s.size()) + " features, the first " +
                                  std::to_string(n));
    }
    for (int a = 0; a < numActions; ++a) {
      const rl_common::StateActionInfo info = view.query(s, a);
      for (float x : s) out << text(x, 9) << ',';
      out << a << ',' << (info.known ? 1 : 0) << ',' << text(info.reward, 9) << ','
          << text(info.termProb, 9);
      for (std::size_t j = 0; j < n; ++j) {
        out << ',';
        bool first = true;
        for (const auto& [value, p] : featureDistribution(info, j)) {
          out << (first ? "" : " ") << text(value, 9) << ':' << text(p, 17);
          first = false;
        }
      }
      out << '\n';
    }
  }
}

void saveModelPredictions(const rl_common::ModelView& view,
                          const std::vector<rl_common::State>& states, int numActions,
                          const std::string& path) {
  const std::string partial = path + ".partial-" + std::to_string(::getpid());
  {
    std::ofstream out(partial, std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write model predictions to '" + partial + "'");
    try {
      writeModelPredictions(view, states, numActions, out);
    } catch (...) {
      out.close();
      std::remove(partial.c_str());
      throw;
    }
    out.flush();
    if (!out) {
      out.close();
      std::remove(partial.c_str());
      throw std::runtime_error("writing model predictions to '" + partial + "' failed");
    }
  }
  std::error_code error;
  std::filesystem::rename(partial, path, error);
  if (error) {
    std::remove(partial.c_str());
    throw std::runtime_error("cannot move model predictions into '" + path +
                             "': " + error.message());
  }
}

}  // namespace rl_agent
