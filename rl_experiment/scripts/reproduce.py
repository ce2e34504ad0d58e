#!/usr/bin/env python3
"""The TEXPLORE-VANIR paper's LightWorld experiments (section 5.1, Figs. 4-8), in one command.

Usage: reproduce.py lightworld [--quick] [--out DIR] [--trials N] [--jobs K] [--seed S]
                               [--rollouts R] [--experiment NAME ...] [--agent LABEL ...]
                               [--lambda L]
                               [--task-rewards given|learned] [--task-planner vi|same] [--list]

Experiments (each agent runs --trials trials through the standalone `experiment` runner):
  explore-task  1000 exploration steps without external reward, then 3000 task steps acting
                greedily on the learned model (Figs. 4, 5, 6: model accuracy, task reward,
                where PRESS was tried)
  combined      3000 steps with intrinsic and external rewards together (Fig. 7)
  ablation      TEXPLORE-VANIR with v/n in {1/3, 1/0, 0/3, 0/0}, 5000 steps combined (Fig. 8)
Agents: TEXPLORE-VANIR (v=1, n=3), TEXPLORE greedy (v=0, n=0), the paper's comparison explorers
on TEXPLORE's forest (random, competence, prederror, R-MAX-style, Boltzmann), the tabular random
agent, and every other agent the registry offers when this runs (`experiment --list-agents`).
Every UCT agent plans with --lambda (1 unless given): with the agents' default 0.1, the original's,
they fixate on self-loops in LightWorld and TEXPLORE-VANIR explores less than random actions (the
README's "Known limits"); `--lambda 0.1` runs the original's setting. At the switch to the task
the model-based agents are given the task's reward of their exploration steps (the runner's
--task-rewards given, the paper's "provided with a reward function"); --task-rewards learned
makes them learn it from the task steps only. Their task phase is planned by value iteration on
the learned model over LightWorld's position, key, door and room (--task-planner vi, the
default: UCT with 100 rollouts does not plan key, lock and door); --task-planner same plans it
as they explored (UCT for TEXPLORE, the paper's setting; see the README's task-phase section).
--quick uses 4 trials and shorter runs (8 minutes on 2 cores). The full run (30 trials, the
paper's lengths) took 7.8 h of trial CPU on 2 cores (2026-12-03, docs/results/lightworld/).
Writes run folders, figures (PNG, PDF) and figures/per-trial.csv (every trial's summary and its model distance at
step 1000, trials_table.py: small enough to commit) per experiment, and DIR/results.md with
the final numbers, 95% intervals and
p-values (two-sided Welch t-tests of the per-trial values against TEXPLORE-VANIR: texplore-vanir,
in the ablation texplore-v1-n3).
A rerun resumes: finished trials are kept (use a new --out for a fresh run).
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys
import time

import slurm_sweep

HERE = os.path.dirname(os.path.abspath(__file__))
PAPER_OPTIMAL_TASK_REWARD = 1800.6  # the paper's optimal policy over the 3000 task steps
# LightWorld's ns, ew, have_key, door_open and room_id: what --task-planner vi tells apart (the
# light sensors follow from them within a room; the learned model's guesses at them never close).
LIGHTWORLD_TASK_KEY = "0,1,2,3,4"
SKIPPED_AGENTS = {
    "savedpolicy": "needs a policy file",
}
# (label, options) of the paper's comparison methods on TEXPLORE's forest model: random
# actions, R-IAC-style competence progress, prediction error, R-MAX-style rewards (Figs. 4-6)
# and Boltzmann selection with the paper's temperature (Fig. 7).
COMPARISON_EXPLORERS = [
    ("texplore-random", ["--explore", "random"]),
    ("texplore-competence", ["--explore", "competence"]),
    ("texplore-prederror", ["--explore", "prederror"]),
    ("texplore-rmax-style", ["--explore", "unknown", "--m", "5"]),
    ("texplore-boltzmann", ["--explore", "boltzmann", "--tau", "0.2"]),
]


def find_experiment():
    """The runner: $RL_EXPERIMENT, on PATH via rosrun's layout, or next to this script."""
    if os.environ.get("RL_EXPERIMENT"):
        return os.environ["RL_EXPERIMENT"]
    try:
        out = subprocess.run(["catkin_find", "--first-only", "rl_experiment", "experiment"],
                             capture_output=True, text=True, check=False).stdout.split()
        if out:
            return out[0]
    except OSError:
        pass
    for cand in (os.path.join(HERE, "experiment"),):
        if os.path.exists(cand):
            return cand
    found = shutil.which("experiment")
    if found:
        return found
    sys.exit("reproduce: cannot find the experiment runner; build first (./rl build) or set "
             "RL_EXPERIMENT")


def registry_agents(exe):
    out = subprocess.run([exe, "--list-agents"], capture_output=True, text=True, check=True)
    return [line.split("\t")[0] for line in out.stdout.splitlines() if line.strip()]


def accepts(exe, args):
    return subprocess.run([exe] + args + ["--check"], capture_output=True).returncode == 0


def agent_variants(exe, rollouts, log, planner_opts=()):
    """(label, options) for every agent to compare."""
    variants = []
    for name in registry_agents(exe):
        if name in SKIPPED_AGENTS:
            log("  skipping agent %s: %s" % (name, SKIPPED_AGENTS[name]))
            continue
        if name == "texplore":
            variants.append(("texplore-vanir", ["--agent", "texplore", "--v", "1", "--n", "3"]))
            variants.append(("texplore-greedy", ["--agent", "texplore"]))
            # The paper's comparison explorers on the same forest model (section 5.1).
            for label, explore in COMPARISON_EXPLORERS:
                variants.append((label, ["--agent", "texplore"] + explore))
        elif name == "modelbased":
            # The paper's random agent with a tabular model.
            variants.append(("tabular-random", ["--agent", "modelbased", "--model", "tabular",
                                                "--explore", "random", "--planner", "vi"]))
        else:
            variants.append((name, ["--agent", name]))
    out = []
    for label, opts in variants:
        with_rollouts = opts + ["--rollouts", str(rollouts)] + list(planner_opts)
        if accepts(exe, with_rollouts + ["--env", "lightworld"]):
            out.append((label, with_rollouts))
        elif accepts(exe, opts + ["--env", "lightworld"]):
            out.append((label, opts))
        else:
            log("  skipping agent %s: its options are not accepted" % label)
    return out


def with_task_planner(exe, opts, task_planner):
    """An agent's options for the explore-task experiment: with --task-planner vi, those of the
    value-iteration task planner where the agent takes them (model-based agents)."""
    if task_planner != "vi":
        return opts
    task_opts = ["--taskplanner", "vi", "--taskkey", LIGHTWORLD_TASK_KEY]
    if accepts(exe, opts + task_opts + ["--env", "lightworld"]):
        return opts + task_opts
    return opts


def ablation_variants(rollouts, planner_opts=()):
    out = []
    for v, n in ((1, 3), (1, 0), (0, 3), (0, 0)):
        opts = ["--agent", "texplore", "--rollouts", str(rollouts)] + list(planner_opts)
        if v or n:
            opts += ["--v", str(v), "--n", str(n)]
        out.append(("texplore-v%d-n%d" % (v, n), opts))
    return out


def finished_trials(folder):
    path = os.path.join(folder, "trials.csv")
    if not os.path.exists(path):
        return 0
    with open(path) as f:
        return max(0, sum(1 for line in f if line.strip()) - 1)


def trial_seconds(folder):
    """Seconds of the finished trials in a run folder (trials.csv), each as its trial took them."""
    path = os.path.join(folder, "trials.csv")
    if not os.path.exists(path):
        return 0.0
    with open(path) as f:
        return sum(float(r["seconds"]) for r in csv.DictReader(f) if r.get("seconds"))


def submit_to_slurm(args, raw_argv, exe, out, experiments, wanted, common, trials, log):
    """One Slurm job array per experiment (a task per agent and block of trials), then one job
    after all of them that reruns this script with --collect: it merges each agent's tasks into
    its run folder and draws the figures and tables exactly as a local run does."""
    out = os.path.abspath(out)
    arrays = []
    for name, what, variants, opts, _ in experiments:
        if name not in wanted:
            continue
        tasks = []
        for label, agent_opts in variants:
            folder = os.path.join(out, name, label)
            if finished_trials(folder) >= trials:
                log("  %s/%-20s done already" % (name, label))
                continue
            if name == "explore-task":
                agent_opts = with_task_planner(exe, agent_opts, args.task_planner)
            tasks += slurm_sweep.plan_tasks(folder, [os.path.abspath(exe)] + agent_opts + common
                                            + opts + ["--label", label], 0, trials,
                                            args.trials_per_task or args.cpus_per_task,
                                            args.cpus_per_task)
        if tasks:
            arrays.append(slurm_sweep.submit_array(os.path.join(out, "slurm", name),
                                                   "rl-lightworld-" + name, tasks, args, log))
    command = slurm_sweep.collect_command(exe, __file__, raw_argv, out)
    report = slurm_sweep.submit_after(os.path.join(out, "slurm"), "rl-lightworld-report",
                                      command, arrays, args)
    log("submitted: %d job arrays (%s), then the report job %s (merges, figures, results.md)"
        % (len([a for a in arrays if a]), ", ".join(a for a in arrays if a) or "none", report))
    log(slurm_sweep.follow_hint(os.path.join(out, "slurm", "<experiment>"), arrays + [report]))
    return 0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__)
    ap.add_argument("domain", choices=["lightworld"])
    ap.add_argument("--quick", action="store_true", help="fewer trials and steps (~15 min)")
    ap.add_argument("--out", default=None, help="results folder (default results/lightworld[-quick])")
    ap.add_argument("--trials", type=int, default=None, help="trials per agent (30; quick 4)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="parallel trials")
    ap.add_argument("--seed", type=int, default=1, help="run seed (trial seeds derive from it)")
    ap.add_argument("--rollouts", type=int, default=None,
                    help="UCT rollouts per step for planning agents (100)")
    ap.add_argument("--experiment", action="append",
                    choices=["explore-task", "combined", "ablation"],
                    help="run only these experiments (default: all)")
    ap.add_argument("--lambda", dest="lam", type=float, default=1.0,
                    help="UCT(lambda) of every UCT agent (default 1, Monte-Carlo backups; the "
                         "agents' own default, the original's 0.1, makes them fixate on "
                         "self-loops in LightWorld: see the README's known limits)")
    ap.add_argument("--task-rewards", default="given", choices=["given", "learned"],
                    help="explore-task: model-based agents are given the task's reward of their "
                         "exploration steps at the switch (given, default) or learn it from the "
                         "task steps only (learned)")
    ap.add_argument("--task-planner", default="vi", choices=["vi", "same"],
                    help="explore-task: how the model-based agents plan the task phase: by value "
                         "iteration on the learned model over LightWorld's position, key, door "
                         "and room features (vi, default: --taskplanner vi --taskkey %s) or as "
                         "they explored (same: UCT for TEXPLORE, the paper's setting)"
                         % LIGHTWORLD_TASK_KEY)
    ap.add_argument("--agent", action="append", metavar="LABEL",
                    help="run only these agents (labels as --list prints them; e.g. to add "
                         "trials of some agents to a finished run's --out)")
    ap.add_argument("--list", action="store_true",
                    help="print each experiment's agents and their options, then exit")
    slurm_sweep.add_slurm_arguments(ap)
    raw_argv = sys.argv[1:] if argv is None else list(argv)
    args = ap.parse_args(argv)

    if args.quick:
        # The paper's 1000 exploration steps, shorter task and combined runs, fewer trials.
        trials, explore, task, combined, ablation = 4, 1000, 1000, 1500, 2000
        samples, rollouts = 1000, 100
    else:
        trials, explore, task, combined, ablation = 30, 1000, 3000, 3000, 5000
        samples, rollouts = 5000, 100
    trials = args.trials or trials
    rollouts = args.rollouts or rollouts
    out = args.out or os.path.join("results", "lightworld" + ("-quick" if args.quick else ""))
    exe = find_experiment()
    planner_opts = ["--lambda", repr(args.lam)]
    if args.list:
        for label, opts in agent_variants(exe, rollouts, lambda text: print(text), planner_opts):
            task = with_task_planner(exe, opts, args.task_planner)
            if task == opts:
                print("explore-task, combined: %-20s %s" % (label, " ".join(opts)))
            else:
                print("explore-task: %-20s %s" % (label, " ".join(task)))
                print("combined: %-20s %s" % (label, " ".join(opts)))
        for label, opts in ablation_variants(rollouts, planner_opts):
            print("ablation: %-20s %s" % (label, " ".join(opts)))
        return 0
    if args.agent:
        # Checked before anything is written: a typo must not start a run folder.
        known = {label for label, _ in agent_variants(exe, rollouts, lambda text: None,
                                                      planner_opts)}
        known |= {label for label, _ in ablation_variants(rollouts, planner_opts)}
        unknown = [a for a in args.agent if a not in known]
        if unknown:
            print("reproduce.py: unknown --agent %s; the agents: %s"
                  % (", ".join(unknown), ", ".join(sorted(known))), file=sys.stderr)
            return 2
    os.makedirs(out, exist_ok=True)
    start = time.time()
    logf = open(os.path.join(out, "reproduce.log"), "a")

    def log(text):
        print(text, flush=True)
        logf.write(text + "\n")
        logf.flush()

    log("reproduce lightworld%s: %d trials per agent, %d rollouts per step, %d jobs, seed %d, "
        "into %s" % (" --quick" if args.quick else "", trials, rollouts, args.jobs, args.seed,
                     out))
    agents = agent_variants(exe, rollouts, log, planner_opts)
    log("agents: " + ", ".join(label for label, _ in agents))
    # --trials and --jobs come last: a Slurm task replaces them with its own block's.
    common = ["--env", "lightworld", "--seed", str(args.seed), "--eval-samples", str(samples)]
    local = ["--trials", str(trials), "--jobs", str(args.jobs), "--progress", "off"]
    experiments = [
        ("explore-task", "Figs. 4-6: %d exploration steps, then %d task steps" % (explore, task),
         agents, ["--explore-steps", str(explore), "--task-steps", str(task),
                  "--task-rewards", args.task_rewards], "texplore-vanir"),
        ("combined", "Fig. 7: %d steps, intrinsic and external rewards combined" % combined,
         agents, ["--steps", str(combined)], "texplore-vanir"),
        ("ablation", "Fig. 8: TEXPLORE-VANIR v/n ablation, %d steps combined" % ablation,
         ablation_variants(rollouts, planner_opts), ["--steps", str(ablation)], "texplore-v1-n3"),
    ]
    wanted = set(args.experiment or [e[0] for e in experiments])
    if args.agent:
        experiments = [(n, w, [v for v in variants if v[0] in args.agent], o, r)
                       for n, w, variants, o, r in experiments]
    total_trial_seconds = 0.0  # every finished trial's own time, this run and resumed ones
    tables = []
    failures = 0
    # Each experiment's table gives p-values against TEXPLORE-VANIR (`reference`); if its runs
    # failed, plot_results.py falls back to its default (texplore-vanir, else the first label).
    if args.slurm and not args.collect:
        return submit_to_slurm(args, raw_argv, exe, out, experiments, wanted, common, trials,
                               log)
    for name, what, variants, opts, reference in experiments:
        if name not in wanted:
            continue
        log("== %s (%s)" % (name, what))
        folders = []
        for label, agent_opts in variants:
            folder = os.path.join(out, name, label)
            if name == "explore-task":
                agent_opts = with_task_planner(exe, agent_opts, args.task_planner)
            cmd = ([exe] + agent_opts + common + opts + ["--label", label] + local
                   + ["--out", folder])
            if args.collect and os.path.isdir(slurm_sweep.parts_dir(folder)):
                log("  %-20s merged %d trials of its Slurm tasks"
                    % (label, slurm_sweep.merge(folder, " ".join(cmd))))
            if finished_trials(folder) >= trials:
                log("  %-20s done already" % label)
                folders.append(folder)
                continue
            if os.path.exists(os.path.join(folder, "run.csv")):
                cmd.append("--resume")
            t0 = time.time()
            res = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            with open(os.path.join(out, name, label + ".log"), "w") as f:
                f.write(" ".join(cmd) + "\n" + res.stdout)
            if res.returncode != 0:
                failures += 1
                log("  %-20s FAILED (exit %d), see %s.log" % (label, res.returncode,
                                                             os.path.join(name, label)))
            else:
                log("  %-20s %d trials in %.0f s" % (label, trials, time.time() - t0))
            if finished_trials(folder) > 0:
                folders.append(folder)
        if not folders:
            continue
        figs = os.path.join(out, name, "figures")
        ref_opts = (["--reference", reference]
                    if os.path.join(out, name, reference) in folders else [])
        res = subprocess.run([sys.executable, os.path.join(HERE, "plot_results.py"), "--out", figs,
                              "--title", "LightWorld %s" % name] + ref_opts + folders,
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if res.returncode != 0:
            failures += 1
            log("  figures FAILED:\n" + res.stdout)
            continue
        # Every trial's numbers in one small file beside the figures: the run folders' steps
        # files are too large to keep, and this is what plot_trials.py draws from.
        res = subprocess.run([sys.executable, os.path.join(HERE, "trials_table.py"), "--out",
                              os.path.join(figs, "per-trial.csv"), "--at-step", str(explore)]
                             + folders, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             text=True)
        if res.returncode != 0:
            failures += 1
            log("  per-trial table FAILED:\n" + res.stdout)
        with open(os.path.join(figs, "results.md")) as f:
            table = f.read().split("\n", 1)[1]
        tables.append("## %s\n\n%s\n%s" % (name, what, table))
        total_trial_seconds += sum(trial_seconds(f) for f in folders)
        log("  figures in %s" % figs)
    elapsed = time.time() - start
    md = ["# LightWorld reproduction%s" % (" (quick)" if args.quick else ""), "",
          "%d trials per agent, %d UCT rollouts per step, UCT lambda %s, task rewards %s at the "
          "switch, task planner %s, seed %d; this invocation ran %.1f min on %d jobs; the "
          "trials took %.1f h between them (summed over trials, including those of earlier, "
          "resumed invocations)." %
          (trials, rollouts, repr(args.lam), args.task_rewards, args.task_planner, args.seed,
           elapsed / 60, args.jobs, total_trial_seconds / 3600), "",
          "The TEXPLORE agents plan on the separate forest (the suite's default, --combo "
          "separate: one full tree plans, the forest gives the variance; the task phase's value "
          "iteration plans on the forest's average; the original's default is --combo average) "
          "and do not put off one-way steps (--defer 0, the original's).", "",
          "For reference, the paper's optimal policy earns %.1f over the 3000 task steps." %
          PAPER_OPTIMAL_TASK_REWARD, ""] + tables
    tmp = os.path.join(out, ".results.md.tmp")
    with open(tmp, "w") as f:
        f.write("\n".join(md) + "\n")
    os.replace(tmp, os.path.join(out, "results.md"))
    log("\n".join(md))
    log("results: %s (%.1f min)" % (os.path.join(out, "results.md"), elapsed / 60))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
