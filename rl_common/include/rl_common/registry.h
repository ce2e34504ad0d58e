/**
 * Registry: a table from names to factories, one per component kind (environments, agents,
 * models, planners, explorers), filled explicitly in one place per kind.
 *
 * Names are the original package's option values; aliases map other accepted spellings
 * (e.g. "parallel-uct" and "realtimeuct") to one canonical name. Asking for an unknown name is
 * an error whose message lists every valid name, so a command line can print it as is.
 *
 * An entry also carries facts about its component (short tags such as an environment's
 * "true-model") and the names of the component-specific options it reads (an environment's
 * "delay"), so that a list of the components with a property, or the check that an option
 * applies, is read from the registry instead of being written out again wherever it is needed.
 * It may also carry option values of its own: defaults it gives the options the user did not
 * set (rmax's --planner vi), and values it needs (rmax's --model tabular), so that a preset is
 * written once, in the entry of its component.
 */
#pragma once

#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rl_common {

/// Joins names as "a, b, c" (or with another separator, e.g. "a|b|c") for error messages and
/// help texts.
inline std::string joinNames(const std::vector<std::string>& names,
                             const std::string& separator = ", ") {
  std::string out;
  for (const auto& n : names) {
    out += (out.empty() ? "" : separator) + n;
  }
  return out;
}

/// Option values as (option name, value as on the command line) pairs.
using OptionValues = std::vector<std::pair<std::string, std::string>>;

template <class Product, class... Args>
class Registry {
 public:
  using Factory = std::function<std::unique_ptr<Product>(Args...)>;

  /// `kind` names the component kind in messages, e.g. "environment".
  explicit Registry(std::string kind) : kind_(std::move(kind)) {}

  /// Adds a factory under a canonical name, with the facts that hold for its product and the
  /// component-specific options it reads. Throws if the name is taken.
  Registry& add(const std::string& name, Factory factory, std::string description = {},
                std::vector<std::string> facts = {}, std::vector<std::string> options = {}) {
    if (factory == nullptr) {
      throw std::invalid_argument("Registry::add(): null factory for " + kind_ + " '" + name + "'");
    }
    if (contains(name)) {
      throw std::invalid_argument("Registry::add(): " + kind_ + " '" + name +
                                  "' is already registered");
    }
    entries_.emplace(name, Entry{std::move(factory),
                                 std::move(description),
                                 std::move(facts),
                                 std::move(options),
                                 {},
                                 {}});
    return *this;
  }

  /// Gives the entry `name` option values of its own: `defaults` for options the user did not
  /// set, and `needs`, values the component requires (also applied when not set; a different
  /// value given is an error of the caller's option check). Throws if the name is unknown.
  Registry& setOptionValues(const std::string& name, OptionValues defaults,
                            OptionValues needs = {}) {
    Entry& entry = entries_.at(canonical(name));
    entry.defaults = std::move(defaults);
    entry.needs = std::move(needs);
    return *this;
  }

  /// Makes `alias` another spelling of the registered `name`.
  Registry& addAlias(const std::string& alias, const std::string& name) {
    if (entries_.count(name) == 0) {
      throw std::invalid_argument("Registry::addAlias(): unknown " + kind_ + " '" + name + "'");
    }
    if (contains(alias)) {
      throw std::invalid_argument("Registry::addAlias(): " + kind_ + " '" + alias +
                                  "' is already registered");
    }
    aliases_.emplace(alias, name);
    return *this;
  }

  /// True if `name` is a canonical name or an alias.
  bool contains(const std::string& name) const {
    return entries_.count(name) > 0 || aliases_.count(name) > 0;
  }

  /// The canonical name of `name` (itself or the name it aliases). Throws if unknown.
  std::string canonical(const std::string& name) const {
    if (entries_.count(name) > 0) return name;
    const auto alias = aliases_.find(name);
    if (alias != aliases_.end()) return alias->second;
    throw std::invalid_argument(unknownMessage(name));
  }

  /// Builds the product registered under `name`. Throws std::invalid_argument listing the
  /// valid names if `name` is unknown.
  std::unique_ptr<Product> create(const std::string& name, Args... args) const {
    return entries_.at(canonical(name)).factory(std::forward<Args>(args)...);
  }

  /// Canonical names, sorted.
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& e : entries_) out.push_back(e.first);
    return out;
  }

  /// Canonical names and aliases, sorted: every spelling `create` accepts.
  std::vector<std::string> allNames() const {
    std::vector<std::string> out = names();
    for (const auto& a : aliases_) out.push_back(a.first);
    std::sort(out.begin(), out.end());
    return out;
  }

  /// Every spelling `create` accepts with its canonical name (for an option that takes any of
  /// them): each canonical name, sorted, followed by its aliases.
  std::vector<std::pair<std::string, std::string>> spellings() const {
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& e : entries_) {
      out.emplace_back(e.first, e.first);
      for (const auto& a : aliases_) {
        if (a.second == e.first) out.emplace_back(a.first, e.first);
      }
    }
    return out;
  }

  const std::string& description(const std::string& name) const {
    return entries_.at(canonical(name)).description;
  }

  /// True if `fact` was registered for `name` (a canonical name or an alias). Throws if the
  /// name is unknown.
  bool hasFact(const std::string& name, const std::string& fact) const {
    const auto& facts = entries_.at(canonical(name)).facts;
    return std::find(facts.begin(), facts.end(), fact) != facts.end();
  }
  /// Canonical names whose entry has `fact`, sorted.
  std::vector<std::string> namesWith(const std::string& fact) const {
    std::vector<std::string> out;
    for (const auto& [name, entry] : entries_) {
      if (std::find(entry.facts.begin(), entry.facts.end(), fact) != entry.facts.end()) {
        out.push_back(name);
      }
    }
    return out;
  }
  /// True if the entry of `name` reads the component-specific `option`. Throws if the name
  /// is unknown.
  bool takesOption(const std::string& name, const std::string& option) const {
    const auto& options = entries_.at(canonical(name)).options;
    return std::find(options.begin(), options.end(), option) != options.end();
  }
  /// Canonical names whose entry reads `option`, sorted.
  std::vector<std::string> namesTaking(const std::string& option) const {
    std::vector<std::string> out;
    for (const auto& [name, entry] : entries_) {
      if (std::find(entry.options.begin(), entry.options.end(), option) != entry.options.end()) {
        out.push_back(name);
      }
    }
    return out;
  }
  /// The option defaults and required values of `name` (setOptionValues). Throw if unknown.
  const OptionValues& defaults(const std::string& name) const {
    return entries_.at(canonical(name)).defaults;
  }
  const OptionValues& needs(const std::string& name) const {
    return entries_.at(canonical(name)).needs;
  }
  /// Every component-specific option some entry reads, sorted and without repeats.
  std::vector<std::string> specificOptions() const {
    std::vector<std::string> out;
    for (const auto& e : entries_)
      out.insert(out.end(), e.second.options.begin(), e.second.options.end());
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }
  const std::string& kind() const { return kind_; }

 private:
  struct Entry {
    Factory factory;
    std::string description;
    std::vector<std::string> facts;
    std::vector<std::string> options;
    OptionValues defaults;
    OptionValues needs;
  };

  std::string unknownMessage(const std::string& name) const {
    return "unknown " + kind_ + " '" + name + "'; valid " + kind_ + "s: " + joinNames(allNames());
  }

  std::string kind_;
  std::map<std::string, Entry> entries_;
  std::map<std::string, std::string> aliases_;
};

}  // namespace rl_common
