#include "rl_agent/journal/experience_journal.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace rl_agent {

namespace {

const char* const kMagic = "RL_EXPERIENCE_JOURNAL 1";
constexpr int kMaxFeatures = 65536;  // as the agent node's description limit

std::size_t recordBytes(int n) {
  return 2 * static_cast<std::size_t>(n) * sizeof(float) + sizeof(std::int32_t) + sizeof(float) + 1;
}

std::string oneLine(std::string s) {
  for (char& c : s) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return s;
}

struct Parsed {
  JournalContents contents;
  std::size_t wholeBytes = 0;  // header, feature count and whole records
};

Parsed parse(const std::string& path, const std::string& data) {
  const auto fail = [&](const std::string& why) {
    return std::runtime_error("experience journal '" + path + "': " + why);
  };
  Parsed out;
  std::size_t pos = 0;
  const auto line = [&](std::string* text) {
    const std::size_t end = data.find('\n', pos);
    if (end == std::string::npos) return false;
    *text = data.substr(pos, end - pos);
    pos = end + 1;
    return true;
  };
  std::string text;
  if (!line(&text) || text != kMagic) {
    throw fail("not an experience journal (it must begin with the line '" + std::string(kMagic) +
               "')");
  }
  while (true) {
    if (!line(&text)) throw fail("the header has no 'end' line (cut while it was written?)");
    if (text == "end") break;
    const std::size_t space = text.find(' ');
    out.contents.header.emplace_back(text.substr(0, space),
                                     space == std::string::npos ? "" : text.substr(space + 1));
  }
  std::int32_t n = 0;
  if (data.size() - pos < sizeof(n)) throw fail("no feature count after the header");
  std::memcpy(&n, data.data() + pos, sizeof(n));
  pos += sizeof(n);
  if (n < 1 || n > kMaxFeatures) {
    throw fail("feature count " + std::to_string(n) + " is not in [1, " +
               std::to_string(kMaxFeatures) + "]");
  }
  out.contents.numFeatures = n;
  const std::size_t size = recordBytes(n);
  const auto floats = [&](rl_common::State* s) {
    s->resize(static_cast<std::size_t>(n));
    std::memcpy(s->data(), data.data() + pos, s->size() * sizeof(float));
    pos += s->size() * sizeof(float);
  };
  while (data.size() - pos >= size) {
    rl_common::Experience e;
    floats(&e.s);
    floats(&e.next);
    std::int32_t action = 0;
    std::memcpy(&action, data.data() + pos, sizeof(action));
    pos += sizeof(action);
    e.action = action;
    std::memcpy(&e.reward, data.data() + pos, sizeof(e.reward));
    pos += sizeof(e.reward);
    e.terminal = data[pos] != 0;
    pos += 1;
    out.contents.records.push_back(std::move(e));
  }
  out.wholeBytes = pos;
  out.contents.droppedBytes = data.size() - pos;
  return out;
}

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("experience journal '" + path + "': cannot be read");
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

JournalContents readExperienceJournal(const std::string& path) {
  return parse(path, readAll(path)).contents;
}

ExperienceJournalWriter::ExperienceJournalWriter(const std::string& path, int numFeatures,
                                                 const JournalHeader& header)
    : path_(path), numFeatures_(numFeatures) {
  if (numFeatures < 1 || numFeatures > kMaxFeatures) {
    throw std::runtime_error("experience journal '" + path + "': feature count " +
                             std::to_string(numFeatures) + " is not in [1, " +
                             std::to_string(kMaxFeatures) + "]");
  }
  std::ifstream probe(path, std::ios::binary | std::ios::ate);
  const bool fresh = !probe || probe.tellg() == 0;
  probe.close();
  if (fresh) {
    // The run folder may not exist yet (an experiment node creates it as the agent starts).
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    std::error_code ec;
    if (!parent.empty()) std::filesystem::create_directories(parent, ec);
    file_ = std::fopen(path.c_str(), "wb");
    if (file_ == nullptr) {
      throw std::runtime_error("experience journal '" + path +
                               "': cannot be created: " + std::strerror(errno));
    }
    std::string head = std::string(kMagic) + "\n";
    for (const auto& [key, value] : header) head += oneLine(key) + " " + oneLine(value) + "\n";
    head += "end\n";
    const std::int32_t n = numFeatures;
    head.append(reinterpret_cast<const char*>(&n), sizeof(n));
    if (std::fwrite(head.data(), 1, head.size(), file_) != head.size() || std::fflush(file_) != 0) {
      std::fclose(file_);
      throw std::runtime_error("experience journal '" + path + "': cannot be written");
    }
    return;
  }
  const Parsed existing = parse(path, readAll(path));
  if (existing.contents.numFeatures != numFeatures) {
    throw std::runtime_error("experience journal '" + path + "' holds " +
                             std::to_string(existing.contents.numFeatures) +
                             "-feature experiences, not " + std::to_string(numFeatures) +
                             " (give another file; it is not overwritten)");
  }
  // A record cut by a kill: drop its bytes so the next record starts on a record boundary.
  if (existing.contents.droppedBytes > 0 &&
      ::truncate(path.c_str(), static_cast<off_t>(existing.wholeBytes)) != 0) {
    throw std::runtime_error("experience journal '" + path +
                             "': cannot cut its partial record: " + std::strerror(errno));
  }
  file_ = std::fopen(path.c_str(), "ab");
  if (file_ == nullptr) {
    throw std::runtime_error("experience journal '" + path +
                             "': cannot be appended to: " + std::strerror(errno));
  }
  records_ = static_cast<long>(existing.contents.records.size());
}

ExperienceJournalWriter::~ExperienceJournalWriter() {
  if (file_ != nullptr) std::fclose(file_);
}

void ExperienceJournalWriter::append(const rl_common::Experience& e) {
  const auto n = static_cast<std::size_t>(numFeatures_);
  if (e.s.size() != n || e.next.size() != n) {
    throw std::invalid_argument(
        "experience journal '" + path_ + "': an experience with " + std::to_string(e.s.size()) +
        " and " + std::to_string(e.next.size()) + " features, expected " + std::to_string(n));
  }
  std::string record;
  record.reserve(recordBytes(numFeatures_));
  record.append(reinterpret_cast<const char*>(e.s.data()), n * sizeof(float));
  record.append(reinterpret_cast<const char*>(e.next.data()), n * sizeof(float));
  const std::int32_t action = e.action;
  record.append(reinterpret_cast<const char*>(&action), sizeof(action));
  record.append(reinterpret_cast<const char*>(&e.reward), sizeof(e.reward));
  record.push_back(e.terminal ? 1 : 0);
  // One write and a flush per record: a kill loses at most the record being written.
  if (std::fwrite(record.data(), 1, record.size(), file_) != record.size() ||
      std::fflush(file_) != 0) {
    throw std::runtime_error("experience journal '" + path_ +
                             "': write failed: " + std::strerror(errno));
  }
  ++records_;
}

}  // namespace rl_agent
