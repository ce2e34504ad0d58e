#include "rl_common/option_parser.h"

#include <algorithm>
#include <boost/program_options.hpp>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "rl_common/registry.h"

namespace po = boost::program_options;

namespace rl_common {

namespace {

std::vector<std::string> splitNames(const std::string& names) {
  std::vector<std::string> out;
  std::stringstream ss(names);
  std::string item;
  while (std::getline(ss, item, '|')) {
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

long long parseInteger(const std::string& text) {
  if (text.empty()) throw std::invalid_argument("expected an integer");
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (*end != '\0') throw std::invalid_argument("expected an integer");
  if (errno == ERANGE) throw std::invalid_argument("integer out of range");
  return v;
}

double parseReal(const std::string& text) {
  if (text.empty()) throw std::invalid_argument("expected a number");
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (*end != '\0') throw std::invalid_argument("expected a number");
  if (!std::isfinite(v) || errno == ERANGE) {
    throw std::invalid_argument("expected a finite number");
  }
  return v;
}

/// Unsigned values span [0, 2^64 - 1] (seeds: the reset service takes any uint64): parsed as
/// unsigned, not through long long.
unsigned long long parseUnsigned(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first != std::string::npos && text[first] == '-') {
    parseInteger(text);  // "expected an integer" for text that is not one
    throw std::invalid_argument("expected an integer >= 0");
  }
  if (text.empty()) throw std::invalid_argument("expected an integer");
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
  if (*end != '\0') throw std::invalid_argument("expected an integer");
  if (errno == ERANGE) throw std::invalid_argument("integer out of range");
  return v;
}

template <class T>
T checkedIntegral(const std::string& text) {
  if constexpr (std::is_unsigned_v<T>) {
    const unsigned long long v = parseUnsigned(text);
    if (v > std::numeric_limits<T>::max()) throw std::invalid_argument("integer out of range");
    return static_cast<T>(v);
  }
  const long long v = parseInteger(text);
  if (std::is_unsigned_v<T> && v < 0) throw std::invalid_argument("expected an integer >= 0");
  if (static_cast<long double>(v) > static_cast<long double>(std::numeric_limits<T>::max()) ||
      (std::is_signed_v<T> && v < static_cast<long long>(std::numeric_limits<T>::min()))) {
    throw std::invalid_argument("integer out of range");
  }
  return static_cast<T>(v);
}

}  // namespace

template <>
bool parseOptionValue<bool>(const std::string& text) {
  if (text == "true" || text == "1" || text == "yes" || text == "on") return true;
  if (text == "false" || text == "0" || text == "no" || text == "off") return false;
  throw std::invalid_argument("expected true or false");
}
template <>
int parseOptionValue<int>(const std::string& text) {
  return checkedIntegral<int>(text);
}
template <>
long parseOptionValue<long>(const std::string& text) {
  return checkedIntegral<long>(text);
}
template <>
unsigned parseOptionValue<unsigned>(const std::string& text) {
  return checkedIntegral<unsigned>(text);
}
template <>
unsigned long parseOptionValue<unsigned long>(const std::string& text) {
  return checkedIntegral<unsigned long>(text);
}
template <>
unsigned long long parseOptionValue<unsigned long long>(const std::string& text) {
  return checkedIntegral<unsigned long long>(text);
}
template <>
double parseOptionValue<double>(const std::string& text) {
  return parseReal(text);
}
template <>
float parseOptionValue<float>(const std::string& text) {
  const double v = parseReal(text);
  if (std::fabs(v) > std::numeric_limits<float>::max()) {
    throw std::invalid_argument("number out of range");
  }
  return static_cast<float>(v);
}
template <>
std::string parseOptionValue<std::string>(const std::string& text) {
  return text;
}
template <>
std::vector<int> parseOptionValue<std::vector<int>>(const std::string& text) {
  std::vector<int> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string item =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    try {
      out.push_back(checkedIntegral<int>(item));
    } catch (const std::invalid_argument&) {
      throw std::invalid_argument("expected integers separated by commas, e.g. 30,12,0");
    }
    if (comma == std::string::npos) return out;
    start = comma + 1;
  }
}

template <class T>
std::string formatOptionValue(const T& value) {
  if constexpr (std::is_same_v<T, bool>) {
    return value ? "true" : "false";
  } else if constexpr (std::is_same_v<T, std::string>) {
    return value;
  } else if constexpr (std::is_same_v<T, std::vector<int>>) {
    std::string out;
    for (std::size_t i = 0; i < value.size(); ++i) {
      out += (i ? "," : "") + std::to_string(value[i]);
    }
    return out;
  } else {
    std::ostringstream os;
    if constexpr (std::is_floating_point_v<T>) {
      os.precision(std::numeric_limits<T>::max_digits10);
      os << value;
      // Round-trip precision prints 0.1f as 0.100000001; prefer the short form when exact.
      std::ostringstream shortForm;
      shortForm << value;
      if (parseOptionValue<T>(shortForm.str()) == value) return shortForm.str();
    } else {
      os << value;
    }
    return os.str();
  }
}

template std::string formatOptionValue<bool>(const bool&);
template std::string formatOptionValue<int>(const int&);
template std::string formatOptionValue<long>(const long&);
template std::string formatOptionValue<unsigned>(const unsigned&);
template std::string formatOptionValue<unsigned long>(const unsigned long&);
template std::string formatOptionValue<unsigned long long>(const unsigned long long&);
template std::string formatOptionValue<float>(const float&);
template std::string formatOptionValue<double>(const double&);
template std::string formatOptionValue<std::string>(const std::string&);
template std::string formatOptionValue<std::vector<int>>(const std::vector<int>&);

OptionParser::OptionParser(std::string program, std::string synopsis)
    : program_(std::move(program)), synopsis_(std::move(synopsis)) {}

OptionParser::Spec OptionParser::makeSpec(const std::string& names, Kind kind,
                                          const std::string& help) const {
  std::vector<std::string> all = splitNames(names);
  if (all.empty()) throw std::invalid_argument("OptionParser::makeSpec(): no option name");
  Spec spec;
  spec.name = all.front();
  spec.aliases.assign(all.begin() + 1, all.end());
  spec.kind = kind;
  spec.help = help;
  return spec;
}

OptionParser& OptionParser::addSpec(Spec spec) {
  std::vector<std::string> spellings = spec.aliases;
  spellings.push_back(spec.name);
  for (const std::string& s : spellings) {
    if (s == "help" || s == "h" || find(s) != nullptr) {
      throw std::invalid_argument("OptionParser::addSpec(): option '" + s + "' declared twice");
    }
  }
  specs_.push_back(std::move(spec));
  return *this;
}

OptionParser& OptionParser::choice(const std::string& names, std::string* target,
                                   const std::vector<std::string>& valid, const std::string& help) {
  std::vector<std::pair<std::string, std::string>> spellings;
  for (const auto& v : valid) spellings.emplace_back(v, v);
  return aliasedChoice(names, target, spellings, help);
}

OptionParser& OptionParser::aliasedChoice(
    const std::string& names, std::string* target,
    const std::vector<std::pair<std::string, std::string>>& spellings, const std::string& help) {
  Spec spec = makeSpec(names, Kind::Value, help);
  std::vector<std::string> accepted;
  for (const auto& s : spellings) accepted.push_back(s.first);
  spec.valueHint = "{" + joinNames(accepted) + "}";
  const std::string shown = spec.name;
  spec.apply = [target, spellings, accepted, shown](const std::string& text) {
    for (const auto& s : spellings) {
      if (s.first == text) {
        *target = s.second;
        return;
      }
    }
    throw OptionError("option --" + shown + ": invalid value '" + text +
                      "'; valid values: " + joinNames(accepted));
  };
  spec.current = [target] { return *target; };
  return addSpec(std::move(spec));
}

OptionParser& OptionParser::flag(const std::string& names, bool* target, bool setTo,
                                 const std::string& help) {
  Spec spec = makeSpec(names, Kind::Flag, help);
  const std::string shown = spec.name;
  spec.apply = [target, setTo, shown](const std::string& text) {
    bool on = true;
    if (!text.empty()) {
      try {
        on = parseOptionValue<bool>(text);
      } catch (const std::invalid_argument&) {
        throw OptionError("option --" + shown + " takes no value (or true/false), got '" + text +
                          "'");
      }
    }
    *target = on ? setTo : !setTo;
  };
  spec.current = [target, setTo] { return formatOptionValue(*target == setTo); };
  return addSpec(std::move(spec));
}

const OptionParser::Spec* OptionParser::find(const std::string& name) const {
  for (const Spec& s : specs_) {
    if (s.name == name || std::find(s.aliases.begin(), s.aliases.end(), name) != s.aliases.end()) {
      return &s;
    }
  }
  return nullptr;
}

bool OptionParser::has(const std::string& name) const { return find(name) != nullptr; }

std::string OptionParser::validNames() const {
  std::vector<std::string> names{"--help"};
  for (const Spec& s : specs_) {
    names.push_back("--" + s.name);
    for (const auto& a : s.aliases) names.push_back("--" + a);
  }
  return joinNames(names);
}

void OptionParser::set(const std::string& name, const std::string& value) {
  const Spec* spec = find(name);
  if (spec == nullptr) {
    throw OptionError(program_ + ": unknown option '" + name + "'; valid options: " + validNames());
  }
  spec->apply(value);
  if (!given(spec->name)) given_.push_back(spec->name);
}

bool OptionParser::given(const std::string& name) const {
  const Spec* spec = find(name);
  return spec != nullptr && std::find(given_.begin(), given_.end(), spec->name) != given_.end();
}

bool OptionParser::parse(int argc, const char* const* argv) {
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i) args.emplace_back(argv[i]);
  return parse(args);
}

bool OptionParser::parse(const std::vector<std::string>& args) {
  po::options_description desc;
  desc.add_options()("help,h", "");
  for (const Spec& s : specs_) {
    std::vector<std::string> spellings = s.aliases;
    spellings.insert(spellings.begin(), s.name);
    for (const std::string& n : spellings) {
      if (s.kind == Kind::Flag) {
        desc.add_options()(n.c_str(), po::value<std::string>()->implicit_value(""), "");
      } else {
        desc.add_options()(n.c_str(), po::value<std::string>(), "");
      }
    }
  }
  po::parsed_options parsed(&desc);
  try {
    // getopt_long_only semantics: long names with one or two dashes, unambiguous prefixes.
    const int style =
        po::command_line_style::default_style | po::command_line_style::allow_long_disguise;
    parsed = po::command_line_parser(args).options(desc).style(style).run();
  } catch (const po::unknown_option& e) {
    throw OptionError(program_ + ": unknown option '" + e.get_option_name() +
                      "'; valid options: " + validNames());
  } catch (const po::too_many_positional_options_error&) {
    throw OptionError(program_ + ": unexpected argument; options take the form --name value");
  } catch (const po::error& e) {
    throw OptionError(program_ + ": " + e.what());
  }
  for (const po::option& opt : parsed.options) {
    if (opt.string_key == "help") return false;
  }
  for (const po::option& opt : parsed.options) {
    if (opt.position_key >= 0 || opt.unregistered) {
      const std::string token = opt.original_tokens.empty() ? "" : opt.original_tokens.front();
      throw OptionError(program_ + ": unexpected argument '" + token +
                        "'; options take the form --name value");
    }
    set(opt.string_key, opt.value.empty() ? std::string() : opt.value.front());
  }
  return true;
}

std::string OptionParser::help() const {
  std::ostringstream os;
  os << "Usage: " << program_ << " " << synopsis_ << "\n\nOptions (one or two dashes):\n";
  os << "  --help\n      print this help and exit\n";
  for (const Spec& s : specs_) {
    os << "  --" << s.name;
    for (const auto& a : s.aliases) os << ", --" << a;
    if (s.kind == Kind::Value) os << " " << s.valueHint;
    os << "\n      " << s.help;
    if (s.kind == Kind::Value) {
      os << " (default: " << s.current() << ")";
    }
    os << "\n";
  }
  return os.str();
}

std::vector<std::pair<std::string, std::string>> OptionParser::currentValues() const {
  std::vector<std::pair<std::string, std::string>> out;
  for (const Spec& s : specs_) out.emplace_back(s.name, s.current());
  return out;
}

std::string OptionParser::currentValuesLine() const {
  std::string line;
  for (const Spec& s : specs_) line += (line.empty() ? "" : " ") + s.name + "=" + s.current();
  return line;
}

}  // namespace rl_common
