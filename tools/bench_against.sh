#!/usr/bin/env bash
# Fixed-mode planning speed of this tree against an older revision, measured in one run.
#
#   tools/bench_against.sh REV [RUNS] [agent_benchmark fixed options...]
#   e.g. tools/bench_against.sh a990e7b 5 --steps 1000 --rollouts 100
#
# Builds REV's rl_experiment_agent_benchmark in a git worktree under .build/bench-REV (once),
# builds this tree's (./rl build), then runs the two alternately RUNS times (default 5), so
# that both see the same machine load, and prints each run's rollouts/s at the last row and
# the median ratio. Prints figures only.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
[ $# -ge 1 ] || { echo "usage: tools/bench_against.sh REV [RUNS] [benchmark options]" >&2; exit 2; }
REV=$1
shift
RUNS=5
if [ $# -ge 1 ] && [[ $1 =~ ^[0-9]+$ ]]; then RUNS=$1; shift; fi
ARGS=("$@")
[ ${#ARGS[@]} -gt 0 ] || ARGS=(--steps 1000 --rollouts 100)
export PATH=/usr/sbin:/usr/bin:/sbin:/bin:$PATH

# shellcheck source=tools/old_build.sh
source "$ROOT/tools/old_build.sh"
old_build "$REV" rl_experiment_agent_benchmark
SHA=$OLD_SHA
"$ROOT/rl" build >/dev/null
OLD=$OLD_DEVEL/lib/rl_experiment/rl_experiment_agent_benchmark
NEW=$ROOT/.build/devel/lib/rl_experiment/rl_experiment_agent_benchmark

rate() { "$1" fixed "${ARGS[@]}" | awk 'NF == 6 && $1 ~ /^[0-9]+$/ { r = $4 } END { print r }'; }
ratios=()
echo "run  $SHA rollouts/s  this tree rollouts/s  ratio"
for i in $(seq 1 "$RUNS"); do
  old=$(rate "$OLD")
  new=$(rate "$NEW")
  ratio=$(awk -v a="$new" -v b="$old" 'BEGIN { printf "%.2f", a / b }')
  ratios+=("$ratio")
  printf '%3d  %16s  %20s  %5s\n' "$i" "$old" "$new" "$ratio"
done
printf '%s\n' "${ratios[@]}" | sort -n | awk '{ a[NR] = $1 } END {
  m = (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2
  printf "median ratio over %d runs: %.2fx\n", NR, m }'
