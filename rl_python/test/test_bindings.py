#!/usr/bin/env python3
"""The rl_python module against the C++ it binds: LightWorld's known transitions and a
hand-written plan through room 0, the true model against steps, seeded resets and runs, C++
run() against the Python loop, option errors with the command line's exact messages, the
reward breakdown, and a TEXPLORE agent that learns TwoRooms.

Run after sourcing the workspace (catkin's run_tests does):
    /usr/bin/python3 rl_python/test/test_bindings.py [--xunit FILE]
"""
import math
import random
import sys
import unittest

import numpy as np

import rl_python as rl

# LightWorld's actions and features (rl_env/env/light_world.h).
NORTH, EAST, WEST, SOUTH, PICKUP, PRESS = range(6)
NS, EW, HAVE_KEY, DOOR_OPEN, ROOM = range(5)
KEY_N, KEY_E, KEY_W, KEY_S = 5, 6, 7, 8


def key_cell(obs):
    """The key's cell from the key sensors (10 - axis distance on the key's side)."""
    ns = obs[NS] + (10 - obs[KEY_N]) if obs[KEY_N] > 0 else obs[NS] - (10 - obs[KEY_S])
    ew = obs[EW] + (10 - obs[KEY_E]) if obs[KEY_E] > 0 else obs[EW] - (10 - obs[KEY_W])
    return int(ns), int(ew)


def moves_to(obs, ns, ew):
    """Moves from the agent's cell to (ns, ew) inside a room, north is +ns, east is +ew."""
    d_ns, d_ew = ns - int(obs[NS]), ew - int(obs[EW])
    return ([NORTH] * d_ns if d_ns > 0 else [SOUTH] * -d_ns) + \
           ([EAST] * d_ew if d_ew > 0 else [WEST] * -d_ew)


class Steps:
    """Steps `env` and keeps every (action, obs, reward)."""

    def __init__(self, env):
        self.env, self.log = env, []
        self.obs, _ = env.reset()

    def do(self, actions):
        for a in actions:
            obs, reward, terminated, truncated, info = self.env.step(a)
            self.log.append((a, obs, reward))
            self.obs = obs
        return self.obs


def room0_plan(env):
    """Room 0 (lock (2,6), door (5,6), both in the east wall): key, lock, door, out.
    Returns the Steps and the index of the exit step."""
    s = Steps(env)
    assert s.obs[ROOM] == 0
    s.do(moves_to(s.obs, *key_cell(s.obs)))
    s.do([PICKUP])
    s.do(moves_to(s.obs, 2, 5) + [EAST, PRESS, WEST])  # onto the lock, press, back in
    s.do(moves_to(s.obs, 5, 5) + [EAST])  # onto the open door
    s.do([EAST])  # through it
    return s


class LightWorldFromPython(unittest.TestCase):
    def test_description_is_the_cpp_one(self):
        d = rl.make_env("lightworld").description
        self.assertEqual((d.num_features, d.num_actions), (17, 6))
        self.assertEqual(d.max_features, [8, 8, 1, 1, 3] + [10] * 12)
        self.assertEqual(d.min_features, [0] * 17)
        self.assertEqual((d.min_reward, d.max_reward, d.reward_range), (0.0, 10.0, 10.0))
        self.assertFalse(d.episodic)
        self.assertTrue(d.stochastic)
        self.assertFalse(rl.make_env("lightworld", stochastic=False).description.stochastic)
        self.assertEqual(d.title, "Environment: LightWorld\n")

    def test_reset_and_step_shapes(self):
        env = rl.make_env("lightworld", seed=4)
        obs, info = env.reset()
        self.assertEqual(info, {})
        self.assertEqual((obs.dtype, obs.shape), (np.float32, (17,)))
        obs, reward, terminated, truncated, info = env.step(NORTH)
        self.assertEqual((obs.shape, type(reward), terminated, truncated, info),
                         ((17,), float, False, False, {}))
        np.testing.assert_array_equal(obs, env.observation)
        self.assertEqual(env.episode_steps, 1)

    def test_known_plan_leaves_room_0_with_10(self):
        for seed in (1, 2, 3):
            env = rl.make_env("lightworld", stochastic=False, seed=seed)
            s = room0_plan(env)
            rewards = [r for _, _, r in s.log]
            self.assertEqual(rewards[-1], 10.0, seed)
            self.assertEqual(sum(rewards), 10.0, seed)
            pickup = [o for a, o, _ in s.log if a == PICKUP][0]
            self.assertEqual(pickup[HAVE_KEY], 1.0)
            self.assertEqual(list(pickup[KEY_N:KEY_S + 1]), [0, 0, 0, 0])  # key lights off
            press = [o for a, o, _ in s.log if a == PRESS][0]
            self.assertEqual((press[NS], press[EW], press[DOOR_OPEN]), (2, 6, 1))
            # Door (5,6) seen from the lock (2,6): N = 10 - 3, E = W = 10, S = 0 (C++ test).
            self.assertEqual(list(press[13:17]), [7, 10, 10, 0])
            # Into room 1 at its entry cell (3, 0), door closed, key not held.
            last = s.obs
            self.assertEqual((last[ROOM], last[NS], last[EW], last[HAVE_KEY], last[DOOR_OPEN]),
                             (1, 3, 0, 0, 0))
            # The same actions in C++ from the same seed: the same reward and final state.
            actions = [a for a, _, _ in s.log]
            again = rl.make_env("lightworld", stochastic=False, seed=seed)
            self.assertEqual(again.run(actions), 10.0)
            np.testing.assert_array_equal(again.observation, last)

    def test_walls_block_and_reward_nothing(self):
        env = rl.make_env("lightworld", stochastic=False)
        obs, _ = env.reset()
        s = Steps(env)
        s.do(moves_to(obs, 1, int(obs[EW])))  # to the south wall
        obs, reward, _, _, _ = env.step(SOUTH)
        self.assertEqual((obs[NS], reward), (1, 0.0))

    def test_true_model_prediction_equals_the_step(self):
        env = rl.make_env("lightworld", stochastic=False)
        model = env.true_model
        self.assertTrue(env.has_true_model)
        states = model.reachable_states()
        self.assertGreater(len(states), 1000)
        checked_single = 0
        for s in states[::97]:
            for a in range(6):
                outcomes = model.transitions(s, a)
                self.assertAlmostEqual(sum(o.probability for o in outcomes), 1.0, places=9)
                model.set_state(s)
                obs, reward, terminated, _, _ = env.step(a)
                match = [o for o in outcomes if np.array_equal(o.next, obs)]
                self.assertEqual(len(match), 1, (list(s), a))
                self.assertEqual((match[0].reward, match[0].terminal), (reward, terminated))
                if len(outcomes) == 1:  # deterministic: only a room exit places a key at random
                    checked_single += 1
        self.assertGreater(checked_single, 100)

    def test_stochastic_steps_follow_the_distribution(self):
        env = rl.make_env("lightworld", seed=9)
        model = env.true_model
        start = env.reset()[0]
        outcomes = model.transitions(start, EAST)
        self.assertEqual(len(outcomes), 3)  # as intended 0.9, slips 0.05 each (C++ test)
        counts = [0] * len(outcomes)
        for _ in range(2000):
            model.set_state(start)
            obs = env.step(EAST)[0]
            counts[[np.array_equal(o.next, obs) for o in outcomes].index(True)] += 1
        for o, c in zip(outcomes, counts):
            self.assertLess(abs(c / 2000 - o.probability), 0.03)

    def test_no_true_model(self):
        env = rl.make_env("mcar")
        self.assertIsNone(env.true_model)
        self.assertFalse(env.has_true_model)
        self.assertEqual(rl.list_envs(rl.TRUE_MODEL), ["fourrooms", "lightworld", "taxi",
                                                       "tworooms"])


class SameSeedSameRun(unittest.TestCase):
    def test_seeded_reset_is_the_env_built_with_that_seed(self):
        actions = [random.Random(0).randrange(6) for _ in range(300)]
        env = rl.make_env("lightworld")
        env.step(NORTH)
        first, _ = env.reset(seed=5)
        fresh = rl.make_env("lightworld", seed=5)
        np.testing.assert_array_equal(first, fresh.reset()[0])
        self.assertEqual(env.seed, 5)
        self.assertEqual(env.options["seed"], "5")
        a = [env.step(x) for x in actions]
        b = [fresh.step(x) for x in actions]
        for x, y in zip(a, b):
            np.testing.assert_array_equal(x[0], y[0])
            self.assertEqual(x[1:4], y[1:4])

    def test_cpp_run_equals_the_python_loop(self):
        # Taxi is episodic: both loops reset on termination.
        rng = random.Random(3)
        actions = [rng.randrange(6) for _ in range(5000)]
        py_env, cpp_env = rl.make_env("taxi", seed=2), rl.make_env("taxi", seed=2)
        total, episodes = 0.0, 0
        py_env.reset()
        for a in actions:
            if py_env.terminated:
                py_env.reset()
                episodes += 1
            total += py_env.step(a)[1]
        self.assertGreater(episodes, 0)
        self.assertEqual(cpp_env.run(actions), total)
        np.testing.assert_array_equal(cpp_env.observation, py_env.observation)

    def run_vanir(self, agent_seed, env_seed, steps=120):
        env = rl.make_env("lightworld", seed=env_seed)
        agent = rl.make_agent("texplore", env, v=1, n=3, rollouts=30, lambda_=1, seed=agent_seed)
        obs, _ = env.reset()
        action = agent.first_action(obs)
        actions, rewards, bonuses = [action], [], []
        for _ in range(steps):
            obs, reward, _, _, _ = env.step(action)
            action = agent.next_action(reward, obs)
            b = agent.reward_breakdown()
            actions.append(action)
            rewards.append(reward)
            bonuses.append((b.variance, b.novelty, b.other))
        return actions, rewards, bonuses

    def test_same_seeds_same_rewards(self):
        one, two = self.run_vanir(7, 8), self.run_vanir(7, 8)
        self.assertEqual(one, two)
        self.assertNotEqual(one[0], self.run_vanir(9, 8)[0])  # another agent seed: other actions


class OptionErrors(unittest.TestCase):
    def assertValueError(self, message, f, *args, **kwargs):
        with self.assertRaises(ValueError) as c:
            f(*args, **kwargs)
        self.assertEqual(str(c.exception), message)

    def test_environment_options(self):
        self.assertValueError("option --env: unknown environment 'nosuch'; valid environments: "
                              + ", ".join(rl.list_envs()), rl.make_env, "nosuch")
        self.assertValueError("option --delay applies only to --env mcar, tworooms, not to "
                              "'lightworld'", rl.make_env, "lightworld", delay=2)
        self.assertValueError("option --delay: invalid value '-1' (must be in [0, 1000])",
                              rl.make_env, "tworooms", delay=-1)
        self.assertValueError(
            "make_env: unknown option 'bogus'; valid options: --help, --env, --seed, "
            "--stochastic, --deterministic, --delay, --nsectors, --nstocks, --lag, --nolag, "
            "--highvar", rl.make_env, "taxi", bogus=1)
        with self.assertRaisesRegex(ValueError, r"^option --seed: invalid value 'x' \("):
            rl.make_env("taxi", seed="x")
        # Flags: True gives the flag, False its opposite.
        self.assertEqual(rl.make_env("taxi", deterministic=True).options["stochastic"], "false")
        self.assertEqual(rl.make_env("taxi", stochastic=False).options["stochastic"], "false")
        self.assertEqual(rl.make_env("tworooms", delay=2).options["delay"], "2")

    def test_agent_options(self):
        env = rl.make_env("lightworld")
        self.assertValueError("unknown agent 'x'; valid agents: " + ", ".join(rl.list_agents()),
                              rl.make_agent, "x", env)
        self.assertValueError("option --alpha applies only to --agent "
                              + ", ".join(rl.list_agents(rl.MODEL_FREE)) + ", not to 'texplore'",
                              rl.make_agent, "texplore", env, alpha=0.5)
        self.assertValueError("option --gamma: invalid value '2' (must be in [0, 1])",
                              rl.make_agent, "qlearner", env, gamma=2)
        self.assertValueError("option --combo separate needs --nmodels > 1 (one tree has "
                              "nothing to combine)", rl.make_agent, "texplore", env, nmodels=1,
                              combo="separate")
        self.assertValueError("option --tau applies to --explore boltzmann, not to 'greedy'",
                              rl.make_agent, "texplore", env, tau=0.5)
        with self.assertRaisesRegex(ValueError, r"^make_agent: unknown option 'bogus'; valid "
                                    r"options: --help, --agent, --gamma, --discountfactor, "):
            rl.make_agent("texplore", env, bogus=1)
        self.assertValueError("agent optimal plans on the environment's true model: give "
                              "make_agent an environment with one (fourrooms, lightworld, taxi, "
                              "tworooms)", rl.make_agent, "optimal", rl.make_env("mcar"))

    def test_agent_defaults_as_on_the_command_line(self):
        env = rl.make_env("lightworld")
        vanir = rl.make_agent("texplore", env, v=1, n=3, rollouts=10, lambda_=1, seed=4)
        self.assertEqual((vanir.name, vanir.seed), ("texplore", 4))
        o = vanir.options
        self.assertEqual((o["explore"], o["nmodels"], o["combo"], o["lambda"], o["nstates"]),
                         ("variancenovelty", "5", "separate", "1", "0"))
        self.assertEqual(rl.make_agent("texplore", env, nmodels=1).options["combo"], "best")
        self.assertEqual(rl.make_agent("texplore", env, rollouts=10).options["explore"], "greedy")
        self.assertEqual(rl.make_agent("rmax", env).options["model"], "tabular")
        self.assertEqual(rl.make_agent("qlearner", env, nstates=[2] * 17).options["nstates"],
                         ",".join(["2"] * 17))

    def test_other_errors(self):
        env = rl.make_env("lightworld")
        self.assertValueError("LightWorld::apply(): action 6 out of range [0, 5]", env.step, 6)
        with self.assertRaises(TypeError):
            env.step("north")
        taxi = rl.make_env("taxi", stochastic=False)
        agent = rl.make_agent("optimal", taxi)
        obs, _ = taxi.reset()
        action = agent.first_action(obs)
        for _ in range(100):
            obs, reward, terminated, _, _ = taxi.step(action)
            if terminated:
                break
            action = agent.next_action(reward, obs)
        self.assertTrue(terminated)
        self.assertEqual(reward, 20.0)
        with self.assertRaises(RuntimeError) as c:
            taxi.step(0)
        self.assertEqual(str(c.exception),
                         "PyEnvironment::step(): the episode has terminated; call reset()")
        taxi.reset()
        taxi.step(0)
        with self.assertRaisesRegex(RuntimeError, r"^PyAgent::setIntrinsicEnabled\(\): agent "
                                    r"qlearner is not model-based"):
            rl.make_agent("qlearner", env).set_intrinsic_enabled(False)
        with self.assertRaisesRegex(ValueError, "1-D"):
            rl.make_agent("qlearner", env).first_action(np.zeros((17, 1)))


class Agents(unittest.TestCase):
    def test_reward_breakdown(self):
        env = rl.make_env("lightworld", seed=3)
        agent = rl.make_agent("texplore", env, v=1, n=3, rollouts=20, seed=3)
        obs, _ = env.reset()
        action = agent.first_action(obs)
        b = agent.reward_breakdown()
        # Nothing seen yet: novelty is n * 1 (the largest), no trees to disagree.
        self.assertEqual((b.external, b.variance, b.novelty, b.other), (0.0, 0.0, 3.0, 0.0))
        seen_variance = False
        for step in range(60):
            obs, reward, _, _, _ = env.step(action)
            action = agent.next_action(reward, obs)
            b = agent.reward_breakdown()
            self.assertEqual(b.external, reward)
            self.assertAlmostEqual(b.intrinsic, b.variance + b.novelty + b.other, places=6)
            self.assertTrue(0.0 <= b.novelty <= 3.0)
            self.assertGreaterEqual(b.variance, 0.0)
            self.assertEqual(b.other, 0.0)
            self.assertFalse(math.isnan(b.planned_value))
            seen_variance |= b.variance > 0.0
        self.assertTrue(seen_variance)
        agent.set_intrinsic_enabled(False)  # the task phase: no bonuses any more
        for step in range(5):
            obs, reward, _, _, _ = env.step(action)
            action = agent.next_action(reward, obs)
            self.assertEqual(agent.reward_breakdown().intrinsic, 0.0)
        self.assertIsNone(rl.make_agent("qlearner", env).reward_breakdown())

    def episode_lengths(self, agent_name, seed, episodes=10, cap=1000, **options):
        env = rl.make_env("tworooms", stochastic=False, seed=seed)
        agent = rl.make_agent(agent_name, env, seed=seed, **options) if agent_name else None
        rng = random.Random(seed)
        lengths = []
        for _ in range(episodes):
            obs, _ = env.reset()
            action = agent.first_action(obs) if agent else rng.randrange(4)
            for t in range(1, cap + 1):
                obs, reward, terminated, _, _ = env.step(action)
                if terminated:
                    if agent:
                        agent.last_action(reward)
                    break
                action = agent.next_action(reward, obs) if agent else rng.randrange(4)
            lengths.append(t)
        return lengths

    def test_texplore_learns_tworooms(self):
        # Same start states (env seed) for all three; the optimal agent plans on the true model.
        for seed in (1, 2, 3):
            texplore = self.episode_lengths("texplore", seed, rollouts=100)
            optimal = self.episode_lengths("optimal", seed)
            uniform = self.episode_lengths(None, seed)
            late = sum(texplore[-5:]) / 5
            self.assertLessEqual(late, 1.25 * sum(optimal[-5:]) / 5 + 1, (seed, texplore, optimal))
            self.assertLess(late, sum(uniform) / len(uniform) / 5, (seed, texplore, uniform))


class Registry(unittest.TestCase):
    def test_lists(self):
        self.assertIn("lightworld", rl.list_envs())
        self.assertEqual(rl.list_envs(), sorted(rl.list_envs()))
        self.assertIn("texplore", rl.list_agents())
        self.assertEqual(rl.list_agents(rl.PLANS_ON_TRUE_MODEL), ["optimal"])
        self.assertEqual(rl.list_agents(rl.MODEL_BASED), ["modelbased", "rmax", "texplore"])
        for name in rl.list_envs():
            d = rl.make_env(name).description
            self.assertEqual(len(d.min_features), d.num_features)
            self.assertTrue(all(lo <= hi for lo, hi in zip(d.min_features, d.max_features)))
        self.assertIn("--rollouts", rl.agent_help())
        self.assertIn("--deterministic", rl.env_help())


if __name__ == "__main__":
    argv = sys.argv[1:]
    if "--xunit" in argv:
        i = argv.index("--xunit")
        path = argv[i + 1]
        import rosunit
        suite = unittest.defaultTestLoader.loadTestsFromModule(sys.modules[__name__])
        result = rosunit.create_xml_runner("rl_python", "test_bindings",
                                           results_file=path).run(suite)
        sys.exit(0 if result.wasSuccessful() else 1)
    unittest.main()
