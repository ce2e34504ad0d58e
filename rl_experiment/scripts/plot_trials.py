#!/usr/bin/env python3
"""Per-agent figures and a table from a per-trial CSV (one row per trial, an `agent` column).

Usage: plot_trials.py --out DIR [--title TEXT] [--reference AGENT] [--agents A,B,...]
                      --column LABEL=SPEC [--column LABEL=SPEC ...] TRIALS_CSV

For tables of finished trials whose run folders are not kept, e.g.
docs/science/data/lightworld-paper-seed1-explore-task.csv. SPEC names the CSV's
columns: `col` (the value), `a+b` (a sum) or `a+b/c+d` (a ratio of sums, e.g. the share of
PRESS actions on objects). An empty cell makes the trial's value missing (left out of that
column). Per column, draws DIR/<slug>.png and .pdf: every trial's value as a dot and each
agent's mean with its 95% Student t interval. Writes DIR/results.md: mean +- half-width of
the 95% interval and the two-sided Welch p against --reference (default texplore-vanir if
present, else the first agent). Agents appear in --agents' order (default: as first met).
Needs numpy and matplotlib (Debian's python3-numpy, python3-matplotlib); /usr/bin/python3.
Exits 2 with a message on a column or agent the CSV lacks.
"""
import argparse
import csv
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import stats  # noqa: E402  (rl_experiment/scripts/stats.py)
from plot_results import ci95, save  # noqa: E402

DEFAULT_REFERENCE = "texplore-vanir"


class UsageError(Exception):
    pass


def parse_column(text, header):
    """LABEL=SPEC -> (label, numerator columns, denominator columns or None)."""
    label, sep, spec = text.partition("=")
    if not sep or not label.strip() or not spec.strip():
        raise UsageError("--column takes LABEL=SPEC (SPEC: col, a+b or a+b/c+d), not %r" % text)
    parts = spec.split("/")
    if len(parts) > 2:
        raise UsageError("--column %r: at most one '/'" % text)
    sums = [[c.strip() for c in p.split("+")] for p in parts]
    for c in (c for s in sums for c in s):
        if c not in header:
            raise UsageError("--column %r: no column %r; the CSV has: %s"
                             % (text, c, ", ".join(header)))
    return label.strip(), sums[0], sums[1] if len(sums) == 2 else None


def value_of(row, numerator, denominator):
    """The trial's value of one column, NaN when a cell is empty or the denominator is 0."""
    try:
        num = math.fsum(float(row[c]) for c in numerator)
        if denominator is None:
            return num
        den = math.fsum(float(row[c]) for c in denominator)
    except ValueError:
        return float("nan")
    return num / den if den != 0 else float("nan")


def slug(label):
    return re.sub(r"[^a-z0-9]+", "-", label.lower()).strip("-") or "column"


def plot_column(label, agents, values, reference, out, title):
    # Agents without a value here (no forest model: no distance) get no empty slot.
    agents = [a for a in agents if any(not math.isnan(x) for x in values[a])]
    fig, ax = plt.subplots(figsize=(max(4.0, 0.9 * len(agents) + 1.5), 3.6))
    rng = np.random.default_rng(0)  # the dots' jitter only; the same figure every time
    for i, agent in enumerate(agents):
        v = np.asarray([x for x in values[agent] if not math.isnan(x)], dtype=float)
        ax.scatter(i + rng.uniform(-0.18, 0.18, len(v)), v, s=9, alpha=0.45,
                   color="C0" if agent == reference else "C7")
        mean, half, _ = ci95(v)
        ax.errorbar([i], [mean], yerr=[[0.0 if math.isnan(half) else half]] * 2, fmt="D",
                    color="C3", capsize=5, markersize=5, zorder=3)
    ax.set_xticks(range(len(agents)))
    ax.set_xticklabels(agents, rotation=30, ha="right")
    ax.set_ylabel(label)
    ax.set_title(title)
    ax.grid(axis="y", alpha=0.3)
    save(fig, out, slug(label))


def fmt(mean, half, n):
    if n == 0:
        return "n/a"
    return "%.3f ± %.3f" % (mean, half) if not math.isnan(half) else "%.3f" % mean


def write_table(columns, agents, data, reference, out, title, source):
    lines = ["# " + title, "", "Per-trial values: `%s`. Mean over trials with 95%% confidence "
             "interval (Student t); p against %s." % (source, reference), "",
             "| agent | " + " | ".join("%s | trials | p" % c for c in columns) + " |",
             "|---|" + "---|---|---|" * len(columns)]
    for agent in agents:
        cells = []
        for c in columns:
            mean, half, n = ci95(data[c][agent])
            if agent == reference:
                p = "ref"
            else:
                p = stats.format_p(stats.welch_t_test(data[c][agent], data[c][reference])[2])
            cells.append("%s | %d | %s" % (fmt(mean, half, n), n, p))
        lines.append("| %s | %s |" % (agent, " | ".join(cells)))
    lines += ["", stats.p_value_note(reference), ""]
    with open(os.path.join(out, "results.md"), "w") as f:
        f.write("\n".join(lines))
    return "\n".join(lines)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("csv")
    ap.add_argument("--out", required=True)
    ap.add_argument("--title", default="per-trial values")
    ap.add_argument("--reference")
    ap.add_argument("--agents", help="comma-separated, in the figures' order (default: all)")
    ap.add_argument("--column", action="append", required=True, help="LABEL=SPEC")
    args = ap.parse_args(argv)
    try:
        with open(args.csv, newline="") as f:
            reader = csv.DictReader(f)
            rows = list(reader)
            header = reader.fieldnames or []
        if "agent" not in header:
            raise UsageError("%s has no 'agent' column" % args.csv)
        found = list(dict.fromkeys(r["agent"] for r in rows))
        agents = args.agents.split(",") if args.agents else found
        missing = [a for a in agents if a not in found]
        if missing:
            raise UsageError("no trials of %s in %s; its agents: %s"
                             % (", ".join(missing), args.csv, ", ".join(found)))
        reference = args.reference or (DEFAULT_REFERENCE if DEFAULT_REFERENCE in agents
                                       else agents[0])
        if reference not in agents:
            raise UsageError("--reference %s is not among the agents: %s"
                             % (reference, ", ".join(agents)))
        specs = [parse_column(c, header) for c in args.column]
    except (UsageError, OSError) as e:
        print("plot_trials.py: %s" % e, file=sys.stderr)
        return 2
    os.makedirs(args.out, exist_ok=True)
    data = {}
    for label, num, den in specs:
        data[label] = {a: [value_of(r, num, den) for r in rows if r["agent"] == a]
                       for a in agents}
        plot_column(label, agents, data[label], reference, args.out, args.title)
    print(write_table([s[0] for s in specs], agents, data, reference, args.out, args.title,
                      os.path.basename(args.csv)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
