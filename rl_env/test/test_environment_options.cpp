// The environment options: declaration with the original's names, defaults, validation, and
// the per-environment applicability check.
#include "rl_env/env/environment_options.h"

#include "rl_env/env/environment_registry.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace {

using rl_common::OptionError;
using rl_common::OptionParser;
using rl_env::EnvironmentOptions;

// Parses `args` into a fresh options struct; returns it.
EnvironmentOptions parse(const std::vector<std::string>& args, OptionParser* parser,
                         EnvironmentOptions* o) {
  rl_env::addEnvironmentOptions(*parser, o, rl_env::builtinEnvironments());
  parser->parse(args);
  return *o;
}

TEST(EnvironmentOptions, DefaultsAreTheOriginals) {
  const EnvironmentOptions o;
  EXPECT_EQ(o.env, "lightworld");
  EXPECT_TRUE(o.stochastic);
  EXPECT_EQ(o.delay, 0);
  EXPECT_EQ(o.nsectors, 3);
  EXPECT_EQ(o.nstocks, 3);
  EXPECT_FALSE(o.lag);
  EXPECT_FALSE(o.highvar);
}

TEST(EnvironmentOptions, ParsesEveryOption) {
  OptionParser parser("env", "--env <type>");
  EnvironmentOptions o;
  parse({"--env", "stocks", "--seed", "7", "--deterministic", "--nsectors", "4", "--nstocks", "2"},
        &parser, &o);
  EXPECT_EQ(o.env, "stocks");
  EXPECT_EQ(o.seed, 7u);
  EXPECT_FALSE(o.stochastic);
  EXPECT_EQ(o.nsectors, 4);
  EXPECT_EQ(o.nstocks, 2);
  EXPECT_NO_THROW(rl_env::checkEnvironmentOptions(parser, o, rl_env::builtinEnvironments()));

  OptionParser p2("env", "--env <type>");
  EnvironmentOptions o2;
  parse({"-env", "car2to7", "-lag"}, &p2, &o2);  // single-dash long names, as the original
  EXPECT_TRUE(o2.lag);
  EXPECT_NO_THROW(rl_env::checkEnvironmentOptions(p2, o2, rl_env::builtinEnvironments()));
}

TEST(EnvironmentOptions, DelayWithTaxiIsRejectedNamingTheOption) {
  OptionParser parser("env", "--env <type>");
  EnvironmentOptions o;
  parse({"--env", "taxi", "--delay", "2"}, &parser, &o);
  try {
    rl_env::checkEnvironmentOptions(parser, o, rl_env::builtinEnvironments());
    FAIL() << "--delay accepted for taxi";
  } catch (const OptionError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("--delay"), std::string::npos) << what;
    EXPECT_NE(what.find("mcar"), std::string::npos) << what;
    EXPECT_NE(what.find("taxi"), std::string::npos) << what;
  }
}

TEST(EnvironmentOptions, EachOptionOnlyForItsEnvironments) {
  struct Case {
    std::vector<std::string> args;
    bool ok;
  };
  const std::vector<Case> cases = {
      {{"--env", "mcar", "--delay", "3"}, true},
      {{"--env", "tworooms", "--delay", "1"}, true},
      {{"--env", "lightworld", "--delay", "1"}, false},
      {{"--env", "stocks", "--nstocks", "5"}, true},
      {{"--env", "taxi", "--nsectors", "5"}, false},
      {{"--env", "carrandom", "--nolag"}, true},
      {{"--env", "lightworld", "--lag"}, false},
      {{"--env", "fuelworld", "--highvar"}, true},
      {{"--env", "energy", "--highvar"}, false},
      {{"--env", "taxi", "--deterministic", "--seed", "3"}, true},
  };
  for (const Case& c : cases) {
    OptionParser parser("env", "--env <type>");
    EnvironmentOptions o;
    parse(c.args, &parser, &o);
    if (c.ok) {
      EXPECT_NO_THROW(rl_env::checkEnvironmentOptions(parser, o, rl_env::builtinEnvironments()))
          << c.args[1] << " " << c.args[2];
    } else {
      EXPECT_THROW(rl_env::checkEnvironmentOptions(parser, o, rl_env::builtinEnvironments()),
                   OptionError)
          << c.args[1] << " " << c.args[2];
    }
  }
}

TEST(EnvironmentOptions, BadValuesAreRejectedNamingTheOption) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"--delay", "-1"},
        {"--nsectors", "0"},
        {"--nstocks", "x"},
        // Values that would exhaust memory (a delay of 1e9 queued 3.3 GB in 15 s).
        {"--delay", "1000000000"},
        {"--nsectors", "100000"},
        {"--nstocks", "100000"}}) {
    OptionParser parser("env", "--env <type>");
    EnvironmentOptions o;
    rl_env::addEnvironmentOptions(parser, &o, rl_env::builtinEnvironments());
    try {
      parser.parse(args);
      ADD_FAILURE() << "accepted " << args[0] << " " << args[1];
    } catch (const OptionError& e) {
      EXPECT_NE(std::string(e.what()).find(args[0]), std::string::npos) << e.what();
    }
  }
}

TEST(EnvironmentOptions, AnUnknownEnvironmentIsAnOptionErrorListingTheValidOnes) {
  OptionParser parser("env", "--env <type>");
  EnvironmentOptions o;
  parse({"--env", "naoarm"}, &parser, &o);  // another package's: not among rl_env's own
  try {
    rl_env::checkEnvironmentOptions(parser, o, rl_env::builtinEnvironments());
    FAIL() << "naoarm accepted by rl_env's own catalog";
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("valid environments: car2to7"), std::string::npos)
        << e.what();
  }
}

// Another package's option, declared with its environment's registration: parsed with the
// shared ones, defaulted, validated against its choices, and refused for the other entries.
TEST(EnvironmentOptions, ExtraOptionsComeFromTheCatalog) {
  rl_env::EnvironmentCatalog catalog;
  rl_env::addBuiltinEnvironments(catalog);
  catalog.registry().add("robot",
                         [](const EnvironmentOptions& o, std::uint64_t seed) {
                           return rl_env::builtinEnvironments().registry().create("taxi", o, seed);
                         },
                         "a robot", {}, {"task"});
  catalog.addOption({"task", {"explore", "wave"}, "explore", "the robot's task"});
  EXPECT_THROW(catalog.addOption({"task", {"a"}, "a", ""}), std::invalid_argument);
  EXPECT_THROW(catalog.addOption({"other", {"a"}, "b", ""}), std::invalid_argument);

  {
    OptionParser parser("env", "--env <type>");
    EnvironmentOptions o;
    rl_env::addEnvironmentOptions(parser, &o, catalog);
    parser.parse(std::vector<std::string>{"--env", "robot"});
    EXPECT_EQ(o.extraValue("task", "none"), "explore");
  }
  {
    OptionParser parser("env", "--env <type>");
    EnvironmentOptions o;
    rl_env::addEnvironmentOptions(parser, &o, catalog);
    parser.parse(std::vector<std::string>{"--env", "robot", "--task", "wave"});
    EXPECT_EQ(o.extraValue("task", "none"), "wave");
    EXPECT_NO_THROW(rl_env::checkEnvironmentOptions(parser, o, catalog));
    EXPECT_NE(parser.help().find("the robot's task (robot)"), std::string::npos) << parser.help();
  }
  {
    OptionParser parser("env", "--env <type>");
    EnvironmentOptions o;
    rl_env::addEnvironmentOptions(parser, &o, catalog);
    EXPECT_THROW(parser.parse(std::vector<std::string>{"--task", "dance"}), OptionError);
  }
  {
    OptionParser parser("env", "--env <type>");
    EnvironmentOptions o;
    rl_env::addEnvironmentOptions(parser, &o, catalog);
    parser.parse(std::vector<std::string>{"--env", "taxi", "--task", "wave"});
    try {
      rl_env::checkEnvironmentOptions(parser, o, catalog);
      FAIL() << "--task accepted for taxi";
    } catch (const OptionError& e) {
      EXPECT_EQ(std::string(e.what()), "option --task applies only to --env robot, not to 'taxi'");
    }
  }
  EnvironmentOptions unparsed;
  EXPECT_EQ(unparsed.extraValue("task", "explore"), "explore");
}

}  // namespace
