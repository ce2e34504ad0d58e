#!/usr/bin/env bash
# One whole experiment trial of this tree against an older build, timed in one run.
#
#   tools/trial_against.sh OLD [RUNS] [experiment options...]
#   e.g. tools/trial_against.sh 8d634a9 2
#
# OLD is a revision (its `experiment` is built in a git worktree under .build/bench-REV, once)
# or the lib folder of a copied devel tree (e.g. /work/runs/bin5/lib). Each run starts the old
# and this tree's `experiment` at the same time, one per core, with the same options, so both
# see the same load; it prints both wall times, their ratio and whether the two runs' steps and
# accuracy files are byte-identical. Default options: the paper-scale run's VANIR explore-task
# trial (seed 1, 1000 + 3000 steps, value-iteration task phase).
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
[ $# -ge 1 ] || { echo "usage: tools/trial_against.sh REV|LIBDIR [RUNS] [experiment options]" >&2; exit 2; }
OLDARG=$1
shift
RUNS=1
if [ $# -ge 1 ] && [[ $1 =~ ^[0-9]+$ ]]; then RUNS=$1; shift; fi
ARGS=("$@")
[ ${#ARGS[@]} -gt 0 ] || ARGS=(--agent texplore --v 1 --n 3 --rollouts 100 --lambda 1.0
  --taskplanner vi --taskkey 0,1,2,3,4 --env lightworld --seed 1 --eval-samples 5000
  --explore-steps 1000 --task-steps 3000 --task-rewards given --trials 1 --jobs 1)
export PATH=/usr/sbin:/usr/bin:/sbin:/bin:$PATH

if [ -d "$OLDARG" ]; then
  OLDLIB=$(cd "$OLDARG" && pwd)
  LABEL=$(basename "$(dirname "$OLDLIB")")
else
  # shellcheck source=tools/old_build.sh
  source "$ROOT/tools/old_build.sh"
  old_build "$OLDARG" experiment
  OLDLIB=$OLD_DEVEL/lib
  LABEL=$OLD_SHA
fi
"$ROOT/rl" build >/dev/null
NEWLIB=$ROOT/.build/devel/lib
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT

timed() {  # LIBDIR OUTDIR: wall seconds of one experiment run
  local start end
  start=$(date +%s.%N)
  LD_LIBRARY_PATH=$1 "$1/rl_experiment/experiment" "${ARGS[@]}" --progress off --out "$2" \
    >"$2.log" 2>&1 || { echo "experiment failed, see:" >&2; tail -5 "$2.log" >&2; return 1; }
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN { printf "%.1f", b - a }'
}
printf 'run  %12s s  this tree s  ratio  files\n' "$LABEL"
for i in $(seq 1 "$RUNS"); do
  rm -rf "$OUT/old" "$OUT/new"
  timed "$OLDLIB" "$OUT/old" >"$OUT/old.time" &
  pid=$!
  new=$(timed "$NEWLIB" "$OUT/new")
  wait "$pid"
  old=$(cat "$OUT/old.time")
  same=identical
  for f in "$OUT"/old/steps-*.csv "$OUT"/old/accuracy-*.csv; do
    [ -e "$f" ] || continue
    cmp -s "$f" "$OUT/new/$(basename "$f")" || same=different
  done
  ratio=$(awk -v a="$old" -v b="$new" 'BEGIN { printf "%.2f", a / b }')
  printf '%3d  %14s  %11s  %5s  %s\n' "$i" "$old" "$new" "$ratio" "$same"
done
