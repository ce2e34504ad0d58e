#!/usr/bin/env python3
"""The TEXPLORE-VANIR paper's Nao experiments (section 5.2, Figs. 10-14) on the simulated Nao.

Usage: reproduce_nao.py [--quick] [--out DIR] [--trials N] [--jobs K] [--seed S]
                        [--rollouts R] [--explore-steps E] [--task-steps T] [--lambda L]
                        [--nstates G|none] [--task-rewards given|learned]

For each exploration strategy (TEXPLORE-VANIR with v = 3, n = 10; random exploration) and each
task (pink, button, mic), the standalone `experiment` runner runs --trials trials on the
in-process `naoarm` environment: E exploration steps with the task's reward hidden from the agent
(paper: 400), then T task steps with the reward (paper: 200). Trials of one strategy share their
seeds, so their exploration phases are the same run seen through three reward functions: the
button runs give Fig. 10 (fraction of trials that pressed the foot button by each exploration
step), the pink runs Fig. 11 (highest pink pixel count seen by each step); the task phases give
Figs. 12-14 (average task reward per step). The paper's first question, how much of the state
space the agent explored, is also measured directly: fig_cells_explore.png counts the distinct
shoulder targets (cells of the 8-degree grid the actions move on) commanded by each step.
Writes DIR/fig10_button_explore.png ... fig14, DIR/results.md (a table; per column the p-value
of a two-sided Welch t-test of random's per-trial values against TEXPLORE-VANIR's, with
rl_experiment/scripts/stats.py) and the runs under DIR/runs/.
--quick: 6 trials, 400 exploration and 100 task steps, 100 rollouts (a few minutes on 2 cores);
the full run is the paper's 13 trials, 400 and 200 steps.

Both strategies see the arm's state binned per feature (the agents' --nstates, default
NAO_STATES: 8-degree joint cells, 20 mm hand cells, ~1000 pink pixels, the bumper, 200 units of
microphone energy), and UCT mixes Monte-Carlo returns with lambda 1 (--lambda; as the LightWorld
reproduction). On the raw continuous, noisy states every relative change is a class of its own,
so the trees disagree everywhere (the variance bonus is flat), UCT meets each imagined state once,
and TEXPLORE-VANIR explores no more than random actions do; --nstates none --lambda 0.1 runs that
setting (the agents' defaults).

In the task phase every strategy acts greedily on the model it learned (the runner switches
exploration off, random action choice included), as in the paper, after being "provided with a
reward function" (--task-rewards given: it is given the task's reward of its exploration steps;
learned: it learns the reward from the task steps only).
"""
import argparse
import csv
import glob
import os
import shutil
import subprocess
import sys

STRATEGIES = {
    "texplore-vanir": ["--agent", "texplore", "--v", "3", "--n", "10"],
    "random": ["--agent", "texplore", "--explore", "random"],
}
TASKS = ["pink", "button", "mic"]
# The strategy the table's p-values compare against.
REFERENCE = "texplore-vanir"
# Bins per feature over the naoarm ranges (nao_arm_task.cpp): RShoulderPitch 242 deg / 30,
# RShoulderRoll 97 deg / 12 (both about the 8-degree action step), hand x, y, z 500 mm / 25,
# pink 153600 / 154, bumper 1 / 1 (0 or 1), microphone 4000 / 20.
NAO_STATES = "30,12,25,25,25,154,1,20"
# The shoulder joints' limits (urdf/nao_upper_body.urdf) and start posture
# (NaoArmSimConfig), in degrees: the actions move the targets 8 degrees, clamped to the limits.
PITCH_LIMITS = (-119.5, 119.5)
ROLL_LIMITS = (-76.0, 18.0)
START = (-72.0, -12.0)


def find_experiment():
    if os.environ.get("RL_EXPERIMENT"):
        return os.environ["RL_EXPERIMENT"]
    try:
        out = subprocess.run(["catkin_find", "--first-only", "rl_experiment", "experiment"],
                             capture_output=True, text=True, check=False).stdout.split()
        if out:
            return out[0]
    except OSError:
        pass
    found = shutil.which("experiment")
    if found:
        return found
    sys.exit("reproduce nao: cannot find the experiment runner; build first (./rl build) or "
             "set RL_EXPERIMENT")


def import_stats():
    """rl_experiment's stats.py (the Welch t-test): in the source tree next to this package,
    else wherever catkin_find finds it (the devel or install space of rl_experiment)."""
    here = os.path.dirname(os.path.abspath(__file__))
    folder = os.path.join(here, "..", "..", "rl_experiment", "scripts")
    looked = [os.path.abspath(folder)]
    for rel in ("scripts/stats.py", "stats.py"):
        if os.path.exists(os.path.join(folder, "stats.py")):
            break
        try:
            found = subprocess.run(["catkin_find", "--first-only", "rl_experiment", rel],
                                   capture_output=True, text=True, check=False).stdout.split()
        except OSError:
            found = []
        folder = os.path.dirname(found[0]) if found else folder
        looked.append("catkin_find rl_experiment " + rel)
    if not os.path.exists(os.path.join(folder, "stats.py")):
        sys.exit("reproduce nao: cannot find rl_experiment's stats.py (looked in "
                 + ", ".join(looked) + ")")
    sys.path.insert(0, os.path.abspath(folder))
    import stats
    return stats


def run_command(args, exe, name, agent, task):
    """The runner's options of one strategy on one task (without the trials, jobs and folder)."""
    cmd = [exe, *agent, "--env", "naoarm", "--task", task,
           "--explore-steps", str(args.explore_steps), "--task-steps", str(args.task_steps),
           "--rollouts", str(args.rollouts), "--seed", str(args.seed), "--eval-every", "0",
           "--label", name, "--lambda", repr(args.lam), "--task-rewards", args.task_rewards]
    if args.nstates != "none":
        cmd += ["--nstates", args.nstates]
    return cmd


def submit_to_slurm(args, exe, raw_argv):
    """One job array (a task per strategy, task and block of trials), then a job after it that
    reruns this script with --collect: merge each run folder, then the figures and the table."""
    import slurm_sweep
    tasks = []
    for name, agent in STRATEGIES.items():
        for task in TASKS:
            out = os.path.join(os.path.abspath(args.out), "runs", f"{name}-{task}")
            if os.path.exists(os.path.join(out, "trials.csv")):
                print(f"[reproduce nao] {name} / {task}: done before, kept ({out})", flush=True)
                continue
            tasks += slurm_sweep.plan_tasks(out, run_command(args, os.path.abspath(exe), name,
                                                             agent, task),
                                            0, args.trials,
                                            args.trials_per_task or args.cpus_per_task,
                                            args.cpus_per_task)
    sweep = os.path.join(os.path.abspath(args.out), "slurm")
    array = slurm_sweep.submit_array(sweep, "rl-nao", tasks, args) if tasks else None
    command = slurm_sweep.collect_command(exe, __file__, raw_argv, os.path.abspath(args.out))
    report = slurm_sweep.submit_after(sweep, "rl-nao-report", command, [array], args)
    print(f"[reproduce nao] submitted: array job {array or 'none'} ({len(tasks)} tasks), "
          f"then the report job {report} (merge, figures, results.md)", flush=True)
    print(slurm_sweep.follow_hint(sweep, [array, report]), flush=True)


def merge_slurm_parts(args):
    import slurm_sweep
    for name in STRATEGIES:
        for task in TASKS:
            out = os.path.join(args.out, "runs", f"{name}-{task}")
            if os.path.isdir(slurm_sweep.parts_dir(out)):
                n = slurm_sweep.merge(os.path.abspath(out))
                print(f"[reproduce nao] {name} / {task}: merged {n} trials of its Slurm tasks",
                      flush=True)


def run_all(args, exe):
    for name, agent in STRATEGIES.items():
        for task in TASKS:
            out = os.path.join(args.out, "runs", f"{name}-{task}")
            if os.path.exists(os.path.join(out, "trials.csv")):
                print(f"[reproduce nao] {name} / {task}: done before, kept ({out})", flush=True)
                continue
            cmd = run_command(args, exe, name, agent, task) + [
                "--trials", str(args.trials), "--jobs", str(args.jobs), "--out", out, "--force",
                "--progress", "off"]
            print(f"[reproduce nao] {name} / {task}: {' '.join(cmd)}", flush=True)
            subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def read_steps(args, name, task, with_actions=False):
    """{trial: [(phase, reward[, action]), ...]} in step order."""
    trials = {}
    for path in sorted(glob.glob(os.path.join(args.out, "runs", f"{name}-{task}", "steps-*.csv"))):
        with open(path) as f:
            for row in csv.DictReader(f):
                step = (row["phase"], float(row["reward"]))
                if with_actions:
                    step += (int(row["action"]),)
                trials.setdefault(int(row["trial"]), []).append(step)
    if not trials:
        sys.exit(f"reproduce nao: no step logs for {name} / {task}")
    return [trials[t] for t in sorted(trials)]


def mean(xs):
    return sum(xs) / len(xs) if xs else float("nan")


def cells_curve_step(pitch, roll, action):
    """The shoulder targets after `action`, as applyNaoArmAction moves and clamps them."""
    if action in (0, 1):
        pitch = min(max(pitch + (8.0 if action == 0 else -8.0), PITCH_LIMITS[0]), PITCH_LIMITS[1])
    elif action in (2, 3):
        roll = min(max(roll + (8.0 if action == 2 else -8.0), ROLL_LIMITS[0]), ROLL_LIMITS[1])
    return pitch, roll


def cell(pitch, roll):
    """The 8-degree cell of a shoulder target, counted in steps from the start posture (a target
    clamped at a limit and one step back from it fall in neighbouring cells)."""
    return round((pitch - START[0]) / 8.0), round((roll - START[1]) / 8.0)


def cells_curve(actions):
    """Distinct shoulder cells commanded by each step."""
    pitch, roll = START
    seen = {cell(pitch, roll)}
    curve = []
    for a in actions:
        pitch, roll = cells_curve_step(pitch, roll, a)
        seen.add(cell(pitch, roll))
        curve.append(len(seen))
    return curve


def analyse(args):
    res = {}
    for name in STRATEGIES:
        r = {}
        button = read_steps(args, name, "button")
        pink = read_steps(args, name, "pink")
        # Fig. 10: fraction of trials that have pressed the button by each exploration step.
        pressed_at = []
        for steps in button:
            explore = [rw for ph, rw in steps if ph == "explore"]
            first = next((i for i, rw in enumerate(explore) if rw > 0), None)
            pressed_at.append(first)
        n_explore = min(len([1 for ph, _ in s if ph == "explore"]) for s in button)
        r["fig10"] = [mean([1.0 if (p is not None and p <= i) else 0.0 for p in pressed_at])
                      for i in range(n_explore)]
        r["pressed-trials"] = [0.0 if p is None else 1.0 for p in pressed_at]
        # Fig. 11: highest pink count seen by each exploration step, averaged over trials.
        curves = []
        for steps in pink:
            best, curve = 0.0, []
            for ph, rw in steps:
                if ph != "explore":
                    break
                best = max(best, rw)
                curve.append(best)
            curves.append(curve)
        n = min(len(c) for c in curves)
        r["fig11"] = [mean([c[i] for c in curves]) for i in range(n)]
        r["final-max-pink-trials"] = [c[n - 1] for c in curves] if n else []
        # The explored part of the arm's space: distinct shoulder cells commanded by each step.
        cells = [cells_curve([a for ph, _, a in steps if ph == "explore"])
                 for steps in read_steps(args, name, "button", with_actions=True)]
        n = min(len(c) for c in cells)
        r["cells"] = [mean([c[i] for c in cells]) for i in range(n)]
        r["cells-final"] = [c[-1] for c in cells if c]
        # Figs. 12-14: task reward per task step, averaged over trials.
        for task in TASKS:
            runs = read_steps(args, name, task)
            task_rewards = [[rw for ph, rw in s if ph == "task"] for s in runs]
            n = min(len(t) for t in task_rewards)
            r[f"task-{task}"] = [mean([t[i] for t in task_rewards]) for i in range(n)]
            r[f"task-{task}-trials"] = [mean(t) for t in task_rewards]
            r[f"task-{task}-mean"] = mean(r[f"task-{task}-trials"])
            r[f"task-{task}-trials-hit"] = sum(1 for t in task_rewards if max(t, default=0) > 800) \
                if task == "mic" else None
            if task == "mic":
                r["mic-hit-trials"] = [1.0 if max(t, default=0) > 800 else 0.0
                                       for t in task_rewards]
        r["pressed"] = sum(1 for p in pressed_at if p is not None)
        r["trials"] = len(pressed_at)
        r["max-pink"] = max(max(c) if c else 0 for c in curves)
        r["final-max-pink"] = r["fig11"][-1] if r["fig11"] else 0
        res[name] = r
    return res


def plot(args, res):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figs = [
        ("fig10_button_explore", "fig10", "exploration step", "fraction of trials that pressed the button",
         "Fig. 10: foot button pressed during exploration"),
        ("fig11_max_pink_explore", "fig11", "exploration step", "max pink pixels seen (mean)",
         "Fig. 11: max pink pixels during exploration"),
        ("fig_cells_explore", "cells", "exploration step", "distinct shoulder cells commanded (mean)",
         "Explored arm configurations"),
        ("fig12_pink_task", "task-pink", "task step", "reward (pink pixels, mean)",
         "Fig. 12: pink task after exploration"),
        ("fig13_button_task", "task-button", "task step", "reward (mean)",
         "Fig. 13: button task after exploration"),
        ("fig14_mic_task", "task-mic", "task step", "reward (microphone energy, mean)",
         "Fig. 14: microphone task after exploration"),
    ]
    written = []
    for fname, key, xlabel, ylabel, title in figs:
        fig, ax = plt.subplots(figsize=(6, 4))
        for name, r in res.items():
            ax.plot(range(1, len(r[key]) + 1), r[key], label=name)
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.set_title(title + f" ({args.trials} trials)")
        ax.legend()
        fig.tight_layout()
        path = os.path.join(args.out, fname + ".png")
        fig.savefig(path, dpi=100)
        plt.close(fig)
        written.append(path)
    return written


def reachable_cells():
    """The number of shoulder cells within the joint limits."""
    lo, hi = cell(PITCH_LIMITS[0], ROLL_LIMITS[0]), cell(PITCH_LIMITS[1], ROLL_LIMITS[1])
    return (hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1)


# The table's measured columns: their per-trial values (the key in analyse()'s results).
P_COLUMNS = ["cells-final", "pressed-trials", "final-max-pink-trials", "task-pink-trials",
             "task-button-trials", "task-mic-trials", "mic-hit-trials"]


def p_cells(stats, res, name):
    """The p column of each measured column for strategy `name`: Welch against REFERENCE."""
    if name == REFERENCE or REFERENCE not in res:
        return ["ref" if name == REFERENCE else "n/a"] * len(P_COLUMNS)
    return [stats.format_p(stats.welch_t_test(res[name][key], res[REFERENCE][key])[2])
            for key in P_COLUMNS]


def table(args, res, stats):
    lines = [
        f"# Nao arm experiments (TEXPLORE-VANIR paper section 5.2), simulated Nao",
        "",
        f"{args.trials} trials per strategy and task, {args.explore_steps} exploration steps then "
        f"{args.task_steps} task steps, {args.rollouts} UCT rollouts per step, UCT lambda "
        f"{args.lam}, states binned by --nstates {args.nstates}, task rewards {args.task_rewards} "
        f"at the switch, seed {args.seed}. Shoulder cells: distinct 8-degree shoulder targets "
        f"commanded while exploring, of {reachable_cells()} (mean and range over trials). "
        f"Each p follows its column.",
        "",
        "| strategy | shoulder cells visited while exploring | p | trials that pressed the button while exploring | p | max pink seen while exploring (mean of trials / best) | p "
        "| pink task: mean reward per step | p | button task: mean reward per step | p | mic task: mean reward per step | p | mic task: trials with a cymbal hit (> 800) | p |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for name, r in res.items():
        c = r["cells-final"]
        p = p_cells(stats, res, name)
        lines.append(
            f"| {name} | {mean(c):.1f} ({min(c)}-{max(c)}) | {p[0]} | {r['pressed']}/{r['trials']} "
            f"| {p[1]} | {r['final-max-pink']:.0f} / {r['max-pink']:.0f} | {p[2]} "
            f"| {r['task-pink-mean']:.1f} | {p[3]} | {r['task-button-mean']:.1f} | {p[4]} "
            f"| {r['task-mic-mean']:.1f} | {p[5]} | {r['task-mic-trials-hit']}/{r['trials']} "
            f"| {p[6]} |")
    lines += ["", stats.p_value_note(REFERENCE) + " Counts are tested on each trial's 0/1 "
              "outcome, max pink on each trial's highest count.", "",
              "Paper (13 trials, real Nao): button pressed in 7/13 (TEXPLORE-VANIR) vs 0/13 "
              "(random); highest pink count 5434, VANIR seeing nearly twice as much pink as random; "
              "VANIR earns more task reward on pink and button; the cymbal was hit in 1 of 5 "
              "VANIR mic trials and never after random exploration.", ""]
    text = "\n".join(lines)
    with open(os.path.join(args.out, "results.md"), "w") as f:
        f.write(text)
    return text


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--quick", action="store_true", help="6 trials, 400 + 100 steps, 100 rollouts")
    p.add_argument("--out", default=None, help="output folder (default: results/nao[-quick])")
    p.add_argument("--trials", type=int, default=None)
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--rollouts", type=int, default=None)
    p.add_argument("--explore-steps", type=int, default=None)
    p.add_argument("--task-steps", type=int, default=None)
    p.add_argument("--lambda", dest="lam", type=float, default=1.0,
                   help="UCT(lambda) of both strategies (default 1; the agents' own is 0.1)")
    p.add_argument("--task-rewards", default="given", choices=["given", "learned"],
                   help="at the task switch, the agent is given the task's reward of its "
                        "exploration steps (given, default) or learns it from the task steps only")
    p.add_argument("--nstates", default=NAO_STATES,
                   help=f"the agents' bins per feature (default {NAO_STATES}); 'none' learns "
                        "and plans on the continuous states")
    stats = import_stats()  # also puts rl_experiment's scripts (slurm_sweep) on the path
    import slurm_sweep
    slurm_sweep.add_slurm_arguments(p)
    args = p.parse_args()
    quick = dict(trials=6, explore_steps=400, task_steps=100, rollouts=100)
    full = dict(trials=13, explore_steps=400, task_steps=200, rollouts=100)
    for k, v in (quick if args.quick else full).items():
        if getattr(args, k) is None:
            setattr(args, k, v)
    if args.out is None:
        args.out = os.path.join(os.getcwd(), "results", "nao-quick" if args.quick else "nao")
    os.makedirs(args.out, exist_ok=True)
    exe = find_experiment()
    if args.slurm and not args.collect:
        submit_to_slurm(args, exe, sys.argv[1:])
        return
    if args.collect:
        merge_slurm_parts(args)
    run_all(args, exe)
    res = analyse(args)
    figs = plot(args, res)
    print(table(args, res, stats))
    print("[reproduce nao] figures: " + ", ".join(figs))
    print(f"[reproduce nao] table: {os.path.join(args.out, 'results.md')}")


if __name__ == "__main__":
    main()
