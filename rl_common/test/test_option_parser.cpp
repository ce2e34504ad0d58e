#include "rl_common/option_parser.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using rl_common::OptionError;
using rl_common::OptionParser;

namespace {

// A config struct as programs use it: every default lives here, once.
struct Config {
  double gamma = 0.99;
  int nmodels = 1;
  unsigned long seed = 1;
  bool stochastic = true;
  std::string planner = "parallel-uct";
  std::string env = "lightworld";
};

OptionParser makeParser(Config* c) {
  OptionParser p("prog", "[options]");
  p.value("gamma|discountfactor", &c->gamma, "discount factor", rl_common::inRange(0.0, 1.0));
  p.value("nmodels", &c->nmodels, "trees per forest", rl_common::greaterThan(0));
  p.value("seed", &c->seed, "random seed");
  p.flag("stochastic", &c->stochastic, true, "noisy dynamics");
  p.flag("deterministic", &c->stochastic, false, "noise-free dynamics");
  p.aliasedChoice(
      "planner", &c->planner,
      {{"uct", "uct"}, {"parallel-uct", "parallel-uct"}, {"realtimeuct", "parallel-uct"}},
      "planner");
  p.choice("env", &c->env, {"taxi", "lightworld"}, "environment");
  return p;
}

std::string errorOf(const std::vector<std::string>& args) {
  Config c;
  OptionParser p = makeParser(&c);
  try {
    p.parse(args);
  } catch (const OptionError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(OptionParser, DefaultsStayWhenNothingGiven) {
  Config c;
  OptionParser p = makeParser(&c);
  EXPECT_TRUE(p.parse(std::vector<std::string>{}));
  EXPECT_DOUBLE_EQ(c.gamma, 0.99);
  EXPECT_TRUE(c.stochastic);
  EXPECT_FALSE(p.given("gamma"));
}

TEST(OptionParser, SingleAndDoubleDashAndEquals) {
  Config c;
  OptionParser p = makeParser(&c);
  EXPECT_TRUE(p.parse({"-gamma", "0.5", "--nmodels", "5", "--seed=7", "-deterministic"}));
  EXPECT_DOUBLE_EQ(c.gamma, 0.5);
  EXPECT_EQ(c.nmodels, 5);
  EXPECT_EQ(c.seed, 7u);
  EXPECT_FALSE(c.stochastic);
  EXPECT_TRUE(p.given("gamma"));
  EXPECT_TRUE(p.given("discountfactor"));  // any spelling of the same option
  EXPECT_TRUE(p.given("deterministic"));
  EXPECT_FALSE(p.given("stochastic"));
}

TEST(OptionParser, AliasesAndChoiceSpellings) {
  Config c;
  OptionParser p = makeParser(&c);
  p.parse({"--discountfactor", "0.9", "--planner", "realtimeuct"});
  EXPECT_DOUBLE_EQ(c.gamma, 0.9);
  EXPECT_EQ(c.planner, "parallel-uct");
}

TEST(OptionParser, LaterFlagWins) {
  Config c;
  OptionParser p = makeParser(&c);
  p.parse({"--deterministic", "--stochastic"});
  EXPECT_TRUE(c.stochastic);
}

TEST(OptionParser, UnambiguousPrefixAsGetoptLongOnly) {
  Config c;
  OptionParser p = makeParser(&c);
  p.parse({"--determ"});
  EXPECT_FALSE(c.stochastic);
}

TEST(OptionParser, HelpStopsParsingAndListsOptions) {
  Config c;
  OptionParser p = makeParser(&c);
  EXPECT_FALSE(p.parse({"--gamma", "0.1", "--help"}));
  EXPECT_DOUBLE_EQ(c.gamma, 0.99);  // nothing applied
  const std::string h = p.help();
  EXPECT_NE(h.find("--gamma, --discountfactor <number>"), std::string::npos) << h;
  EXPECT_NE(h.find("(default: 0.99)"), std::string::npos) << h;
  EXPECT_NE(h.find("{uct, parallel-uct, realtimeuct}"), std::string::npos) << h;
  EXPECT_FALSE(p.parse({"-h"}));
}

TEST(OptionParser, UnknownOptionListsValidOnes) {
  const std::string e = errorOf({"--gama", "0.5"});
  EXPECT_NE(e.find("unknown option '--gama'"), std::string::npos) << e;
  EXPECT_NE(e.find("--gamma"), std::string::npos) << e;
  EXPECT_NE(e.find("--planner"), std::string::npos) << e;
}

TEST(OptionParser, BadValuesNameTheOptionAndWhatIsValid) {
  EXPECT_NE(errorOf({"--gamma", "abc"}).find("option --gamma: invalid value 'abc' (expected a"),
            std::string::npos);
  EXPECT_NE(errorOf({"--gamma", "1.5"}).find("must be in [0, 1]"), std::string::npos);
  EXPECT_NE(errorOf({"--nmodels", "0"}).find("option --nmodels: invalid value '0' (must be > 0)"),
            std::string::npos);
  EXPECT_NE(errorOf({"--nmodels", "2.5"}).find("expected an integer"), std::string::npos);
  EXPECT_NE(errorOf({"--seed", "-1"}).find("option --seed"), std::string::npos);
  EXPECT_NE(errorOf({"--gamma", "nan"}).find("finite"), std::string::npos);
  const std::string e = errorOf({"--env", "mars"});
  EXPECT_NE(e.find("option --env: invalid value 'mars'; valid values: taxi, lightworld"),
            std::string::npos)
      << e;
}

TEST(OptionParser, MissingValueAndStrayArgumentsAreErrors) {
  EXPECT_FALSE(errorOf({"--gamma"}).empty());
  EXPECT_NE(errorOf({"stray"}).find("unexpected argument"), std::string::npos);
  EXPECT_FALSE(errorOf({"--deterministic=maybe"}).empty());
}

TEST(OptionParser, SetUsesTheSameValidation) {
  Config c;
  OptionParser p = makeParser(&c);
  p.set("discountfactor", "0.8");
  EXPECT_DOUBLE_EQ(c.gamma, 0.8);
  EXPECT_TRUE(p.given("gamma"));
  p.set("deterministic", "true");
  EXPECT_FALSE(c.stochastic);
  p.set("deterministic", "false");  // a flag set to false applies its opposite
  EXPECT_TRUE(c.stochastic);
  EXPECT_THROW(p.set("gamma", "2"), OptionError);
  EXPECT_THROW(p.set("nosuch", "1"), OptionError);
  EXPECT_DOUBLE_EQ(c.gamma, 0.8);  // a rejected value changes nothing
}

TEST(OptionParser, CurrentValuesReportTheEffectiveConfiguration) {
  Config c;
  OptionParser p = makeParser(&c);
  p.parse({"--seed", "12", "--gamma", "0.1"});
  const auto values = p.currentValues();
  ASSERT_EQ(values.size(), 7u);
  EXPECT_EQ(values[0], (std::pair<std::string, std::string>{"gamma", "0.1"}));
  EXPECT_EQ(values[2], (std::pair<std::string, std::string>{"seed", "12"}));
  EXPECT_EQ(values[3], (std::pair<std::string, std::string>{"stochastic", "true"}));
  EXPECT_EQ(values[4], (std::pair<std::string, std::string>{"deterministic", "false"}));
  // The one-line form: the same pairs, space-separated, none left out.
  std::string line;
  for (const auto& [name, value] : values) line += (line.empty() ? "" : " ") + name + "=" + value;
  EXPECT_EQ(p.currentValuesLine(), line);
  EXPECT_EQ(p.currentValuesLine().rfind("gamma=0.1 ", 0), 0u);
}

TEST(OptionParser, DuplicateDeclarationIsAProgrammingError) {
  Config c;
  OptionParser p = makeParser(&c);
  EXPECT_THROW(p.value("gamma", &c.gamma, "again"), std::invalid_argument);
  EXPECT_THROW(p.value("help", &c.gamma, "reserved"), std::invalid_argument);
}

TEST(OptionParser, IntegerListsAreCommaSeparated) {
  std::vector<int> bins{0};
  OptionParser p("prog", "");
  p.value("nstates", &bins, "bins per feature");
  p.parse(std::vector<std::string>{"--nstates", "30,12,0"});
  EXPECT_EQ(bins, (std::vector<int>{30, 12, 0}));
  p.parse(std::vector<std::string>{"--nstates=-4"});
  EXPECT_EQ(bins, (std::vector<int>{-4}));
  EXPECT_EQ(rl_common::formatOptionValue(std::vector<int>{30, 12, 0}), "30,12,0");
  for (const char* bad : {"", "1,", "1,,2", "x", "1.5,2"}) {
    EXPECT_THROW(p.parse(std::vector<std::string>{"--nstates", bad}), OptionError) << bad;
  }
  EXPECT_NE(p.help().find("--nstates <int[,int...]>"), std::string::npos) << p.help();
}

TEST(OptionParser, UnsignedOptionsTakeTheWholeUint64Range) {
  // The reset service's seed is a uint64: the command line takes the same range.
  Config c;
  OptionParser p = makeParser(&c);
  p.parse(std::vector<std::string>{"--seed", "18446744073709551615"});
  EXPECT_EQ(c.seed, 18446744073709551615UL);
  p.parse(std::vector<std::string>{"--seed", "9223372036854775808"});  // 2^63
  EXPECT_EQ(c.seed, 9223372036854775808UL);
  EXPECT_NE(errorOf({"--seed", "18446744073709551616"}).find("integer out of range"),
            std::string::npos);
  EXPECT_NE(errorOf({"--seed", "-1"}).find("expected an integer >= 0"), std::string::npos);
  EXPECT_NE(errorOf({"--seed", "-x"}).find("expected an integer"), std::string::npos);
  EXPECT_NE(errorOf({"--seed", "12abc"}).find("expected an integer"), std::string::npos);
}
