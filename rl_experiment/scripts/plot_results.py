#!/usr/bin/env python3
"""Figures and a table from experiment run folders (the TEXPLORE-VANIR paper's LightWorld plots).

Usage: plot_results.py [--out DIR] [--title TEXT] [--reference LABEL] RUN_FOLDER [RUN_FOLDER ...]

Each RUN_FOLDER is an `--out` folder of the `experiment` runner or node. Folders with the same
label (run.csv's `label`, e.g. from one sweep split over several machines with --first-trial)
are merged. Per label, over trials, the script draws mean +- standard error of:
  reward.png/.pdf    cumulative external reward vs step (of the task phase if there is one;
                     Figs. 5, 7, 8)
  accuracy.png/.pdf  the model's mean variational distance to the true dynamics vs step (Fig. 4)
  press.png/.pdf     cumulative PRESS actions by where they were tried (Fig. 6), one panel per
                     label
and writes results.md: final numbers with 95% confidence intervals and, per column, the p-value
of a two-sided Welch t-test of each label's per-trial values against the reference label's
(--reference; default texplore-vanir if present, else the first label; stats.py next to this
script). Needs numpy and matplotlib (Debian's python3-numpy, python3-matplotlib); run with
/usr/bin/python3.
"""
import argparse
import csv
import glob
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import stats  # noqa: E402  (rl_experiment/scripts/stats.py)

# Two-sided 95% Student t quantiles for 1..30 degrees of freedom (normal beyond).
T95 = [12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179,
       2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064,
       2.060, 2.056, 2.052, 2.048, 2.045, 2.042]
LOCATIONS = [("key", "on the key"), ("lock", "on the lock (with key, door closed)"),
             ("lock_wrong", "on the lock (otherwise)"), ("door", "on the door"),
             ("elsewhere", "elsewhere")]
DEFAULT_REFERENCE = "texplore-vanir"


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def label_of(folder):
    path = os.path.join(folder, "run.csv")
    if os.path.exists(path):
        for row in read_csv(path):
            if row.get("name") == "label" and row.get("value"):
                return row["value"]
    return os.path.basename(os.path.normpath(folder))


def mean_se(matrix):
    """Mean and standard error over rows (trials) of a 2-D array."""
    m = np.asarray(matrix, dtype=float)
    mean = m.mean(axis=0)
    if m.shape[0] < 2:
        return mean, np.zeros_like(mean)
    return mean, m.std(axis=0, ddof=1) / math.sqrt(m.shape[0])


def ci95(values):
    v = np.asarray(values, dtype=float)
    v = v[~np.isnan(v)]
    if len(v) == 0:
        return float("nan"), float("nan"), 0
    if len(v) < 2:
        return float(v.mean()), float("nan"), len(v)
    t = T95[len(v) - 2] if len(v) - 1 <= len(T95) else 1.96
    return float(v.mean()), t * float(v.std(ddof=1)) / math.sqrt(len(v)), len(v)


class Run:
    """All trials of one label."""

    def __init__(self, label):
        self.label = label
        self.rewards = []  # per trial: cumulative external reward over the plotted steps
        self.phase_name = "run"
        self.accuracy = []  # per trial: (steps, distances)
        self.press = []  # per trial: {location: cumulative count array}
        self.summaries = []

    def add_folder(self, folder):
        for path in sorted(glob.glob(os.path.join(folder, "steps-*.csv"))):
            rows = read_csv(path)
            if not rows:
                continue
            phases = {r["phase"] for r in rows}
            plotted = [r for r in rows if r["phase"] == "task"] if "task" in phases else rows
            if "task" in phases:
                self.phase_name = "task"
            self.rewards.append(np.cumsum([float(r["reward"]) for r in plotted]))
            press = {}
            for key, _ in LOCATIONS:
                press[key] = np.cumsum([1 if r["action"] == "5" and r["target"] == key else 0
                                        for r in rows])
            self.press.append(press)
        for path in sorted(glob.glob(os.path.join(folder, "accuracy-*.csv"))):
            rows = read_csv(path)
            if rows:
                self.accuracy.append((np.array([int(r["step"]) for r in rows]),
                                      np.array([float(r["variational_distance"]) for r in rows])))
        for path in sorted(glob.glob(os.path.join(folder, "trial-*.csv"))):
            self.summaries.extend(read_csv(path))


def truncate(arrays):
    n = min(len(a) for a in arrays)
    return np.array([a[:n] for a in arrays])


def save(fig, out, name):
    for ext in ("png", "pdf"):
        fig.savefig(os.path.join(out, name + "." + ext), dpi=130, bbox_inches="tight")
    plt.close(fig)


def plot_reward(runs, out, title):
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for run in runs:
        if not run.rewards:
            continue
        m, se = mean_se(truncate(run.rewards))
        x = np.arange(1, len(m) + 1)
        ax.plot(x, m, label="%s (%d trials)" % (run.label, len(run.rewards)))
        ax.fill_between(x, m - se, m + se, alpha=0.25)
    phase = "task-phase " if any(r.phase_name == "task" for r in runs) else ""
    ax.set_xlabel("Step of the %s(agent's actions)" % ("task phase " if phase else "run "))
    ax.set_ylabel("Cumulative external reward")
    ax.set_title(title or "LightWorld: cumulative %sreward (mean \u00b1 s.e.)" % phase)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, out, "reward")


def plot_accuracy(runs, out, title):
    fig, ax = plt.subplots(figsize=(7, 4.5))
    drawn = False
    for run in runs:
        if not run.accuracy:
            continue
        n = min(len(s) for s, _ in run.accuracy)
        steps = run.accuracy[0][0][:n]
        m, se = mean_se(np.array([d[:n] for _, d in run.accuracy]))
        ax.plot(steps, m, marker=".", label="%s (%d trials)" % (run.label, len(run.accuracy)))
        ax.fill_between(steps, m - se, m + se, alpha=0.25)
        drawn = True
    ax.set_xlabel("Steps taken by the agent")
    ax.set_ylabel("Variational distance, model vs true dynamics\n(lower is more accurate)")
    ax.set_title(title or "LightWorld: model accuracy (mean \u00b1 s.e.)")
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    if drawn:
        ax.legend(fontsize=8)
    else:
        ax.text(0.5, 0.5, "no agent with a learned model", ha="center", transform=ax.transAxes)
    save(fig, out, "accuracy")


def plot_press(runs, out, title):
    runs = [r for r in runs if r.press]
    cols = max(1, min(3, len(runs)))
    rows = max(1, int(math.ceil(len(runs) / cols)))
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.4 * rows), squeeze=False)
    for i, run in enumerate(runs):
        ax = axes[i // cols][i % cols]
        for key, text in LOCATIONS:
            arrays = truncate([p[key] for p in run.press])
            m, se = mean_se(arrays)
            x = np.arange(1, len(m) + 1)
            ax.plot(x, m, label=text)
            ax.fill_between(x, m - se, m + se, alpha=0.2)
        ax.set_title("%s (%d trials)" % (run.label, len(run.press)), fontsize=9)
        ax.set_xlabel("Step")
        ax.set_ylabel("Cumulative PRESS actions")
        ax.grid(alpha=0.3)
    for j in range(len(runs), rows * cols):
        axes[j // cols][j % cols].axis("off")
    if runs:
        axes[0][0].legend(fontsize=7)
    fig.suptitle(title or "LightWorld: where PRESS was tried (mean \u00b1 s.e.)")
    fig.tight_layout()
    save(fig, out, "press")


def fmt(mean, half, n):
    if n == 0 or math.isnan(mean):
        return "n/a"
    if math.isnan(half):
        return "%.1f" % mean
    return "%.1f \u00b1 %.1f" % (mean, half)


def fmt3(mean, half, n):
    if n == 0 or math.isnan(mean):
        return "n/a"
    if math.isnan(half):
        return "%.3f" % mean
    return "%.3f \u00b1 %.3f" % (mean, half)


def pick_reference(runs, label=None):
    """The run the p-values compare against: `label`, else texplore-vanir if present, else the
    first run. An unknown label is a ValueError naming the valid ones."""
    by_label = {r.label: r for r in runs}
    if label:
        if label not in by_label:
            raise ValueError("unknown --reference '%s'; valid labels: %s"
                             % (label, ", ".join(by_label)))
        return by_label[label]
    return by_label.get(DEFAULT_REFERENCE, runs[0])


def table_columns(run):
    """Per-trial values of the table's measured columns, in column order."""
    rewards = [float(r[-1]) if len(r) else 0.0 for r in run.rewards]
    acc = [float(d[-1]) for _, d in run.accuracy]
    frac = []
    for p in run.press:
        total = sum(p[k][-1] if len(p[k]) else 0 for k, _ in LOCATIONS)
        on = total - (p["elsewhere"][-1] if len(p["elsewhere"]) else 0)
        frac.append(on / total if total else float("nan"))
    sps = [float(s["steps_per_second"]) for s in run.summaries if s.get("steps_per_second")]
    return [(rewards, fmt), (acc, fmt3), (frac, fmt3), (sps, fmt)]


def write_table(runs, out, title, reference=None):
    """results.md: per run the mean and 95% interval of each column, and the Welch p-value of
    its per-trial values against the reference run's (`reference`: a label, see
    pick_reference)."""
    ref = pick_reference(runs, reference)
    ref_columns = table_columns(ref)
    lines = ["# " + (title or "LightWorld results"), "",
             "Mean over trials with 95% confidence interval (Student t); p against "
             + ref.label + ".", "",
             "| agent | trials | cumulative reward | p | final model variational distance | p | "
             "PRESS on objects / all PRESS | p | steps/s | p |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for run in runs:
        cells = [run.label, "%d" % len(run.rewards)]
        for (values, form), (ref_values, _) in zip(table_columns(run), ref_columns):
            cells.append(form(*ci95(values)))
            cells.append("ref" if run is ref else
                         stats.format_p(stats.welch_t_test(values, ref_values)[2]))
        lines.append("| " + " | ".join(cells) + " |")
    lines += ["", stats.p_value_note(ref.label)]
    text = "\n".join(lines) + "\n"
    tmp = os.path.join(out, ".results.md.tmp")
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, os.path.join(out, "results.md"))
    return text


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("folders", nargs="+", help="run folders (--out of the experiment runner)")
    ap.add_argument("--out", default="figures", help="folder for the figures and results.md")
    ap.add_argument("--title", default="", help="title prefix of the figures")
    ap.add_argument("--reference", default=None, metavar="LABEL",
                    help="label the table's p-values compare against (default %s if present, "
                         "else the first label)" % DEFAULT_REFERENCE)
    args = ap.parse_args(argv)
    runs = {}
    for folder in args.folders:
        if not os.path.isdir(folder):
            ap.error("not a folder: " + folder)
        label = label_of(folder)
        runs.setdefault(label, Run(label)).add_folder(folder)
    runs = [r for r in runs.values() if r.rewards or r.accuracy]
    if not runs:
        ap.error("no trials found in " + ", ".join(args.folders))
    try:
        pick_reference(runs, args.reference)
    except ValueError as e:
        ap.error(str(e))
    os.makedirs(args.out, exist_ok=True)
    plot_reward(runs, args.out, args.title)
    plot_accuracy(runs, args.out, args.title)
    plot_press(runs, args.out, args.title)
    sys.stdout.write(write_table(runs, args.out, args.title, args.reference))
    print("figures in %s: reward, accuracy, press (.png, .pdf), results.md" % args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
