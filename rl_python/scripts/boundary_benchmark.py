#!/usr/bin/env python3
"""What the Python boundary costs: environment steps per second driven from Python
(env.step() in a loop, reset() on termination) against the same environment taking the same
action sequence in C++ (env.run(actions), one call), measured in the same run. Both start from
the same seed, so their rewards' sums must agree (checked). Prints both figures and the ratio;
a program, never a test.

    source .build/devel/setup.bash
    /usr/bin/python3 rl_python/scripts/boundary_benchmark.py [--steps N] [--repeats R] [ENV ...]
"""
import argparse
import random
import sys
import time

import rl_python as rl


def python_loop(env, actions):
    step, reset = env.step, env.reset
    total = 0.0
    for a in actions:
        if env.terminated:
            reset()
        total += step(a)[1]
    return total


def best_rate(run, make, actions, repeats):
    """Steps per second of the fastest of `repeats` runs on fresh environments, and the
    rewards' sum."""
    best, total = 0.0, None
    for _ in range(repeats):
        env = make()
        start = time.perf_counter()
        total = run(env, actions)
        best = max(best, len(actions) / (time.perf_counter() - start))
    return best, total


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("envs", nargs="*", default=["lightworld", "taxi", "mcar"])
    p.add_argument("--steps", type=int, default=200000, help="actions per run (200000)")
    p.add_argument("--repeats", type=int, default=5, help="runs per figure, best kept (5)")
    p.add_argument("--seed", type=int, default=1)
    args = p.parse_args(argv)
    print("%-11s %8s %14s %14s %7s %14s" % ("env", "steps", "python steps/s", "C++ steps/s",
                                          "ratio", "python us/step"))
    for name in args.envs:
        rng = random.Random(args.seed)
        n = rl.make_env(name).num_actions
        actions = [rng.randrange(n) for _ in range(args.steps)]
        make = lambda: rl.make_env(name, seed=args.seed)  # noqa: E731
        py_rate, py_total = best_rate(python_loop, make, actions, args.repeats)
        cpp_rate, cpp_total = best_rate(lambda env, acts: env.run(acts), make, actions,
                                        args.repeats)
        if py_total != cpp_total:
            print("%s: the loops disagree (python %r, C++ %r)" % (name, py_total, cpp_total))
            return 1
        print("%-11s %8d %14.0f %14.0f %6.1fx %14.2f" % (name, args.steps, py_rate, cpp_rate,
                                                        cpp_rate / py_rate, 1e6 / py_rate))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
