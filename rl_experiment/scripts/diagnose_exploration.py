#!/usr/bin/env python3
"""Where a LightWorld explorer's model is wrong and what the explorer chose to try.

Reads run folders of the experiment runner (steps-*.csv, accuracy-*.csv, trial-*.csv) and
prints, per folder, as Markdown tables:

  * the model's distance at a checkpoint (default: the last exploration checkpoint): the joint
    variational distance, each feature's marginal distance (which features carry the error) and
    the joint distance per action (which actions do);
  * the exploration steps by class (a move, or PICKUP/PRESS and where it was tried), with the
    variance and novelty bonuses the agent met on them;
  * doors passed (exploration reward / 10), PRESS on objects, and the exploration steps taken
    with the key on the floor (with their correlation with the final distance);
  * with the runner's --eval-groups, the joint distance per group of sampled states (e.g.
    LightWorld's room, have_key and door_open: --eval-groups 4,2,3) and each group's share of
    the samples, so that one sees which situations carry the error.

With --reference REF, each other folder's final distance is also compared with REF's at equal
exploration steps with the key on the floor (least squares with that covariate).

Usage: diagnose_exploration.py [--step N] [--reference REF] FOLDER [FOLDER ...]
"""
import argparse
import collections
import csv
import glob
import math
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import stats  # noqa: E402  (rl_experiment/scripts/stats.py)

# LightWorld's 17 features (shared/spec/ORIGINAL.md §4.2) and 6 actions.
FEATURES = ["ns", "ew", "have_key", "door_open", "room", "key_n", "key_e", "key_w", "key_s",
            "lock_n", "lock_e", "lock_w", "lock_s", "door_n", "door_e", "door_w", "door_s"]
ACTIONS = ["N", "E", "W", "S", "PICKUP", "PRESS"]
PRESS_ON_OBJECTS = ["press_key", "press_lock", "press_lock_wrong", "press_door"]


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def mean(values):
    return statistics.mean(values) if values else float("nan")


def sd(values):
    return statistics.stdev(values) if len(values) > 1 else float("nan")


def checkpoint_rows(folder, step):
    out = []
    for path in sorted(glob.glob(os.path.join(folder, "accuracy-*.csv"))):
        r = rows(path)
        explore = [x for x in r if x["phase"] == "explore"]
        if step is None:
            pick = explore[-1:] if explore else r[-1:]
        else:
            pick = [x for x in r if int(x["step"]) == step]
        out += pick
    return out


def accuracy_table(folder, step):
    acc = checkpoint_rows(folder, step)
    if not acc:
        return ["(no accuracy logs)"]
    lines = []
    joint = [float(x["variational_distance"]) for x in acc]
    where = sorted({x["step"] for x in acc})
    lines.append("model distance at step %s over %d trials: joint %.3f (sd %.3f)" %
                 ("/".join(where), len(acc), mean(joint), sd(joint)))
    if "marginal_f0" in acc[0]:
        marg = [mean([float(x["marginal_f%d" % j]) for x in acc]) for j in range(len(FEATURES))
                if "marginal_f%d" % j in acc[0]]
        lines += ["", "| feature | " + " | ".join(FEATURES[:len(marg)]) + " |",
                  "|---|" + "---|" * len(marg),
                  "| marginal distance | " + " | ".join("%.3f" % m for m in marg) + " |"]
        per_action = []
        for a in range(len(ACTIONS)):
            vals = [float(x["action_%d" % a]) for x in acc if x.get("action_%d" % a)]
            per_action.append(mean(vals))
        lines += ["", "| action | " + " | ".join(ACTIONS) + " |", "|---|" + "---|" * len(ACTIONS),
                  "| joint distance | " + " | ".join("%.3f" % m for m in per_action) + " |"]
    return lines


def group_table(folder, step):
    by_group = collections.defaultdict(lambda: [0, 0.0, 0])  # samples, distance sum, trials
    found = False
    for path in sorted(glob.glob(os.path.join(folder, "groups-*.csv"))):
        r = rows(path)
        explore = [x for x in r if x["phase"] == "explore"]
        at = (explore[-1]["step"] if explore else r[-1]["step"]) if step is None else str(step)
        for x in r:
            if x["step"] != at:
                continue
            found = True
            g = by_group[x["group"]]
            n = int(x["samples"])
            g[0] += n
            g[1] += n * float(x["variational_distance"])
            g[2] += 1
    if not found:
        return []
    total = sum(g[0] for g in by_group.values())
    lines = ["| state group | share of samples | joint distance | share of the error |",
             "|---|---|---|---|"]
    error = sum(g[1] for g in by_group.values())
    for name, (n, d, _) in sorted(by_group.items()):
        lines.append("| %s | %.3f | %.3f | %.3f |" % (name, n / total, d / n, d / error))
    return lines


def class_table(folder):
    stats = collections.defaultdict(lambda: [0, 0.0, 0.0])
    trials = 0
    for path in sorted(glob.glob(os.path.join(folder, "steps-*.csv"))):
        trials += 1
        for r in rows(path):
            if r["phase"] != "explore":
                continue
            a = int(r["action"])
            name = "move" if a < 4 else ACTIONS[a] + " " + (r["target"] or "?")
            s = stats[name]
            s[0] += 1
            s[1] += float(r["variance"] or 0)
            s[2] += float(r["novelty"] or 0)
    if not trials:
        return ["(no step logs)"]
    total = sum(s[0] for s in stats.values())
    lines = ["| exploration steps | per trial | share | mean variance bonus | mean novelty bonus |",
             "|---|---|---|---|---|"]
    for name, (n, v, nov) in sorted(stats.items(), key=lambda kv: -kv[1][0]):
        lines.append("| %s | %.1f | %.3f | %.4f | %.4f |" %
                     (name, n / trials, n / total, v / n, nov / n))
    return lines


def summary_line(folder):
    trials = [rows(p)[0] for p in sorted(glob.glob(os.path.join(folder, "trial-*.csv")))]
    if not trials:
        return "(no finished trials)"
    doors = [float(t["explore_reward"] or 0) / 10 for t in trials]
    press = [sum(float(t.get(k) or 0) for k in PRESS_ON_OBJECTS) for t in trials]
    line = ("%d trials: doors passed while exploring %.2f per trial (sd %.2f); PRESS on objects "
            "%.1f per trial (sd %.1f)" % (len(trials), mean(doors), sd(doors), mean(press),
                                          sd(press)))
    # Exploration steps with the key on the floor: the only steps that teach the key sensors,
    # and most of the trial-to-trial spread of the final distance (lightworld-curiosity.md §2.1).
    floor = [(float(t["explore_key_on_floor"]), float(t["final_accuracy"])) for t in trials
             if t.get("explore_key_on_floor") and t.get("final_accuracy")]
    if floor:
        line += "; exploration steps with the key on the floor %.0f per trial (sd %.0f)" % (
            mean([f for f, _ in floor]), sd([f for f, _ in floor]))
        if len(floor) > 2 and len({f for f, _ in floor}) > 1:
            line += ", correlation with the final distance %.2f" % statistics.correlation(
                [f for f, _ in floor], [a for _, a in floor])
    return line


def floor_pairs(folder):
    """(exploration steps with the key on the floor, final distance) per finished trial."""
    out = []
    for path in sorted(glob.glob(os.path.join(folder, "trial-*.csv"))):
        t = rows(path)[0]
        if t.get("explore_key_on_floor") and t.get("final_accuracy"):
            out.append((float(t["explore_key_on_floor"]), float(t["final_accuracy"])))
    return out


def floor_adjusted(folder, reference):
    """The folder's final distance minus the reference's at equal time with the key on the floor.

    Ordinary least squares of distance ~ 1 + [folder] + log(1 + steps with the key on the
    floor) over both folders' trials (an analysis of covariance); returns (difference, its
    standard error, the two-sided p of its t statistic, the fit's R^2), or None with fewer than
    five trials in all.
    """
    a, b = floor_pairs(folder), floor_pairs(reference)
    n = len(a) + len(b)
    if not a or not b or n < 5:
        return None
    import numpy as np
    y = np.array([d for _, d in a + b])
    x = np.column_stack([np.ones(n), [1.0] * len(a) + [0.0] * len(b),
                         np.log1p([f for f, _ in a + b])])
    beta = np.linalg.lstsq(x, y, rcond=None)[0]
    resid = y - x @ beta
    dof = n - 3
    s2 = float(resid @ resid) / dof
    se = math.sqrt(s2 * np.linalg.inv(x.T @ x)[1, 1])
    tss = float(((y - y.mean()) ** 2).sum())
    p = stats.student_t_two_sided_p(beta[1] / se, dof) if se > 0 else float("nan")
    return float(beta[1]), se, p, (1.0 - float(resid @ resid) / tss) if tss > 0 else float("nan")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--step", type=int, default=None,
                    help="accuracy checkpoint to report (default: the last exploration one)")
    ap.add_argument("--reference", default=None,
                    help="a run folder to compare every other folder with at equal exploration "
                         "steps with the key on the floor")
    ap.add_argument("folders", nargs="+")
    args = ap.parse_args(argv)
    for folder in args.folders:
        if not os.path.isdir(folder):
            print("diagnose_exploration.py: no such folder: %s" % folder, file=sys.stderr)
            return 2
    for folder in args.folders:
        print("## %s\n" % os.path.basename(os.path.normpath(folder)))
        print(summary_line(folder) + "\n")
        print("\n".join(accuracy_table(folder, args.step)) + "\n")
        groups = group_table(folder, args.step)
        if groups:
            print("\n".join(groups) + "\n")
        print("\n".join(class_table(folder)) + "\n")
        if args.reference and os.path.normpath(folder) != os.path.normpath(args.reference):
            adj = floor_adjusted(folder, args.reference)
            if adj:
                print("final distance against %s at equal steps with the key on the floor: "
                      "%+.3f (se %.3f, p = %s; R^2 of the fit %.2f)\n" % (
                          os.path.basename(os.path.normpath(args.reference)), adj[0], adj[1],
                          stats.format_p(adj[2]), adj[3]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
