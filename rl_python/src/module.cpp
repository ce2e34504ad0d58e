// The Python module `rl_python` (pybind11): the suite's environments and agents, built from
// their registries by name with the command line's option names (make_env, make_agent), with
// a Gymnasium-style reset/step (no Gymnasium dependency), the environments' descriptions and
// true models, and the agents' reward breakdown. Errors: std::invalid_argument (which includes
// rl_common::OptionError: unknown names and options, bad values) and std::out_of_range (an
// action outside the range) raise ValueError with the C++ message; every other std::exception
// raises RuntimeError.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "rl_agent/agent/agent_options.h"
#include "rl_agent/agent/agent_registry.h"
#include "rl_common/option_parser.h"
#include "rl_common/registry.h"
#include "rl_env/env/environment_options.h"
#include "rl_env/env/environment_registry.h"
#include "rl_python/option_values.h"
#include "rl_python/py_agent.h"
#include "rl_python/py_environment.h"

namespace py = pybind11;

namespace rl_python {
namespace {

using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

/// The catalog the module offers: rl_env's built-in environments.
const rl_env::EnvironmentCatalog& catalog() { return rl_env::builtinEnvironments(); }

rl_common::State toState(const FloatArray& a) {
  if (a.ndim() != 1) {
    throw std::invalid_argument("a state is a 1-D sequence of features, got an array of " +
                                std::to_string(a.ndim()) + " dimensions");
  }
  return rl_common::State(a.data(), a.data() + a.size());
}

py::array_t<float> toArray(const rl_common::State& s) {
  return py::array_t<float>(static_cast<py::ssize_t>(s.size()), s.data());
}

/// A keyword argument as command-line text: bools as true/false, sequences comma-separated
/// (--nstates 3,0,2), everything else as str() gives it.
std::string optionText(const std::string& name, const py::handle& value) {
  if (value.is_none()) {
    throw rl_common::OptionError("option --" + name + ": None is not a value");
  }
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    std::string text;
    for (const py::handle item : value) {
      text += (text.empty() ? "" : ",") + py::str(item).cast<std::string>();
    }
    return text;
  }
  return py::str(value).cast<std::string>();
}

OptionValues optionValues(const py::kwargs& kwargs) {
  OptionValues values;
  for (const auto& [key, value] : kwargs) {
    std::string name = py::str(key).cast<std::string>();
    // lambda_=1 for --lambda: a trailing underscore spells an option that is a Python keyword.
    if (name.size() > 1 && name.back() == '_') name.pop_back();
    values.emplace_back(name, optionText(name, value));
  }
  return values;
}

py::dict optionDict(const OptionValues& values) {
  py::dict d;
  for (const auto& [name, value] : values) d[py::str(name)] = value;
  return d;
}

/// An environment's true model, valid across seeded resets (which rebuild the environment).
struct TrueModelHandle {
  std::shared_ptr<PyEnvironment> env;

  rl_common::TrueModel& model() const {
    rl_common::TrueModel* m = env->trueModel();
    if (m == nullptr) throw std::logic_error("TrueModel: the environment has none");
    return *m;
  }
};

}  // namespace
}  // namespace rl_python

PYBIND11_MODULE(rl_python, m) {
  using namespace rl_python;
  m.doc() =
      "The TEXPLORE suite's environments and agents (rl_env, rl_agent) from Python.\n\n"
      "make_env(name, **options) and make_agent(name, env, **options) take the option names of "
      "the env and agent nodes' command lines (make_env('lightworld', stochastic=False, seed=3),"
      " make_agent('texplore', env, v=1, n=3, rollouts=100, seed=1)). Env has a Gymnasium-style"
      " reset(seed=None) -> (obs, info) and step(action) -> (obs, reward, terminated, "
      "truncated, info); Agent has the C++ protocol first_action(obs), next_action(reward, obs),"
      " last_action(reward). Same seeds (and a fixed rollouts count) give the same run.";

  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const py::error_already_set&) {
      throw;  // a Python error raised inside: pass it on untouched
    } catch (const py::builtin_exception&) {
      throw;  // pybind11's own (cast errors, stop iteration ...): its default translation
    } catch (const std::invalid_argument& e) {
      PyErr_SetString(PyExc_ValueError, e.what());  // OptionError, unknown names, bad states
    } catch (const std::out_of_range& e) {
      PyErr_SetString(PyExc_ValueError, e.what());  // an action outside the range
    } catch (const std::exception& e) {
      PyErr_SetString(PyExc_RuntimeError, e.what());
    }
  });

  m.attr("TRUE_MODEL") = rl_env::kTrueModelFact;
  m.attr("RENDER") = rl_env::kRenderFact;
  m.attr("MODEL_BASED") = rl_agent::kModelBasedFact;
  m.attr("MODEL_FREE") = rl_agent::kModelFreeFact;
  m.attr("PLANS_ON_TRUE_MODEL") = rl_agent::kTrueModelPlannerFact;

  py::class_<rl_common::EnvironmentDescription>(
      m, "EnvDescription", "What an agent is told about a task (rl_msgs/RLEnvDescription).")
      .def_property_readonly(
          "num_actions", [](const rl_common::EnvironmentDescription& d) { return d.numActions; })
      .def_property_readonly("num_features", &rl_common::EnvironmentDescription::numFeatures)
      .def_readonly("min_features", &rl_common::EnvironmentDescription::minFeatures,
                    "declared minimum of each feature")
      .def_readonly("max_features", &rl_common::EnvironmentDescription::maxFeatures,
                    "declared maximum of each feature")
      .def_readonly("min_reward", &rl_common::EnvironmentDescription::minReward)
      .def_readonly("max_reward", &rl_common::EnvironmentDescription::maxReward)
      .def_property_readonly("reward_range", &rl_common::EnvironmentDescription::rewardRange,
                             "max_reward - min_reward")
      .def_readonly("episodic", &rl_common::EnvironmentDescription::episodic)
      .def_readonly("stochastic", &rl_common::EnvironmentDescription::stochastic)
      .def_readonly("title", &rl_common::EnvironmentDescription::title,
                    "e.g. 'Environment: LightWorld\\n', as the original's")
      .def("__repr__", [](const rl_common::EnvironmentDescription& d) {
        return "EnvDescription(title=" + py::repr(py::str(d.title)).cast<std::string>() +
               ", num_features=" + std::to_string(d.numFeatures()) +
               ", num_actions=" + std::to_string(d.numActions) + ", reward=[" +
               std::to_string(d.minReward) + ", " + std::to_string(d.maxReward) +
               "], episodic=" + (d.episodic ? "True" : "False") +
               ", stochastic=" + (d.stochastic ? "True" : "False") + ")";
      });

  py::class_<rl_common::Experience>(m, "Experience", "One transition (s, a, r, s', terminal).")
      .def(py::init([](const FloatArray& s, int action, float reward, const FloatArray& next,
                       bool terminal) {
             return rl_common::Experience{toState(s), action, reward, toState(next), terminal};
           }),
           py::arg("s"), py::arg("action"), py::arg("reward"), py::arg("next"),
           py::arg("terminal") = false)
      .def_property_readonly("s", [](const rl_common::Experience& e) { return toArray(e.s); })
      .def_readonly("action", &rl_common::Experience::action)
      .def_readonly("reward", &rl_common::Experience::reward)
      .def_property_readonly("next", [](const rl_common::Experience& e) { return toArray(e.next); })
      .def_readonly("terminal", &rl_common::Experience::terminal);

  py::class_<rl_common::Outcome>(m, "Outcome", "One possible result of an action.")
      .def_property_readonly("next", [](const rl_common::Outcome& o) { return toArray(o.next); })
      .def_readonly("reward", &rl_common::Outcome::reward)
      .def_readonly("terminal", &rl_common::Outcome::terminal)
      .def_readonly("probability", &rl_common::Outcome::probability)
      .def("__repr__", [](const rl_common::Outcome& o) {
        return "Outcome(reward=" + std::to_string(o.reward) +
               ", terminal=" + (o.terminal ? "True" : "False") +
               ", probability=" + std::to_string(o.probability) + ")";
      });

  py::class_<TrueModelHandle>(m, "TrueModel",
                              "An environment's exact dynamics (rl_common::TrueModel).")
      .def(
          "transitions",
          [](const TrueModelHandle& h, const FloatArray& s, int action) {
            return h.model().transitions(toState(s), action);
          },
          py::arg("state"), py::arg("action"),
          "Every distinct outcome of `action` in `state`, probabilities summing to 1.")
      .def(
          "reachable_states",
          [](const TrueModelHandle& h) {
            py::list out;
            for (const rl_common::State& s : h.model().reachableStates()) out.append(toArray(s));
            return out;
          },
          "Every state reachable from the start states, each once, in a fixed order.")
      .def(
          "set_state",
          [](const TrueModelHandle& h, const FloatArray& s) { h.env->setState(toState(s)); },
          py::arg("state"),
          "Puts the environment in `state` (ValueError if it cannot occur); reset() then starts "
          "a new episode.");

  py::class_<PyEnvironment, std::shared_ptr<PyEnvironment>>(
      m, "Env", "An environment of the registry (make an instance with make_env).")
      .def(
          "reset",
          [](PyEnvironment& e, std::optional<std::uint64_t> seed) {
            return py::make_tuple(toArray(e.reset(seed)), py::dict());
          },
          py::arg("seed") = py::none(),
          "reset(seed=None) -> (obs, info). With a seed the environment is built anew with it "
          "(the C++ environment constructed with that seed); without, a new episode from its own "
          "random source (right after construction or a seeded reset: the start state it was "
          "built in).")
      .def(
          "step",
          [](PyEnvironment& e, int action) {
            const PyEnvironment::Step s = e.step(action);
            return py::make_tuple(toArray(s.observation), s.reward, s.terminated, s.truncated,
                                  py::dict());
          },
          py::arg("action"),
          "step(action) -> (obs, reward, terminated, truncated, info). truncated is always "
          "False (no time limit); a terminated episode needs reset() before the next step.")
      .def(
          "run",
          [](PyEnvironment& e, const std::vector<int>& actions) {
            py::gil_scoped_release release;
            return e.run(actions);
          },
          py::arg("actions"),
          "Takes every action in C++ (reset on termination, as a Python loop of step() and "
          "reset() would) and returns the rewards' sum: the baseline of the Python boundary's "
          "cost.")
      .def_property_readonly("name", &PyEnvironment::name, "registry name")
      .def_property_readonly("description", &PyEnvironment::description)
      .def_property_readonly("num_actions",
                             [](const PyEnvironment& e) { return e.description().numActions; })
      .def_property_readonly("observation",
                             [](const PyEnvironment& e) { return toArray(e.observation()); })
      .def_property_readonly("terminated", &PyEnvironment::terminated)
      .def_property_readonly("episode_steps", &PyEnvironment::episodeSteps)
      .def_property_readonly("seed", [](const PyEnvironment& e) { return e.options().seed; })
      .def_property_readonly(
          "options", [](const PyEnvironment& e) { return optionDict(e.effectiveOptions()); },
          "every option's effective value (text, as the env node logs them)")
      .def_property_readonly("has_true_model",
                             [](const PyEnvironment& e) {
                               return e.catalog().registry().hasFact(e.name(),
                                                                     rl_env::kTrueModelFact);
                             })
      .def_property_readonly(
          "true_model",
          [](const std::shared_ptr<PyEnvironment>& e) -> std::optional<TrueModelHandle> {
            if (e->trueModel() == nullptr) return std::nullopt;
            return TrueModelHandle{e};
          },
          "the exact dynamics (TrueModel), or None")
      .def("seed_experiences", &PyEnvironment::seedExperiences,
           "transitions to give an agent before it acts (Agent.seed_experiences)")
      .def("__repr__", [](const PyEnvironment& e) {
        return "Env(" + py::repr(py::str(e.name())).cast<std::string>() +
               ", seed=" + std::to_string(e.options().seed) + ")";
      });

  py::class_<RewardParts>(m, "RewardBreakdown",
                          "The parts of the reward behind an agent's last action "
                          "(rl_agent/rl_reward_breakdown).")
      .def_readonly("external", &RewardParts::external,
                    "the environment's reward given with the last call (0 after first_action)")
      .def_readonly("variance", &RewardParts::variance, "VANIR's variance bonus of the action")
      .def_readonly("novelty", &RewardParts::novelty, "VANIR's novelty bonus of the action")
      .def_readonly("other", &RewardParts::other, "other intrinsic bonuses (R-MAX optimism ...)")
      .def_property_readonly("intrinsic", &RewardParts::intrinsic, "variance + novelty + other")
      .def_readonly("planned_value", &RewardParts::plannedValue,
                    "Q(s, a) of the action (NaN: none)")
      .def_readonly("value_spread", &RewardParts::valueSpread, "max Q - min Q at s (NaN: none)")
      .def("__repr__", [](const RewardParts& r) {
        return "RewardBreakdown(external=" + std::to_string(r.external) +
               ", variance=" + std::to_string(r.variance) +
               ", novelty=" + std::to_string(r.novelty) + ", other=" + std::to_string(r.other) +
               ")";
      });

  py::class_<PyAgent>(m, "Agent", "An agent of the registry (make an instance with make_agent).")
      .def(
          "first_action",
          [](PyAgent& a, const FloatArray& obs) {
            const rl_common::State s = toState(obs);
            py::gil_scoped_release release;
            return a.firstAction(s);
          },
          py::arg("obs"), "Starts an episode in `obs`; returns the action.")
      .def(
          "next_action",
          [](PyAgent& a, float reward, const FloatArray& obs) {
            const rl_common::State s = toState(obs);
            py::gil_scoped_release release;
            return a.nextAction(reward, s);
          },
          py::arg("reward"), py::arg("obs"),
          "The reward of the previous action and the new state; returns the next action.")
      .def(
          "last_action",
          [](PyAgent& a, float reward) {
            py::gil_scoped_release release;
            a.lastAction(reward);
          },
          py::arg("reward"), "The reward of the action that ended the episode.")
      .def("seed_experiences", &PyAgent::seedExperiences, py::arg("experiences"),
           "Learns from transitions given before acting (Env.seed_experiences()).")
      .def("save_policy", &PyAgent::savePolicy, py::arg("filename"),
           "Writes the policy file (the original's format) if the agent has one.")
      .def("reward_breakdown", &PyAgent::rewardBreakdown,
           "RewardBreakdown of the last action, or None for an agent without intrinsic rewards.")
      .def("set_intrinsic_enabled", &PyAgent::setIntrinsicEnabled, py::arg("enabled"),
           "Model-based agents: intrinsic rewards and exploratory choices on or off (the task "
           "phase of the paper's protocol).")
      .def_property_readonly("name", &PyAgent::name, "registry name")
      .def_property_readonly("seed", &PyAgent::seed)
      .def_property_readonly(
          "options", [](const PyAgent& a) { return optionDict(a.effectiveOptions()); },
          "every option's effective value after the agent's defaults (text)")
      .def("__repr__", [](const PyAgent& a) {
        return "Agent(" + py::repr(py::str(a.name())).cast<std::string>() +
               ", seed=" + std::to_string(a.seed()) + ")";
      });

  m.def(
      "list_envs",
      [](std::optional<std::string> fact) {
        const auto& r = catalog().registry();
        return fact ? r.namesWith(*fact) : r.names();
      },
      py::arg("fact") = py::none(),
      "Registry names of the environments (with `fact`, e.g. TRUE_MODEL: those that have it).");
  m.def(
      "list_agents",
      [](std::optional<std::string> fact) {
        const auto& r = rl_agent::agentRegistry();
        return fact ? r.namesWith(*fact) : r.names();
      },
      py::arg("fact") = py::none(),
      "Registry names of the agents (with `fact`, e.g. MODEL_BASED: those that have it).");
  m.def(
      "make_env",
      [](const std::string& name, const py::kwargs& kwargs) {
        return std::make_shared<PyEnvironment>(catalog(), name, optionValues(kwargs));
      },
      py::arg("name") = "lightworld",
      "make_env(name='lightworld', **options) -> Env, options named as the env node's "
      "(seed, stochastic, deterministic, delay, nsectors, nstocks, lag, nolag, highvar). "
      "ValueError with the command line's message for an unknown name or option or a bad "
      "value.");
  m.def(
      "make_agent",
      [](const std::string& name, const py::object& env, const py::kwargs& kwargs) {
        rl_common::EnvironmentDescription task;
        PyAgent::EnvironmentFactory source;
        std::shared_ptr<PyEnvironment> e;
        if (py::isinstance<PyEnvironment>(env)) {
          e = env.cast<std::shared_ptr<PyEnvironment>>();
          task = e->description();
          if (e->trueModel() != nullptr) source = [e] { return e->makeCopy(); };
        } else {
          task = env.cast<rl_common::EnvironmentDescription>();
        }
        return std::make_unique<PyAgent>(name, optionValues(kwargs), task, source,
                                         catalog().trueModelNames());
      },
      py::arg("name"), py::arg("env"),
      "make_agent(name, env, **options) -> Agent for the task of `env` (an Env or an "
      "EnvDescription), options named as the agent node's (seed, v, n, rollouts, lambda, "
      "gamma, model, planner, explore, ...). Without rollouts, texplore plans in real time at "
      "actrate (not reproducible); with rollouts=N it plans N rollouts per step.");
  m.def(
      "env_help",
      [] {
        rl_env::EnvironmentOptions o;
        rl_common::OptionParser parser("make_env", "make_env(name, **options)");
        rl_env::addEnvironmentOptions(parser, &o, catalog());
        return parser.help();
      },
      "The environment options with their defaults (the env node's --help).");
  m.def(
      "agent_help",
      [] {
        rl_agent::AgentOptions o;
        rl_common::OptionParser parser("make_agent", "make_agent(name, env, **options)");
        rl_agent::addAgentOptions(parser, &o);
        parser.value("seed", &o.seed, "seed of the agent's random source");
        return parser.help();
      },
      "The agent options with their defaults (the agent node's --help).");
}
