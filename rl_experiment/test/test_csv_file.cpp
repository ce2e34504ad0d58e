#include "rl_experiment/log/csv_file.h"

#include <dirent.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <string>

namespace {

std::string tempDir() {
  char tmpl[] = "/tmp/rl_csv_XXXXXX";
  return ::mkdtemp(tmpl);
}

int countFiles(const std::string& dir) {
  int n = 0;
  if (DIR* d = ::opendir(dir.c_str())) {
    while (const dirent* e = ::readdir(d)) n += e->d_name[0] != '.';
    ::closedir(d);
  }
  return n;
}

}  // namespace

TEST(CsvFile, EveryRowIsOnDiskBeforeTheFileCloses) {
  const std::string dir = tempDir();
  const std::string path = dir + "/log.csv";
  rl_experiment::CsvFile f(path, {"a", "b"});
  EXPECT_EQ(rl_experiment::readFile(path), "a,b\n");
  f.row({"1", "2.5"});
  // Read while the file is still open (as after a kill): the row is there.
  EXPECT_EQ(rl_experiment::readFile(path), "a,b\n1,2.5\n");
  const auto rows = rl_experiment::parseCsv(rl_experiment::readFile(path));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1][1], "2.5");
  EXPECT_THROW(rl_experiment::CsvFile(dir + "/missing/x.csv", {"a"}), std::runtime_error);
}

TEST(CsvFile, AtomicWriteReplacesWholeFileAndLeavesNoTemporary) {
  const std::string dir = tempDir();
  const std::string path = dir + "/summary.csv";
  rl_experiment::writeFileAtomically(path, "x\n1\n");
  rl_experiment::writeFileAtomically(path, "x\n2\n");
  EXPECT_EQ(rl_experiment::readFile(path), "x\n2\n");
  EXPECT_EQ(countFiles(dir), 1);
  EXPECT_THROW(rl_experiment::writeFileAtomically(dir + "/no/such/file", "x"), std::runtime_error);
}

TEST(CsvFile, NumbersReadBackExactly) {
  EXPECT_EQ(rl_experiment::formatNumber(0.1f), "0.100000001");
  EXPECT_EQ(std::stof(rl_experiment::formatNumber(0.1f)), 0.1f);
  EXPECT_EQ(rl_experiment::formatNumber(10), "10");
  EXPECT_EQ(rl_experiment::csvLine({"a", "", "c"}), "a,,c\n");
  const auto rows = rl_experiment::parseCsv("h1,h2\n1,\n");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].size(), 2u);
}
