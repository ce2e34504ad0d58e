// The model-predictions table (--model-predictions): its exact text for factored, tabular and
// unknown predictions, its errors, and a save that never leaves a half-written file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>

#include "rl_agent/model/model_predictions.h"

using namespace rl_agent;
using rl_common::State;
using rl_common::StateActionInfo;

namespace {

/// Action 0: factored; action 1: three listed next states; state {9, 9}: nothing known.
class FixedView : public rl_common::ModelView {
 public:
  bool throwOnQuery = false;
  StateActionInfo query(const State& s, int a) const override {
    if (throwOnQuery) throw std::runtime_error("view failed");
    StateActionInfo info;
    if (s == State{9.0f, 9.0f}) return info;
    info.known = true;
    info.reward = 0.25f * static_cast<float>(a + 1);
    info.termProb = a == 1 ? 0.5f : 0.0f;
    if (a == 0) {
      info.factored = {{{s[0], 0.75}, {s[0] + 1.0f, 0.25}}, {{s[1], 1.0}}};
    } else {
      info.transitions = {{{2.0f, 1.0f}, 0.5}, {{1.0f, 1.0f}, 0.25}, {{2.0f, 0.0f}, 0.25}};
    }
    return info;
  }
};

std::string textOf(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

TEST(ModelPredictions, OneRowPerStateAndActionWithEachFeaturesDistribution) {
  std::ostringstream out;
  writeModelPredictions(FixedView(), {{1.0f, 3.5f}, {9.0f, 9.0f}}, 2, out);
  EXPECT_EQ(out.str(),
            "s0,s1,action,known,reward,term_prob,next0,next1\n"
            "1,3.5,0,1,0.25,0,1:0.75 2:0.25,3.5:1\n"
            // the listed next states' marginals, values in increasing order
            "1,3.5,1,1,0.5,0.5,1:0.25 2:0.75,0:0.25 1:0.75\n"
            "9,9,0,0,0,0,,\n"
            "9,9,1,0,0,0,,\n");
}

TEST(ModelPredictions, ProbabilitiesKeepEveryDigit) {
  class Third : public rl_common::ModelView {
    StateActionInfo query(const State&, int) const override {
      StateActionInfo info;
      info.known = true;
      info.factored = {{{0.1f, 1.0 / 3.0}, {0.2f, 2.0 / 3.0}}};
      return info;
    }
  };
  std::ostringstream out;
  writeModelPredictions(Third(), {{0.0f}}, 1, out);
  // 17 digits give back the double; 9 the float.
  EXPECT_NE(out.str().find("0.100000001:0.33333333333333331 0.200000003:0.66666666666666663"),
            std::string::npos)
      << out.str();
}

TEST(ModelPredictions, RefusesStatesOfDifferentLengthsAndNoActions) {
  std::ostringstream out;
  EXPECT_THROW(writeModelPredictions(FixedView(), {{1.0f, 2.0f}, {1.0f}}, 2, out),
               std::invalid_argument);
  EXPECT_THROW(writeModelPredictions(FixedView(), {{1.0f, 2.0f}}, 0, out), std::invalid_argument);
}

TEST(ModelPredictions, AFailedSaveLeavesThePreviousFile) {
  const std::string path = "/tmp/rl_predictions_test_" + std::to_string(::getpid()) + ".csv";
  FixedView view;
  saveModelPredictions(view, {{1.0f, 3.5f}}, 2, path);
  const std::string saved = textOf(path);
  EXPECT_NE(saved.find("1,3.5,1,1,0.5,0.5,"), std::string::npos) << saved;
  view.throwOnQuery = true;
  EXPECT_THROW(saveModelPredictions(view, {{1.0f, 3.5f}}, 2, path), std::runtime_error);
  EXPECT_EQ(textOf(path), saved);
  EXPECT_THROW(saveModelPredictions(view, {{1.0f}}, 2, "/nonexistent-dir/p.csv"),
               std::runtime_error);
  std::remove(path.c_str());
}
