// `./rl reproduce nao` end to end, tiny: both strategies, three tasks, one short trial each;
// the script must write the table and every figure, and run the agents as documented.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

namespace {

std::pair<int, std::string> shell(const std::string& cmd) {
  std::string out;
  std::FILE* p = ::popen((cmd + " 2>&1").c_str(), "r");
  char buf[4096];
  while (std::fgets(buf, sizeof(buf), p) != nullptr) out += buf;
  const int status = ::pclose(p);
  return {WEXITSTATUS(status), out};
}

std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(ReproduceNao, WritesTheTableAndTheFigures) {
  const auto out = std::filesystem::temp_directory_path() / "rl_texplore_tests_reproduce_nao";
  std::filesystem::remove_all(out);
  const auto [status, text] = shell(
      "RL_EXPERIMENT=" + std::string(EXPERIMENT_BIN) + " /usr/bin/python3 " +
      std::string(REPRODUCE_NAO_SCRIPT) +
      " --trials 1 --explore-steps 24 --task-steps 6 --rollouts 5 --jobs 1 --out " + out.string());
  ASSERT_EQ(status, 0) << text;
  const std::string table = slurp(out / "results.md");
  for (const char* row : {"| texplore-vanir | ", "| random | ", "shoulder cells visited",
                          "--nstates 30,12,25,25,25,154,1,20", "task rewards given"}) {
    EXPECT_NE(table.find(row), std::string::npos) << row << "\n" << table;
  }
  for (const char* fig : {"fig10_button_explore", "fig11_max_pink_explore", "fig_cells_explore",
                          "fig12_pink_task", "fig13_button_task", "fig14_mic_task"}) {
    EXPECT_TRUE(std::filesystem::exists(out / (std::string(fig) + ".png"))) << fig;
  }
  // Each run logged its configuration: VANIR's coefficients, the binned states, UCT(1).
  const std::string run = slurp(out / "runs" / "texplore-vanir-button" / "run.csv");
  for (const char* option :
       {"option.v,3", "option.n,10", "option.nstates,30;12;25;25;25;154;1;20", "option.lambda,1",
        "option.task-rewards,given", "option.task,button"}) {
    EXPECT_NE(run.find(option), std::string::npos) << option << "\n" << run;
  }
  std::filesystem::remove_all(out);
}
