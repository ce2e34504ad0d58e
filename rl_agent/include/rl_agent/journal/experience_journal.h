/**
 * Experience journal: every experience an agent learns from, appended to a file and flushed
 * record by record, so a killed agent's experiences can rebuild its model (`--resume-journal`).
 *
 * Layout: a text header, then the original package's experience file (ORIGINAL.md: the
 * `ExperienceFile` it declared and never wrote): `int32 nfeats`, then per record
 * `float s[nfeats]`, `float next[nfeats]`, `int32 act`, `float reward`, `bool terminal` (one
 * byte), native byte order, no padding. The header is
 *
 *     RL_EXPERIENCE_JOURNAL 1
 *     <key> <value>          (e.g. version, seed, config: who wrote it and how)
 *     end
 *
 * so that `tail -c +<header bytes>` of a journal is a file the original's layout reads. A kill
 * during a write leaves at most one partial record at the end: the reader loads every whole
 * record before it and says how many bytes it dropped.
 */
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "rl_common/experience.h"

namespace rl_agent {

/// The header's key-value lines, in order (keys without spaces, values without newlines).
using JournalHeader = std::vector<std::pair<std::string, std::string>>;

/// What a journal holds.
struct JournalContents {
  JournalHeader header;
  int numFeatures = 0;
  std::vector<rl_common::Experience> records;
  /// Bytes after the last whole record (a record cut by a kill); 0 for a clean file.
  std::size_t droppedBytes = 0;
};

/// Reads a journal. Throws std::runtime_error naming the file if it cannot be read, is not a
/// journal, or its header or feature count is malformed.
JournalContents readExperienceJournal(const std::string& path);

/// Appends experiences to a journal, one flushed record at a time.
class ExperienceJournalWriter {
 public:
  /// Opens `path` for `numFeatures`-feature experiences. A missing or empty file gets
  /// `header` (its folder is created if missing); an existing journal is appended to (after a
  /// partial last record is cut off), which is how a resumed agent goes on writing the journal it
  /// was rebuilt from. Throws std::runtime_error if the file cannot be opened, is not a journal, or
  /// is one of another feature count (it is never overwritten).
  ExperienceJournalWriter(const std::string& path, int numFeatures, const JournalHeader& header);
  ~ExperienceJournalWriter();
  ExperienceJournalWriter(const ExperienceJournalWriter&) = delete;
  ExperienceJournalWriter& operator=(const ExperienceJournalWriter&) = delete;

  /// Writes one record and flushes it. Throws std::invalid_argument for a state of the wrong
  /// length and std::runtime_error if the write fails (e.g. a full disk).
  void append(const rl_common::Experience& e);
  int numFeatures() const { return numFeatures_; }
  const std::string& path() const { return path_; }
  /// Records in the file (those found on opening plus those appended).
  long records() const { return records_; }

 private:
  std::string path_;
  int numFeatures_;
  std::FILE* file_ = nullptr;
  long records_ = 0;
};

}  // namespace rl_agent
