#!/usr/bin/env python3
"""Self time of perf.data files grouped by what the code does (docs/performance/profile.md).

Usage: tools/perf_groups.py PERF_DATA [PERF_DATA ...]

Reads `perf report --no-children --sort symbol` of each file and prints one Markdown table:
the share of samples per group (the first group whose pattern matches a symbol takes it).
"""
import re
import subprocess
import sys

GROUPS = [
    ("state table (hash, lookup, record touch)", r"_Hashtable|StateHash|UctPlanner::touch|StateIndex"),
    ("UCB selection", r"selectUcbAction|__ieee754_log|^log@"),
    ("model query: tree descent",
     r"C45Tree::Snapshot::(predict|leaf)|treePredictions|RandomForest::Snapshot::predict"),
    ("model query: variance (KL)",
     r"klDivergence|klUnchecked|disagreement|RandomForest::Snapshot::variance"),
    ("model query: combining, other",
     r"combine|FactoredModel::View|ExplorationModel|UctPlanner::prediction"),
    ("novelty (k-d trees)", r"Novelty|nanoflann"),
    ("sampling the next state, range check",
     r"sampleSuccessor|inRange|allFinite|find_if|withinFeatureRanges"),
    ("rollout loop, backups", r"UctPlanner::rollout|clearPath"),
    ("allocation (malloc/free)",
     r"malloc|free|_int_|unlink_chunk|operator new|operator delete|consolidate"),
    ("model learning (tree updates)", r"C45Tree::(learn|build|rebuild)|RandomForest::add|[Gg]ain"),
]


def samples(path):
    """(percent, symbol) per symbol of one perf.data file."""
    out = subprocess.run(["perf", "report", "-i", path, "--no-children", "--sort", "symbol",
                          "--stdio"], capture_output=True, text=True, check=True).stdout
    for line in out.splitlines():
        m = re.match(r"\s+([0-9.]+)%\s+\[[.k]\]\s+(.*)", line)
        if m:
            yield float(m.group(1)), m.group(2).strip()


def grouped(path):
    shares = {name: 0.0 for name, _ in GROUPS}
    other = 0.0
    for percent, symbol in samples(path):
        for name, pattern in GROUPS:
            if re.search(pattern, symbol):
                shares[name] += percent
                break
        else:
            other += percent
    return shares, other


def main(paths):
    if not paths:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    tables = [grouped(p) for p in paths]
    print("| where the time goes | " + " | ".join(paths) + " |")
    print("|---|" + "---|" * len(paths))
    for name, _ in GROUPS:
        print("| %s | %s |" % (name, " | ".join("%.1f%%" % t[0][name] for t in tables)))
    print("| other | %s |" % " | ".join("%.1f%%" % t[1] for t in tables))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
