#include "rl_agent/agent/policy_file.h"

#include <fstream>
#include <stdexcept>

namespace rl_agent {

void PolicyFile::write(const std::string& filename, int numFeatures, int numActions,
                       const Table& q) {
  if (numFeatures < 0 || numActions < 1) {
    throw std::invalid_argument("PolicyFile::write(): need numFeatures >= 0 and numActions >= 1");
  }
  for (const auto& [s, values] : q) {
    if (static_cast<int>(s.size()) != numFeatures ||
        static_cast<int>(values.size()) != numActions) {
      throw std::invalid_argument("PolicyFile::write(): a state or Q row has the wrong size");
    }
  }
  std::ofstream out(filename, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("PolicyFile::write(): cannot open '" + filename + "'");
  out.write(reinterpret_cast<const char*>(&numFeatures), sizeof(int));
  out.write(reinterpret_cast<const char*>(&numActions), sizeof(int));
  for (const auto& [s, values] : q) {
    out.write(reinterpret_cast<const char*>(s.data()),
              static_cast<std::streamsize>(s.size() * sizeof(float)));
    out.write(reinterpret_cast<const char*>(values.data()),
              static_cast<std::streamsize>(values.size() * sizeof(float)));
  }
  if (!out) throw std::runtime_error("PolicyFile::write(): error writing '" + filename + "'");
}

PolicyFile::Contents PolicyFile::read(const std::string& filename) {
  std::ifstream in(filename, std::ios::binary);
  if (!in) throw std::runtime_error("PolicyFile::read(): cannot open '" + filename + "'");
  Contents c;
  in.read(reinterpret_cast<char*>(&c.numFeatures), sizeof(int));
  in.read(reinterpret_cast<char*>(&c.numActions), sizeof(int));
  if (!in || c.numFeatures < 0 || c.numActions < 1 || c.numFeatures > 100000 ||
      c.numActions > 100000) {
    throw std::runtime_error("PolicyFile::read(): '" + filename + "' has no valid header");
  }
  const std::size_t d = static_cast<std::size_t>(c.numFeatures);
  const std::size_t a = static_cast<std::size_t>(c.numActions);
  while (true) {
    rl_common::State s(d);
    std::vector<float> values(a);
    if (d > 0) {
      in.read(reinterpret_cast<char*>(s.data()), static_cast<std::streamsize>(d * sizeof(float)));
      if (in.gcount() == 0 && in.eof()) break;
    } else if (in.peek() == std::char_traits<char>::eof()) {
      break;
    }
    in.read(reinterpret_cast<char*>(values.data()),
            static_cast<std::streamsize>(a * sizeof(float)));
    if (!in) throw std::runtime_error("PolicyFile::read(): '" + filename + "' is truncated");
    c.q[s] = std::move(values);
    if (in.peek() == std::char_traits<char>::eof()) break;
  }
  return c;
}

}  // namespace rl_agent
