/**
 * CSV output that survives a killed run: CsvFile writes each row with one write and flushes it
 * at once, so every finished line is on disk; writeFileAtomically() writes a whole file to a
 * temporary name in the same folder and renames it over the target, so readers see either the
 * old or the new file, never half of one.
 */
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace rl_experiment {

/// Formats a float or double with enough digits to read back the same value.
std::string formatNumber(double value);

/// Joins fields into one CSV line (fields are written as is; callers pass no commas).
std::string csvLine(const std::vector<std::string>& fields);

class CsvFile {
 public:
  /// Creates (truncates) `path` and writes the header line. Throws std::runtime_error if the
  /// file cannot be opened.
  CsvFile(const std::string& path, const std::vector<std::string>& header);
  ~CsvFile();
  CsvFile(const CsvFile&) = delete;
  CsvFile& operator=(const CsvFile&) = delete;

  /// Writes one row and flushes it. Throws std::runtime_error on a write error.
  void row(const std::vector<std::string>& fields);
  const std::string& path() const { return path_; }

 private:
  void writeLine(const std::string& line);
  std::string path_;
  std::FILE* file_ = nullptr;
};

/// Writes `content` to `path` atomically (temporary file + fsync + rename). Throws
/// std::runtime_error on failure.
void writeFileAtomically(const std::string& path, const std::string& content);

/// Reads a whole text file. Throws std::runtime_error if it cannot be read.
std::string readFile(const std::string& path);

/// Parses CSV text without quoting into rows of fields (empty lines skipped).
std::vector<std::vector<std::string>> parseCsv(const std::string& text);

}  // namespace rl_experiment
