#include "rl_experiment/runner/run_folder.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "rl_experiment/log/csv_file.h"

namespace rl_experiment {

namespace fs = std::filesystem;

bool isRunnerFile(const std::string& name) {
  for (const char* exact : {"run.csv", "seeds.csv", "trials.csv"}) {
    if (name == exact) return true;
  }
  for (const char* prefix : {"steps-", "episodes-", "accuracy-", "groups-", "trial-"}) {
    if (name.rfind(prefix, 0) == 0 && name.size() > 4 &&
        name.compare(name.size() - 4, 4, ".csv") == 0) {
      return true;
    }
  }
  return name.rfind("journal-", 0) == 0 && name.size() > 4 &&
         name.compare(name.size() - 4, 4, ".rlj") == 0;
}

std::vector<std::string> listFiles(const std::string& folder) {
  std::vector<std::string> out;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    out.push_back(it->path().filename().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

void makeRunFolder(const std::string& folder) {
  std::error_code ec;
  if (fs::exists(folder, ec) && !fs::is_directory(folder, ec)) {
    throw std::runtime_error("Experiment::prepare(): --out " + folder +
                             " exists and is not a folder");
  }
  fs::create_directories(folder, ec);
  if (ec) {
    throw std::runtime_error("Experiment::prepare(): cannot create " + folder + ": " +
                             ec.message());
  }
}

std::vector<std::pair<std::string, std::string>> parseSummaryRow(const std::string& text) {
  const auto rows = parseCsv(text);
  std::vector<std::pair<std::string, std::string>> out;
  if (rows.size() < 2) return out;
  for (std::size_t i = 0; i < rows[0].size(); ++i) {
    out.emplace_back(rows[0][i], i < rows[1].size() ? rows[1][i] : "");
  }
  return out;
}

void collectTrialSummaries(const std::string& folder) {
  std::string header;
  std::string body;
  for (const auto& f : listFiles(folder)) {
    if (f.rfind("trial-", 0) != 0 || f.size() < 4 || f.compare(f.size() - 4, 4, ".csv") != 0) {
      continue;
    }
    const auto row = parseSummaryRow(readFile(folder + "/" + f));
    if (row.empty()) continue;
    std::vector<std::string> names, values;
    for (const auto& [n, v] : row) {
      names.push_back(n);
      values.push_back(v);
    }
    if (header.empty()) header = csvLine(names);
    body += csvLine(values);
  }
  if (!header.empty()) writeFileAtomically(folder + "/trials.csv", header + body);
}

std::string configurationDifference(const std::string& recorded, const std::string& now) {
  const auto parse = [](const std::string& text) {
    std::map<std::string, std::string> values;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
      const std::size_t eq = line.find('=');
      if (eq != std::string::npos) values[line.substr(0, eq)] = line.substr(eq + 1);
    }
    return values;
  };
  const auto a = parse(recorded), b = parse(now);
  std::string out;
  const auto add = [&out](const std::string& name, const std::string& from, const std::string& to) {
    out += (out.empty() ? "" : ", ") + name + ": " + from + " -> " + to;
  };
  for (const auto& [name, value] : a) {
    const auto it = b.find(name);
    if (it == b.end()) {
      add(name, value, "(not an option now)");
    } else if (it->second != value) {
      add(name, value, it->second);
    }
  }
  for (const auto& [name, value] : b) {
    if (a.count(name) == 0) add(name, "(not recorded)", value);
  }
  return out;
}

}  // namespace rl_experiment
