#include "rl_agent/agent/agent_options.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using rl_agent::AgentOptions;

namespace {

// Parses like the agent node: options, then the agent's defaults, then the rules.
AgentOptions parse(const std::vector<std::string>& args) {
  AgentOptions o;
  rl_common::OptionParser p("agent", "");
  rl_agent::addAgentOptions(p, &o);
  p.parse(args);
  rl_agent::applyAgentDefaults(p, &o);
  rl_agent::checkAgentOptions(p, o);
  return o;
}

std::string errorOf(const std::vector<std::string>& args) {
  try {
    parse(args);
  } catch (const rl_common::OptionError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(AgentOptions, OriginalDefaults) {
  const AgentOptions o;
  EXPECT_FLOAT_EQ(o.gamma, 0.99f);
  EXPECT_FLOAT_EQ(o.epsilon, 0.1f);
  EXPECT_FLOAT_EQ(o.alpha, 0.3f);
  EXPECT_FLOAT_EQ(o.actrate, 10.0f);
  EXPECT_FLOAT_EQ(o.lambda, 0.1f);
  EXPECT_EQ(o.m, 5);
  EXPECT_EQ(o.k, 1000);
  EXPECT_EQ(o.planner, "parallel-uct");
  EXPECT_TRUE(o.reltrans);
}

TEST(AgentOptions, TexploreDefaultsAndVanir) {
  AgentOptions o = parse({"--agent", "texplore"});
  EXPECT_EQ(o.nmodels, 5);
  EXPECT_EQ(o.combo, "separate");  // the suite's forest; the original's is --combo average
  EXPECT_EQ(o.taskcombo, "same");  // UCT plans the task on the forest it explored on
  EXPECT_EQ(o.defer, 0);           // one-way steps are not put off, as the original
  EXPECT_EQ(o.explore, "greedy");  // no v, n: plain TEXPLORE
  EXPECT_EQ(o.m, 0);
  o = parse({"--agent", "texplore", "--v", "1", "--n", "3"});
  EXPECT_EQ(o.explore, "variancenovelty");
  EXPECT_EQ(o.combo, "separate");
  EXPECT_EQ(o.defer, 0);
  EXPECT_FLOAT_EQ(o.v, 1.0f);
  EXPECT_FLOAT_EQ(o.n, 3.0f);
  // Value iteration plans the task on the separate forest's average, unless told otherwise.
  EXPECT_EQ(parse({"--agent", "texplore", "--taskplanner", "vi"}).taskcombo, "average");
  EXPECT_EQ(parse({"--agent", "texplore", "--combo", "average", "--taskplanner", "vi"}).taskcombo,
            "same");
  EXPECT_EQ(parse({"--agent", "texplore", "--taskplanner", "vi", "--taskcombo", "same"}).taskcombo,
            "same");
  // The original's TEXPLORE: --combo average; one tree: best (nothing to combine).
  EXPECT_EQ(parse({"--agent", "texplore", "--combo", "average"}).combo, "average");
  EXPECT_EQ(parse({"--agent", "texplore", "--nmodels", "1"}).combo, "best");
  EXPECT_NE(errorOf({"--agent", "texplore", "--nmodels", "1", "--combo", "separate"})
                .find("--combo separate needs --nmodels > 1"),
            std::string::npos);
  o = parse({"-agent", "texplore", "-b", "2"});  // --b is the original's alias of --v
  EXPECT_FLOAT_EQ(o.v, 2.0f);
  o = parse({"--agent", "texplore", "--nmodels", "3"});  // the user's value wins
  EXPECT_EQ(o.nmodels, 3);
}

TEST(AgentOptions, RmaxDefaults) {
  const AgentOptions o = parse({"--agent", "rmax"});
  EXPECT_EQ(o.model, "tabular");
  EXPECT_EQ(o.explore, "unknown");
  EXPECT_EQ(o.planner, "vi");
  EXPECT_FALSE(o.reltrans);
  EXPECT_NE(errorOf({"--agent", "rmax", "--model", "tree"}).find("tabular"), std::string::npos);
}

TEST(AgentOptions, OptionsApplyOnlyWhereMeaningful) {
  EXPECT_NE(errorOf({"--agent", "texplore", "--alpha", "0.1"})
                .find("--alpha applies only to --agent dyna, qlearner, sarsa"),
            std::string::npos);
  EXPECT_NE(errorOf({"--agent", "qlearner", "--v", "1"}).find("--v applies only"),
            std::string::npos);
  EXPECT_NE(errorOf({"--agent", "qlearner", "--k", "5"}).find("dyna"), std::string::npos);
  EXPECT_NE(errorOf({"--agent", "modelbased", "--combo", "average"}).find("--nmodels > 1"),
            std::string::npos);
  EXPECT_NE(errorOf({"--agent", "rmax", "--actrate", "5"}).find("UCT planner"), std::string::npos);
  EXPECT_NE(errorOf({"--agent", "qlearner", "--explore", "unknown"}).find("greedy"),
            std::string::npos);
}

TEST(AgentOptions, OriginalBugsFixed) {
  // --epsilon works for Q-learning without --explore epsilongreedy (the original refused it).
  EXPECT_FLOAT_EQ(parse({"--agent", "qlearner", "--epsilon", "0.2"}).epsilon, 0.2f);
  // --n is usable with the unvisited-* bonuses (the original rejected it).
  const AgentOptions o =
      parse({"--agent", "texplore", "--explore", "unvisitedactions", "--n", "2"});
  EXPECT_EQ(o.explore, "unvisitedactions");
  EXPECT_FLOAT_EQ(o.n, 2.0f);
  // Model-based agents take --epsilon with epsilon-greedy exploration.
  EXPECT_TRUE(
      errorOf({"--agent", "modelbased", "--explore", "epsilongreedy", "--epsilon", "0.3"}).empty());
  EXPECT_FALSE(errorOf({"--agent", "modelbased", "--epsilon", "0.3"}).empty());
}

TEST(AgentOptions, ValuesAreValidated) {
  EXPECT_NE(errorOf({"--gamma", "1.5"}).find("must be in [0, 1]"), std::string::npos);
  // The planner registry's names, each with its other spellings.
  const std::string planner = errorOf({"--planner", "astar"});
  EXPECT_NE(planner.find("valid values: delayed-parallel-uct, delayedparalleluct, "),
            std::string::npos)
      << planner;
  EXPECT_NE(planner.find("uct, vi, valueiteration"), std::string::npos) << planner;
  EXPECT_NE(errorOf({"--nmodels", "0"}).find("must be in [1, 1000]"), std::string::npos);
  // Values that would exhaust memory or plan one step for hours are refused up front.
  EXPECT_NE(errorOf({"--nmodels", "1000000000"}).find("must be in [1, 1000]"), std::string::npos);
  EXPECT_NE(errorOf({"--history", "1000000000"}).find("must be in [0, 100]"), std::string::npos);
  EXPECT_NE(errorOf({"--agent", "texplore", "--rollouts", "9223372036854775807"})
                .find("must be in [0, 1000000]"),
            std::string::npos);
  EXPECT_EQ(parse({"--agent", "texplore", "--planner", "realtime-uct"}).planner, "parallel-uct");
}

TEST(AgentOptions, ComparisonExplorersAndTau) {
  // Boltzmann with the paper's temperature; --tau only with it.
  AgentOptions o = parse({"--agent", "texplore", "--explore", "boltzmann", "--tau", "0.2"});
  EXPECT_EQ(o.explore, "boltzmann");
  EXPECT_FLOAT_EQ(o.tau, 0.2f);
  EXPECT_NE(errorOf({"--agent", "texplore", "--tau", "0.5"})
                .find("--tau applies to --explore boltzmann, not to 'greedy'"),
            std::string::npos);
  EXPECT_NE(errorOf({"--agent", "texplore", "--explore", "boltzmann", "--tau", "0"}), "");
  EXPECT_NE(errorOf({"--agent", "qlearner", "--tau", "0.5"}), "");
  // Competence and prederror weigh their bonus with --v (1 unless given).
  o = parse({"--agent", "texplore", "--explore", "competence"});
  EXPECT_FLOAT_EQ(o.v, 1.0f);
  o = parse({"--agent", "texplore", "--explore", "prederror", "--v", "3"});
  EXPECT_FLOAT_EQ(o.v, 3.0f);
  EXPECT_NE(errorOf({"--agent", "texplore", "--explore", "random", "--v", "1"}), "");
  // --taskcombo: the forests' combination for a value-iteration task phase.
  EXPECT_EQ(parse({"--agent", "texplore", "--combo", "separate", "--taskplanner", "vi",
                   "--taskcombo", "average"})
                .taskcombo,
            "average");
  EXPECT_EQ(parse({"--agent", "texplore", "--combo", "separate", "--taskplanner", "vi",
                   "--taskcombo", "bagged"})
                .taskcombo,
            "bagged");
  EXPECT_NE(errorOf({"--agent", "texplore", "--taskcombo", "average"}).find("--taskplanner vi"),
            std::string::npos);
  EXPECT_NE(errorOf({"--agent", "modelbased", "--model", "tabular", "--taskplanner", "vi",
                     "--taskcombo", "average"})
                .find("--taskcombo applies to --model tree, not to 'tabular'"),
            std::string::npos);
  // Which explorer reads which option comes from the explorer registry's entries.
  EXPECT_NE(errorOf({"--agent", "texplore", "--explore", "random", "--n", "3"})
                .find("--n applies to --explore unvisitedactions, unvisitedstates, "
                      "variancenovelty, not to 'random'"),
            std::string::npos);
  EXPECT_EQ(errorOf({"--agent", "texplore", "--explore", "unvisitedstates", "--n", "1"}), "");
  EXPECT_NE(errorOf({"--agent", "texplore", "--explore", "competence", "--novelty", "state"})
                .find("--novelty applies to --explore variancenovelty, not to 'competence'"),
            std::string::npos);
  EXPECT_EQ(parse({"--agent", "modelbased", "--model", "tabular", "--explore", "random"}).model,
            "tabular");
}

TEST(AgentOptions, ModelExplorerAndPlannerCombinations) {
  EXPECT_NE(errorOf({"--agent", "modelbased", "--model", "tabular", "--explore", "competence"})
                .find("not available with --model tabular"),
            std::string::npos);
  EXPECT_NE(errorOf({"--agent", "modelbased", "--model", "m5tree", "--explore", "unknown",
                     "--planner", "uct"}),
            "");
  EXPECT_NE(
      errorOf({"--agent", "modelbased", "--model", "m5tree", "--planner", "vi"}).find("--nstates"),
      std::string::npos);
  EXPECT_EQ(
      parse({"--agent", "modelbased", "--model", "m5tree", "--planner", "vi", "--nstates", "10"})
          .planner,
      "vi");
  EXPECT_NE(errorOf({"--agent", "rmax", "--explore", "greedy"}).find("--explore unknown"),
            std::string::npos);
  for (const char* planner :
       {"delayeduct", "delayed-parallel-uct", "prioritizedsweeping", "policyiteration"}) {
    EXPECT_EQ(errorOf({"--agent", "modelbased", "--planner", planner}), "") << planner;
  }
  // --k for dyna only; --lambda for sarsa too.
  EXPECT_EQ(parse({"--agent", "dyna", "--k", "10"}).k, 10);
  EXPECT_NE(errorOf({"--agent", "sarsa", "--k", "10"}), "");
  EXPECT_FLOAT_EQ(parse({"--agent", "sarsa", "--lambda", "0.9"}).lambda, 0.9f);
}

TEST(AgentOptions, PathVisitsIsAUctPlannerOptionOffByDefault) {
  EXPECT_FALSE(parse({"--agent", "texplore"}).pathvisits);
  EXPECT_TRUE(parse({"--agent", "texplore", "--v", "1", "--n", "3", "--pathvisits"}).pathvisits);
  EXPECT_NE(errorOf({"--agent", "qlearner", "--pathvisits"}), "");
  EXPECT_NE(errorOf({"--agent", "modelbased", "--planner", "vi", "--pathvisits"})
                .find("needs a UCT planner"),
            std::string::npos);
}

TEST(AgentOptions, NstatesTakesOneCountOrOnePerFeature) {
  EXPECT_EQ(parse({"--agent", "texplore"}).nstates, (std::vector<int>{0}));
  EXPECT_FALSE(rl_agent::binsStates(parse({"--agent", "texplore"})));
  EXPECT_EQ(parse({"--agent", "texplore", "--nstates", "10"}).nstates, (std::vector<int>{10}));
  const AgentOptions o = parse({"--agent", "texplore", "--nstates", "30,12,0"});
  EXPECT_EQ(o.nstates, (std::vector<int>{30, 12, 0}));
  EXPECT_TRUE(rl_agent::binsStates(o));
  EXPECT_NO_THROW(rl_agent::checkStatesPerDim(o, 3));
  EXPECT_THROW(rl_agent::checkStatesPerDim(o, 2), std::invalid_argument);
  for (const char* bad : {"", "30,", ",4", "3.5", "a,b", "4 5"}) {
    EXPECT_NE(errorOf({"--agent", "texplore", "--nstates", bad}).find("separated by commas"),
              std::string::npos)
        << "'" << bad << "'";
  }
  EXPECT_NE(errorOf({"--agent", "texplore", "--nstates", "3,-1"}).find(">= 0"), std::string::npos);
}

TEST(AgentOptions, UctSearchOptionsDefaultToTheOriginal) {
  const AgentOptions d;
  EXPECT_EQ(d.depth, 200);  // the original's MAX_DEPTH
  EXPECT_EQ(d.ucb, "range");
  EXPECT_FALSE(d.bonusonce);
  EXPECT_EQ(d.taskucb, "same");
  AgentOptions o = parse({"--agent", "texplore", "--v", "1", "--n", "3", "--depth", "50", "--ucb",
                          "normalized", "--ucbc", "3", "--bonusonce", "--taskucb", "range"});
  EXPECT_EQ(o.depth, 50);
  EXPECT_EQ(o.ucb, "normalized");
  EXPECT_FLOAT_EQ(o.ucbc, 3.0f);
  EXPECT_TRUE(o.bonusonce);
  EXPECT_EQ(o.taskucb, "range");
  EXPECT_NE(errorOf({"--agent", "texplore", "--depth", "0"}).find("--depth"), std::string::npos);
  EXPECT_FLOAT_EQ(d.minprob, 0.0f);
  EXPECT_EQ(d.novelty, "stateaction");
  EXPECT_EQ(parse({"--agent", "texplore", "--v", "1", "--n", "3", "--novelty", "state"}).novelty,
            "state");
  EXPECT_NE(errorOf({"--agent", "texplore", "--novelty", "state"}).find("variancenovelty"),
            std::string::npos);
  EXPECT_FLOAT_EQ(parse({"--agent", "texplore", "--minprob", "0.1"}).minprob, 0.1f);
  EXPECT_NE(errorOf({"--agent", "texplore", "--minprob", "2"}).find("--minprob"),
            std::string::npos);
  EXPECT_NE(errorOf({"--agent", "texplore", "--ucb", "wide"}).find("normalized"),
            std::string::npos);
  EXPECT_NE(errorOf({"--agent", "texplore", "--ucbc", "-1"}).find("--ucbc"), std::string::npos);
  // UCT options only where a UCT planner runs.
  EXPECT_NE(errorOf({"--agent", "qlearner", "--depth", "5"}).find("--depth"), std::string::npos);
  EXPECT_NE(errorOf({"--agent", "rmax", "--ucb", "normalized"}).find("UCT planner"),
            std::string::npos);
}

TEST(AgentOptions, TaskPlannerOptions) {
  const AgentOptions d;
  EXPECT_EQ(d.taskplanner, "same");  // the original: the task phase plans as exploration did
  EXPECT_TRUE(d.taskkey.empty());
  AgentOptions o = parse({"--agent", "texplore", "--taskplanner", "vi", "--taskkey", "0,1,4",
                          "--taskdepth", "30", "--taskminprob", "0.05", "--tasksweeps", "50"});
  EXPECT_EQ(o.taskplanner, "vi");
  EXPECT_EQ(o.taskkey, (std::vector<int>{0, 1, 4}));
  EXPECT_EQ(o.taskdepth, 30);
  EXPECT_FLOAT_EQ(o.taskminprob, 0.05f);
  EXPECT_EQ(o.tasksweeps, 50);
  EXPECT_EQ(d.tasksweeps, 0);  // to convergence
  EXPECT_EQ(d.taskrecent, 50);
  EXPECT_EQ(parse({"--agent", "texplore", "--taskplanner", "vi", "--taskrecent", "0"}).taskrecent,
            0);
  EXPECT_NE(errorOf({"--agent", "texplore", "--taskrecent", "5"}).find("--taskplanner vi"),
            std::string::npos);
  EXPECT_NE(errorOf({"--agent", "texplore", "--tasksweeps", "5"}).find("--taskplanner vi"),
            std::string::npos);
  EXPECT_NE(errorOf({"--agent", "texplore", "--taskplanner", "uct"}).find("same, vi"),
            std::string::npos);
  EXPECT_NE(errorOf({"--agent", "texplore", "--taskkey", "0,1"}).find("--taskplanner vi"),
            std::string::npos);
  EXPECT_NE(
      errorOf({"--agent", "texplore", "--taskplanner", "vi", "--history", "2"}).find("--history"),
      std::string::npos);
  EXPECT_NE(errorOf({"--agent", "qlearner", "--taskplanner", "vi"}).find("--taskplanner"),
            std::string::npos);
}

TEST(AgentOptions, TaskOutcomesAreTheKeysUnlessJointIsAsked) {
  EXPECT_EQ(AgentOptions().taskoutcomes, "key");
  EXPECT_EQ(parse({"--agent", "texplore", "--taskplanner", "vi", "--taskkey", "0,1",
                   "--taskoutcomes", "joint"})
                .taskoutcomes,
            "joint");
  EXPECT_NE(errorOf({"--agent", "texplore", "--taskplanner", "vi", "--taskkey", "0",
                     "--taskoutcomes", "all"})
                .find("joint, key"),
            std::string::npos);
  EXPECT_NE(errorOf({"--agent", "texplore", "--taskplanner", "vi", "--taskoutcomes", "key"})
                .find("needs --taskkey"),
            std::string::npos);
  EXPECT_NE(errorOf({"--agent", "texplore", "--taskkey", "0", "--taskoutcomes", "joint"})
                .find("--taskplanner vi"),
            std::string::npos);
  EXPECT_NE(errorOf({"--agent", "qlearner", "--taskoutcomes", "key"}).find("--taskoutcomes"),
            std::string::npos);
}

TEST(AgentOptions, SearchThreads) {
  const AgentOptions d;
  EXPECT_EQ(d.searchthreads, 0);  // one per core
  EXPECT_GE(rl_agent::searchThreads(d), 1);
  AgentOptions o = parse({"--agent", "texplore", "--searchthreads", "3"});
  EXPECT_EQ(o.searchthreads, 3);
  EXPECT_EQ(rl_agent::searchThreads(o), 3);
  EXPECT_NE(errorOf({"--agent", "texplore", "--searchthreads", "65"}).find("[0, 64]"),
            std::string::npos);
  EXPECT_NE(errorOf({"--agent", "texplore", "--searchthreads", "-1"}).find("[0, 64]"),
            std::string::npos);
  // Only the real-time planner has search threads.
  EXPECT_NE(errorOf({"--agent", "texplore", "--rollouts", "100", "--searchthreads", "2"})
                .find("real-time planner"),
            std::string::npos);
  EXPECT_NE(errorOf({"--agent", "texplore", "--planner", "uct", "--searchthreads", "2"})
                .find("real-time planner"),
            std::string::npos);
  EXPECT_NE(errorOf({"--agent", "qlearner", "--searchthreads", "2"}).find("--searchthreads"),
            std::string::npos);
}

TEST(AgentOptions, DeferIsOffUnlessGiven) {
  EXPECT_EQ(parse({"--agent", "texplore", "--v", "1", "--n", "3"}).defer, 0);
  EXPECT_EQ(parse({"--agent", "texplore", "--v", "1", "--n", "3", "--defer", "300"}).defer, 300);
  EXPECT_EQ(parse({"--agent", "texplore", "--defer", "150"}).defer, 150);
  EXPECT_NE(errorOf({"--agent", "texplore", "--defer", "-1"}), "");
  EXPECT_NE(errorOf({"--agent", "qlearner", "--defer", "300"}), "");
  EXPECT_NE(errorOf({"--agent", "texplore", "--defer", "300", "--history", "2"}).find("history"),
            std::string::npos);
  EXPECT_EQ(errorOf({"--agent", "texplore", "--v", "1", "--n", "3", "--history", "2"}), "");
}

TEST(AgentOptions, DeferRegionsIsEveryRegionUnlessGiven) {
  EXPECT_EQ(parse({"--agent", "texplore"}).deferregions, 0);
  EXPECT_EQ(parse({"--agent", "texplore", "--deferregions", "2"}).deferregions, 2);
  EXPECT_NE(errorOf({"--agent", "texplore", "--deferregions", "-1"}).find("--deferregions"),
            std::string::npos);
  EXPECT_NE(errorOf({"--agent", "texplore", "--deferregions", "9999999"}).find("--deferregions"),
            std::string::npos);
  EXPECT_NE(errorOf({"--agent", "qlearner", "--deferregions", "2"}).find("--deferregions"),
            std::string::npos);
}

TEST(AgentOptions, PresetsComeFromTheRegistryEntries) {
  // rmax's needed values: applied when not given, an error when given otherwise.
  EXPECT_NE(errorOf({"--agent", "rmax", "--explore", "variancenovelty"})
                .find("--agent rmax needs --explore unknown (got variancenovelty)"),
            std::string::npos);
  EXPECT_NE(errorOf({"--agent", "rmax", "--model", "tree"})
                .find("--agent rmax needs --model tabular (got tree)"),
            std::string::npos);
  EXPECT_EQ(errorOf({"--agent", "rmax", "--model", "tabular", "--explore", "unknown"}), "");
  // A preset's default never overrides the user's choice, also through the other spelling of
  // one field (--abstrans sets what --reltrans does).
  EXPECT_FALSE(parse({"--agent", "texplore", "--abstrans"}).reltrans);
  EXPECT_TRUE(parse({"--agent", "rmax", "--reltrans"}).reltrans);
  EXPECT_EQ(parse({"--agent", "rmax", "--m", "2"}).m, 2);
  // The model-free agents take the explorers of the registry's model-free-selection fact.
  EXPECT_NE(errorOf({"--agent", "sarsa", "--explore", "boltzmann"})
                .find("must be epsilongreedy or greedy"),
            std::string::npos);
  EXPECT_EQ(errorOf({"--agent", "sarsa", "--explore", "epsilongreedy"}), "");
  // --explore given as variancenovelty stays, even without weights.
  EXPECT_EQ(parse({"--agent", "texplore", "--explore", "variancenovelty"}).explore,
            "variancenovelty");
}
