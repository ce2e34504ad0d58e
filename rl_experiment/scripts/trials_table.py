#!/usr/bin/env python3
"""One per-trial table from experiment run folders: small enough to commit with the results.

Usage: trials_table.py --out FILE [--at-step N ...] RUN_FOLDER [RUN_FOLDER ...]

Each RUN_FOLDER is an `--out` folder of the `experiment` runner or node. Writes FILE (CSV): one
row per finished trial (the folder's trial-NNN.csv summaries: seeds, rewards, final accuracy,
PRESS and PICKUP counts by place, time), with the folder's label as the first column, `agent`
(the summary's agent type becomes `agent_type`),
and for each --at-step N a column `distance_stepN`: the model's variational distance measured
at step N (accuracy-NNN.csv; empty where the trial has no such measurement, e.g. a model-free
agent). Columns are the union over folders, in first-seen order. The run folders (steps files,
hundreds of MB at the paper's scale) can then be deleted without losing a figure's numbers:
plot_trials.py draws from FILE. The file is written to FILE.tmp and renamed, so a killed run
leaves the previous FILE whole. Exits 2 on a folder without trials.
"""
import argparse
import csv
import glob
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_results import label_of, read_csv  # noqa: E402


def distance_at(accuracy_rows, step):
    for row in accuracy_rows:
        if row.get("step") == str(step):
            return row.get("variational_distance", "")
    return ""


def folder_rows(folder, steps):
    rows = []
    label = label_of(folder)
    for path in sorted(glob.glob(os.path.join(folder, "trial-*.csv"))):
        for summary in read_csv(path):
            # `agent` is the run's label (as in the figures); the summary's agent type (e.g.
            # texplore for every TEXPLORE explorer) is kept as `agent_type`.
            row = {"agent": label}
            for k, v in summary.items():
                if k != "label":
                    row["agent_type" if k == "agent" else k] = v
            accuracy = os.path.join(folder, "accuracy-%03d.csv" % int(summary["trial"]))
            acc = read_csv(accuracy) if os.path.exists(accuracy) else []
            for n in steps:
                row["distance_step%d" % n] = distance_at(acc, n)
            rows.append(row)
    return rows


def write_table(path, rows):
    header = []
    for row in rows:
        header.extend(k for k in row if k not in header)
    tmp = path + ".tmp"
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=header, restval="")
        w.writeheader()
        w.writerows(rows)
    os.replace(tmp, path)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("folders", nargs="+")
    ap.add_argument("--out", required=True)
    ap.add_argument("--at-step", type=int, action="append", default=[],
                    help="add the model distance measured at this step")
    args = ap.parse_args(argv)
    rows = []
    for folder in args.folders:
        found = folder_rows(folder, args.at_step)
        if not found:
            print("trials_table.py: no finished trial (trial-NNN.csv) in %s" % folder,
                  file=sys.stderr)
            return 2
        rows.extend(found)
    write_table(args.out, rows)
    print("%d trials of %d folders into %s" % (len(rows), len(args.folders), args.out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
