#!/usr/bin/env python3
"""TEXPLORE-VANIR on LightWorld from Python, with the suite's default agent settings for
LightWorld (`./rl run`, launch/lightworld_experiment.launch: --agent texplore --v 1 --n 3
--rollouts 100 --lambda 1), in episodes of --episode-steps steps: the first --explore-episodes with intrinsic rewards,
the rest in the paper's task phase (set_intrinsic_enabled(False)). LightWorld never terminates,
so each episode starts from env.reset() (room 0) and ends by the runner's cut-off rule: the
agent gets the last reward through next_action(), whose action is discarded. Prints one row per
episode and plots the reward per episode (and the mean intrinsic bonuses) to --out.

    source .build/devel/setup.bash
    /usr/bin/python3 rl_python/scripts/lightworld_vanir.py --steps 3000 --seed 1 --out vanir.png
"""
import argparse
import sys
import time

import rl_python as rl


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--steps", type=int, default=3000, help="steps in all (default 3000)")
    p.add_argument("--episode-steps", type=int, default=500, help="steps per episode (500)")
    p.add_argument("--seed", type=int, default=1,
                   help="seed of the environment and of the agent (as the launch file: 1)")
    p.add_argument("--explore-episodes", type=int, default=None,
                   help="episodes with intrinsic rewards, then the task phase: intrinsic rewards "
                   "off, greedy on the learned model (default: half the episodes)")
    p.add_argument("--rollouts", type=int, default=100, help="UCT rollouts per step (100)")
    p.add_argument("--out", default="lightworld_vanir.png", help="figure (PNG)")
    args = p.parse_args(argv)
    if args.steps < args.episode_steps or args.episode_steps < 1:
        p.error("--steps must be at least --episode-steps, which must be positive")

    env = rl.make_env("lightworld", seed=args.seed)
    agent = rl.make_agent("texplore", env, v=1, n=3, rollouts=args.rollouts, lambda_=1,
                          seed=args.seed)
    agent.seed_experiences(env.seed_experiences())
    print("env", env.options)
    print("agent", {k: agent.options[k] for k in ("agent", "v", "n", "explore", "nmodels",
                                                   "combo", "planner", "rollouts", "lambda",
                                                   "seed")})
    episodes = args.steps // args.episode_steps
    explore = episodes // 2 if args.explore_episodes is None else args.explore_episodes
    rows = []
    print("%7s %7s %6s %6s %6s %9s %9s %8s" % ("episode", "phase", "steps", "reward", "exits", "variance",
                                           "novelty", "steps/s"))
    for episode in range(episodes):
        if episode == explore:
            agent.set_intrinsic_enabled(False)  # the task phase (paper section 5.1)
        start = time.perf_counter()
        obs, _ = env.reset()
        action = agent.first_action(obs)
        reward_sum, exits, variance, novelty = 0.0, 0, 0.0, 0.0
        for step in range(args.episode_steps):
            b = agent.reward_breakdown()  # the bonuses behind `action`
            variance += b.variance
            novelty += b.novelty
            obs, reward, terminated, truncated, _ = env.step(action)
            reward_sum += reward
            exits += reward == 10.0
            action = agent.next_action(reward, obs)  # at the last step: the cut-off, discarded
        n = args.episode_steps
        rows.append((episode, "explore" if episode < explore else "task", n, reward_sum, exits, variance / n, novelty / n,
                     n / (time.perf_counter() - start)))
        print("%7d %7s %6d %6.0f %6d %9.4f %9.4f %8.1f" % rows[-1])
    total = sum(r[3] for r in rows)
    print("total reward %.0f over %d steps" % (total, len(rows) * args.episode_steps))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4))
    episodes = [r[0] for r in rows]
    ax.bar(episodes, [r[3] for r in rows],
           color=["tab:blue" if r[1] == "explore" else "tab:orange" for r in rows],
           label="external reward (blue: explore, orange: task)")
    ax.set_xlabel("episode (%d steps from a reset)" % args.episode_steps)
    ax.set_ylabel("external reward per episode")
    bonus = ax.twinx()
    bonus.plot(episodes, [r[5] for r in rows], "o-", color="tab:red",
               label="mean variance bonus")
    bonus.plot(episodes, [r[6] for r in rows], "s-", color="tab:green",
               label="mean novelty bonus")
    bonus.set_ylabel("mean intrinsic bonus per step")
    lines = ax.get_legend_handles_labels()
    more = bonus.get_legend_handles_labels()
    ax.legend(lines[0] + more[0], lines[1] + more[1], loc="upper center",
              bbox_to_anchor=(0.5, -0.17), ncol=3, fontsize=8)
    ax.set_title("TEXPLORE-VANIR (v=1, n=3, %d rollouts, lambda 1) on LightWorld, seed %d"
                 % (args.rollouts, args.seed), fontsize=9)
    fig.tight_layout()
    fig.savefig(args.out, dpi=100)
    print("figure:", args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
