/**
 * OptionParser: the command-line parser every program of the suite shares.
 *
 * It takes the original package's long option names with one or two dashes, as the original's
 * getopt_long_only did (`-seed 3`, `--seed 3`, `--seed=3`, unambiguous prefixes), plus
 * `--help`. Each option writes into a field of a plain config struct that holds the default,
 * so every default exists once. Unknown options and bad values throw OptionError with a message
 * naming the option and what is valid. The same options can be filled from any other source of
 * name/value strings through set(), with the same validation: the ROS adapter uses that to read
 * `~private` parameters (rl_common/ros/param_loader.h).
 *
 * Tokenising is done by boost::program_options (allow_long_disguise gives the single-dash long
 * names); typed conversion, choices and validation are ours.
 */
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace rl_common {

/// A bad command line or parameter: the message names the option and what is valid.
class OptionError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// Converts option text to a value; throws std::invalid_argument with what was expected.
/// Defined for bool, int, long, unsigned, unsigned long (long), float, double, std::string and
/// std::vector<int> (a comma-separated list, e.g. "30,12,0").
template <class T>
T parseOptionValue(const std::string& text);

/// Formats a value as option text (the inverse of parseOptionValue).
template <class T>
std::string formatOptionValue(const T& value);

class OptionParser {
 public:
  enum class Kind { Value, Flag };

  /// One option: its spellings, how to apply a value and how to show the current one.
  struct Spec {
    std::string name;                  ///< canonical name, without dashes
    std::vector<std::string> aliases;  ///< other accepted names
    Kind kind = Kind::Value;
    std::string valueHint;  ///< e.g. "<float>" or "{a|b|c}"
    std::string help;
    std::function<void(const std::string&)> apply;  ///< parses, validates, stores; may throw
    std::function<std::string()> current;           ///< the current value as text
  };

  /// A check on a parsed value: returns an empty string if valid, else what is valid
  /// (e.g. "must be > 0").
  template <class T>
  using Check = std::function<std::string(const T&)>;

  OptionParser(std::string program, std::string synopsis);

  /// Adds an option taking a value. `names` is "canonical|alias|alias".
  template <class T>
  OptionParser& value(const std::string& names, T* target, const std::string& help,
                      Check<T> check = {}) {
    Spec spec = makeSpec(names, Kind::Value, help);
    spec.valueHint = hintFor<T>();
    const std::string shown = spec.name;
    spec.apply = [target, check, shown](const std::string& text) {
      T v;
      try {
        v = parseOptionValue<T>(text);
      } catch (const std::invalid_argument& e) {
        throw OptionError("option --" + shown + ": invalid value '" + text + "' (" + e.what() +
                          ")");
      }
      if (check) {
        const std::string problem = check(v);
        if (!problem.empty()) {
          throw OptionError("option --" + shown + ": invalid value '" + text + "' (" + problem +
                            ")");
        }
      }
      *target = v;
    };
    spec.current = [target] { return formatOptionValue(*target); };
    return addSpec(std::move(spec));
  }

  /// Adds an option whose value must be one of `valid`.
  OptionParser& choice(const std::string& names, std::string* target,
                       const std::vector<std::string>& valid, const std::string& help);

  /// Adds an option accepting several spellings per value: each pair is (spelling, value).
  OptionParser& aliasedChoice(const std::string& names, std::string* target,
                              const std::vector<std::pair<std::string, std::string>>& spellings,
                              const std::string& help);

  /// Adds a flag taking no value: giving it sets `*target = setTo` (as --deterministic sets
  /// stochastic to false). Through set(), "true" applies the flag and "false" its opposite.
  OptionParser& flag(const std::string& names, bool* target, bool setTo, const std::string& help);

  /// Parses a command line (argv[0] is the program). Returns false if --help was given, in
  /// which case nothing else is applied. Throws OptionError on unknown options, bad values,
  /// missing values and stray arguments.
  bool parse(int argc, const char* const* argv);
  /// Same, for arguments without the program name.
  bool parse(const std::vector<std::string>& args);

  /// Applies `value` to the option named `name` (canonical or alias), validated as on the
  /// command line. Throws OptionError if the option is unknown or the value invalid.
  void set(const std::string& name, const std::string& value);

  /// True if the option (any spelling) was given on the command line or through set().
  bool given(const std::string& name) const;
  /// True if an option with that name or alias exists.
  bool has(const std::string& name) const;

  /// The usage text: synopsis, then every option with its values, help and current value.
  std::string help() const;
  const std::vector<Spec>& specs() const { return specs_; }
  /// Canonical name and current value of every option, in declaration order.
  std::vector<std::pair<std::string, std::string>> currentValues() const;
  /// The same as one line, "name=value name=value ..." (a node's logged configuration).
  std::string currentValuesLine() const;

 private:
  Spec makeSpec(const std::string& names, Kind kind, const std::string& help) const;
  OptionParser& addSpec(Spec spec);
  const Spec* find(const std::string& name) const;
  std::string validNames() const;

  template <class T>
  static std::string hintFor() {
    if constexpr (std::is_same_v<T, bool>) {
      return "<true|false>";
    } else if constexpr (std::is_integral_v<T>) {
      return "<int>";
    } else if constexpr (std::is_same_v<T, std::vector<int>>) {
      return "<int[,int...]>";
    } else if constexpr (std::is_floating_point_v<T>) {
      return "<number>";
    } else {
      return "<text>";
    }
  }

  std::string program_;
  std::string synopsis_;
  std::vector<Spec> specs_;
  std::vector<std::string> given_;
};

/// Common checks for OptionParser::value.
template <class T>
OptionParser::Check<T> greaterThan(T bound) {
  return [bound](const T& v) {
    return v > bound ? std::string() : "must be > " + formatOptionValue(bound);
  };
}
template <class T>
OptionParser::Check<T> atLeast(T bound) {
  return [bound](const T& v) {
    return v >= bound ? std::string() : "must be >= " + formatOptionValue(bound);
  };
}
template <class T>
OptionParser::Check<T> inRange(T lo, T hi) {
  return [lo, hi](const T& v) {
    return (v >= lo && v <= hi)
               ? std::string()
               : "must be in [" + formatOptionValue(lo) + ", " + formatOptionValue(hi) + "]";
  };
}

}  // namespace rl_common
