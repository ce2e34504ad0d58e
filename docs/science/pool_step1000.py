#!/usr/bin/env python3
"""Fig. 4 at step 1000 pooled over every 100-rollout seed set at the current defaults (note §14).

Usage: /usr/bin/python3 docs/science/pool_step1000.py

Reads §12's per-trial values (seeds 707, 808, 909; data/lightworld-step1000-combo-separate-
explorers.csv) and the paper-scale run's (seed 1; docs/results/lightworld-2026-12-07/figures/
per-trial.csv) and prints each explorer's mean and sd of the step-1000 variational distance
over all of them, with the two-sided Welch p against TEXPLORE-VANIR.
"""
import csv
import os
import statistics
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "rl_experiment", "scripts"))
import stats  # noqa: E402

# §12's explorer names and the reproduction's agent labels, to one name each.
NOTE_NAMES = {"vanir-defer0-combo-separate": "vanir", "greedy-combo-separate": "greedy",
              "random-combo-separate": "random", "competence-combo-separate": "competence",
              "prederror-combo-separate": "prederror", "rmaxstyle-combo-separate": "rmax-style",
              "boltzmann-combo-separate": "boltzmann"}
RUN_NAMES = {"texplore-vanir": "vanir", "texplore-greedy": "greedy", "texplore-random": "random",
             "texplore-competence": "competence", "texplore-prederror": "prederror",
             "texplore-rmax-style": "rmax-style", "texplore-boltzmann": "boltzmann"}


def main():
    values = {}
    with open(os.path.join(ROOT, "docs/science/data/"
                                 "lightworld-step1000-combo-separate-explorers.csv")) as f:
        for row in csv.DictReader(f):
            name = NOTE_NAMES.get(row["explorer"])
            if name and row["rollouts"] == "100" and row["run_seed"] in ("707", "808", "909"):
                values.setdefault(name, []).append(float(row["distance_step1000"]))
    with open(os.path.join(ROOT, "docs/results/lightworld-2026-12-07/figures/per-trial.csv")) as f:
        for row in csv.DictReader(f):
            name = RUN_NAMES.get(row["agent"])
            if name and row["distance_step1000"]:
                values.setdefault(name, []).append(float(row["distance_step1000"]))
    ref = values["vanir"]
    print("explorer    trials  mean   sd     p against vanir")
    for name in RUN_NAMES.values():
        x = values[name]
        p = "ref" if name == "vanir" else stats.format_p(stats.welch_t_test(ref, x)[2])
        print("%-11s %6d  %.3f  %.3f  %s" % (name, len(x), statistics.mean(x),
                                             statistics.stdev(x), p))


if __name__ == "__main__":
    main()
