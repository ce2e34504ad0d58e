/**
 * ROS adapter for OptionParser: the same options as the command line, read from `~private`
 * parameters of a node. Header-only, so that rl_common's library stays free of ROS; include it
 * only from nodes and `_ros` targets.
 *
 * A parameter's name is the option's name with '-' turned into '_' (ROS names allow no dashes),
 * e.g. `--explore-steps` is `~explore_steps`. Values may be bool, int, double or string. Flags
 * take a bool: `~deterministic: true` acts as `--deterministic`, `~deterministic: false` as its
 * opposite. The command line is applied after the parameters, so it wins. startNode() is the
 * start of every node's main(): options, parameters, checks, help and exit codes in one place.
 */
#pragma once

#include <ros/console.h>
#include <ros/master.h>
#include <ros/node_handle.h>

#include <functional>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "rl_common/option_parser.h"

namespace rl_common {

/// The ROS parameter name of an option.
inline std::string paramNameOf(std::string option) {
  for (char& c : option) {
    if (c == '-') c = '_';
  }
  return option;
}

/// Applies every `~name` parameter that matches an option (any spelling). Throws OptionError
/// naming the parameter if its type or value is invalid.
inline void loadPrivateParams(OptionParser& parser, const ros::NodeHandle& pnh) {
  for (const OptionParser::Spec& spec : parser.specs()) {
    std::vector<std::string> spellings = spec.aliases;
    spellings.insert(spellings.begin(), spec.name);
    for (const std::string& spelling : spellings) {
      const std::string param = paramNameOf(spelling);
      XmlRpc::XmlRpcValue v;
      if (!pnh.getParam(param, v)) continue;
      std::ostringstream text;
      switch (v.getType()) {
        case XmlRpc::XmlRpcValue::TypeBoolean:
          text << (static_cast<bool>(v) ? "true" : "false");
          break;
        case XmlRpc::XmlRpcValue::TypeInt:
          text << static_cast<int>(v);
          break;
        case XmlRpc::XmlRpcValue::TypeDouble:
          text.precision(17);
          text << static_cast<double>(v);
          break;
        case XmlRpc::XmlRpcValue::TypeString:
          text << static_cast<std::string>(v);
          break;
        default:
          throw OptionError("parameter " + pnh.resolveName(param) +
                            ": expected a bool, number or string");
      }
      try {
        parser.set(spelling, text.str());
      } catch (const OptionError& e) {
        throw OptionError("parameter " + pnh.resolveName(param) + ": " + e.what());
      }
    }
  }
}

/// Reads `~private` parameters, then the command line (ros::init must have removed the
/// remapping arguments). Returns false if --help was given.
inline bool parseNodeOptions(OptionParser& parser, int argc, const char* const* argv,
                             const ros::NodeHandle& pnh) {
  loadPrivateParams(parser, pnh);
  return parser.parse(argc, argv);
}

/// What startNode() leaves to main(): run the node while `privateHandle` lives, or return
/// `exitCode`.
struct NodeStart {
  /// Null: main() returns exitCode. Kept until main() returns: when the last node handle goes,
  /// the node shuts down, and logging with it (a temporary handle silenced every later ROS_*
  /// line).
  std::unique_ptr<ros::NodeHandle> privateHandle;
  int exitCode = 0;  ///< 0 after --help, 2 for a bad option or parameter
  explicit operator bool() const { return privateHandle != nullptr; }
};

/// "program: message", without a second prefix when the message has it already (the
/// OptionParser names its program in its own errors).
inline std::string prefixedError(const std::string& program, const std::string& message) {
  const std::string prefix = program + ": ";
  return message.rfind(prefix, 0) == 0 ? message : prefix + message;
}

/// Every node's start: the command line first (--help and a mistyped option need no master),
/// then the `~private` parameters and the command line again (it wins), then `check` (the
/// node's own option rules; throws). With no master to reach, `check` also runs on the command
/// line alone before the node waits for one, so a bad value (`--env nosuch`) is reported at
/// once instead of after a master appears: no parameter could have been read to change it.
/// --help prints the help and `helpExtra`; an error prints "program: message" to stderr and
/// gives exit code 2. On success logs the configuration ("configuration: name=value ...",
/// rosconsole logger `program`). `check` must be safe to run twice (it validates and derives).
inline NodeStart startNode(OptionParser& parser, int argc, const char* const* argv,
                           const std::string& program, const std::function<void()>& check = {},
                           const std::string& helpExtra = "") {
  NodeStart start;
  try {
    if (!parser.parse(argc, argv)) {
      std::cout << parser.help() << helpExtra;
      return start;
    }
    if (check && !ros::master::check()) check();
    start.privateHandle = std::make_unique<ros::NodeHandle>("~");  // waits for a master
    parseNodeOptions(parser, argc, argv, *start.privateHandle);    // no --help: seen above
    if (check) check();
  } catch (const std::exception& e) {
    std::cerr << prefixedError(program, e.what()) << "\n";
    start.privateHandle.reset();
    start.exitCode = 2;
    return start;
  }
  ROS_INFO_STREAM_NAMED(program, "configuration: " << parser.currentValuesLine());
  return start;
}

}  // namespace rl_common
