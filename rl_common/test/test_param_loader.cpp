// loadPrivateParams fills a config from ~private parameters with the command line's
// validation, and the command line wins over parameters; startNode, every node's start.
#include "rl_common/ros/param_loader.h"

#include <gtest/gtest.h>
#include <ros/ros.h>

#include <string>

namespace {

struct Config {
  double gamma = 0.99;
  bool stochastic = true;
  int exploreSteps = 1000;
  int nmodels = 1;
  unsigned long seed = 1;
  std::string planner = "uct";
};

rl_common::OptionParser makeParser(Config* c) {
  rl_common::OptionParser p("test", "");
  p.value("gamma|discountfactor", &c->gamma, "", rl_common::inRange(0.0, 1.0));
  p.flag("stochastic", &c->stochastic, true, "");
  p.flag("deterministic", &c->stochastic, false, "");
  p.value("explore-steps", &c->exploreSteps, "");
  p.value("nmodels", &c->nmodels, "", rl_common::greaterThan(0));
  p.value("seed", &c->seed, "");
  p.aliasedChoice("planner", &c->planner, {{"uct", "uct"}, {"realtimeuct", "parallel-uct"}}, "");
  return p;
}

}  // namespace

TEST(ParamLoader, PrivateParametersFillTheConfig) {
  Config c;
  auto p = makeParser(&c);
  rl_common::loadPrivateParams(p, ros::NodeHandle("~"));
  EXPECT_DOUBLE_EQ(c.gamma, 0.5);
  EXPECT_FALSE(c.stochastic);
  EXPECT_EQ(c.exploreSteps, 25);  // ~explore_steps for --explore-steps
  EXPECT_EQ(c.planner, "parallel-uct");
  EXPECT_EQ(c.seed, 7u);
  EXPECT_EQ(c.nmodels, 1);
  EXPECT_TRUE(p.given("gamma"));
  EXPECT_FALSE(p.given("nmodels"));
}

TEST(ParamLoader, CommandLineWins) {
  Config c;
  auto p = makeParser(&c);
  const char* argv[] = {"test", "--gamma", "0.25", "--stochastic"};
  ASSERT_TRUE(rl_common::parseNodeOptions(p, 4, argv, ros::NodeHandle("~")));
  EXPECT_DOUBLE_EQ(c.gamma, 0.25);
  EXPECT_TRUE(c.stochastic);
  EXPECT_EQ(c.exploreSteps, 25);
}

TEST(ParamLoader, InvalidParametersNameTheParameter) {
  Config c;
  auto p = makeParser(&c);
  try {
    rl_common::loadPrivateParams(p, ros::NodeHandle("~bad"));
    FAIL();
  } catch (const rl_common::OptionError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("parameter /param_loader/bad/nmodels"), std::string::npos) << msg;
    EXPECT_NE(msg.find("must be > 0"), std::string::npos) << msg;
  }
  EXPECT_THROW(rl_common::loadPrivateParams(p, ros::NodeHandle("~bad_type")),
               rl_common::OptionError);
}

TEST(StartNode, HelpExitsZeroWithoutTouchingTheParameterServer) {
  Config c;
  auto p = makeParser(&c);
  const char* argv[] = {"test", "--help"};
  testing::internal::CaptureStdout();
  const rl_common::NodeStart start = rl_common::startNode(
      p, 2, argv, "test", [] { FAIL() << "check ran after --help"; }, "\nValid things: a, b\n");
  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_FALSE(start);
  EXPECT_EQ(start.exitCode, 0);
  EXPECT_NE(out.find("--explore-steps"), std::string::npos) << out;
  EXPECT_NE(out.find("Valid things: a, b"), std::string::npos) << out;
  EXPECT_DOUBLE_EQ(c.gamma, 0.99);  // ~gamma (0.5) not read
}

TEST(StartNode, ParametersThenTheCommandLineThenTheCheck) {
  Config c;
  auto p = makeParser(&c);
  const char* argv[] = {"test", "--gamma", "0.25"};
  double gammaInCheck = 0.0;
  const rl_common::NodeStart start =
      rl_common::startNode(p, 3, argv, "test", [&] { gammaInCheck = c.gamma; });
  ASSERT_TRUE(start);
  EXPECT_EQ(start.privateHandle->getNamespace(), ros::NodeHandle("~").getNamespace());
  EXPECT_DOUBLE_EQ(c.gamma, 0.25);  // the command line wins over ~gamma
  EXPECT_DOUBLE_EQ(gammaInCheck, 0.25);
  EXPECT_EQ(c.exploreSteps, 25);  // from ~explore_steps
}

TEST(StartNode, BadOptionsAndFailedChecksExitTwoWithTheMessage) {
  for (int kind = 0; kind < 2; ++kind) {
    Config c;
    auto p = makeParser(&c);
    const char* bad[] = {"test", "--nmodels", "0"};
    const char* good[] = {"test"};
    testing::internal::CaptureStderr();
    const rl_common::NodeStart start = kind == 0
                                           ? rl_common::startNode(p, 3, bad, "mynode")
                                           : rl_common::startNode(p, 1, good, "mynode", [] {
                                               throw rl_common::OptionError("option --x needs --y");
                                             });
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_FALSE(start);
    EXPECT_EQ(start.exitCode, 2);
    EXPECT_EQ(err.rfind("mynode: ", 0), 0u) << err;
    EXPECT_NE(err.find(kind == 0 ? "must be > 0" : "option --x needs --y"), std::string::npos)
        << err;
  }
}

TEST(StartNode, AnUnknownOptionIsNamedOnceByItsProgram) {
  Config c;
  auto p = makeParser(&c);  // its program is "test", as the node's
  const char* bad[] = {"test", "--nosuch", "1"};
  testing::internal::CaptureStderr();
  const rl_common::NodeStart start = rl_common::startNode(p, 3, bad, "test");
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(start.exitCode, 2);
  EXPECT_EQ(err.rfind("test: unknown option '--nosuch'", 0), 0u) << err;
  EXPECT_EQ(rl_common::prefixedError("node", "node: x"), "node: x");
  EXPECT_EQ(rl_common::prefixedError("node", "nodes: x"), "node: nodes: x");
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "param_loader");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
