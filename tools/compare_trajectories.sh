#!/usr/bin/env bash
# Proof that a refactor changed no behaviour: the same seeds give byte-identical per-step logs.
#
#   tools/compare_trajectories.sh [--keep] OLD_REV [NEW_REV]
#   e.g. tools/compare_trajectories.sh a3d43ba 0e3862b   # two revisions
#        tools/compare_trajectories.sh HEAD             # HEAD against this working tree
#
# Builds OLD_REV's runner (target `experiment`) in a git worktree under .build/compare-SHA
# (once; reused while its binary exists), and NEW_REV's the same way, or without NEW_REV this
# tree's (./rl build). Runs four fixed-seed configurations (seed 42, one trial each) with both
# binaries, each into a fresh --out folder under a temporary directory:
#   lightworld-vanir  --agent texplore --env lightworld --v 1 --n 3 --rollouts 100 --steps 300
#   taxi-qlearner     --agent qlearner --env taxi --steps 3000
#   fourrooms-rmax    --agent rmax --env fourrooms --steps 1000
#   naoarm-vanir      --agent texplore --env naoarm --v 3 --n 10 --rollouts 100 --lambda 1
#                     --nstates 30,12,25,25,25,154,1,20 --steps 100   (reproduce_nao.py's)
# taxi and fourrooms are episodic, where --steps does not apply: the runner's default 1000
# episodes run (about 53000 and 23000 steps, a few seconds). Every run plans a fixed number of
# rollouts (never in real time), so that a run is a function of its seed.
#
# Then compares every steps-NNN.csv and accuracy-NNN.csv of the old and new runs byte for
# byte and prints one line per configuration: its name, the steps rows compared, and
# "identical" or "DIFFERENT" with the first difference (diff | head). Exits 0 only if all four
# are identical, 1 otherwise, 2 on a usage error. The temporary directory is removed at the
# end; with --keep it is kept and its path printed.
#
# Excluded columns: none today. Wall-clock time and memory are written only to trial-NNN.csv
# and trials.csv (seconds, steps_per_second, peak_rss_mb), which are not compared; the steps
# and accuracy files hold no timing column. Should one of TIMING_COLUMNS below ever appear in
# their header, that column is dropped by name on both sides before comparing, since it
# differs from run to run without any change in behaviour.
#
# Self-check: COMPARE_SEED_NEW=N runs the new side with seed N instead of 42, which must make
# every configuration DIFFERENT (shows that the comparison can fail); not for real use.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
usage() { echo "usage: tools/compare_trajectories.sh [--keep] OLD_REV [NEW_REV]" >&2; exit 2; }

KEEP=0
REVS=()
for arg in "$@"; do
  case "$arg" in
    --keep) KEEP=1 ;;
    -h | --help) sed -n '2,/^set -euo/{/^set -euo/d;s/^# \{0,1\}//;p}' "${BASH_SOURCE[0]}"; exit 0 ;;
    -*) usage ;;
    *) REVS+=("$arg") ;;
  esac
done
if [ ${#REVS[@]} -lt 1 ] || [ ${#REVS[@]} -gt 2 ]; then usage; fi
for rev in "${REVS[@]}"; do
  git -C "$ROOT" rev-parse -q --verify "$rev^{commit}" >/dev/null || { echo "unknown revision: $rev" >&2; usage; }
done
export PATH=/usr/sbin:/usr/bin:/sbin:/bin:$PATH

SEED=42
SEED_NEW=${COMPARE_SEED_NEW:-$SEED}
# Columns that measure the machine, not the agent (trial_logger.cpp's summary row).
TIMING_COLUMNS=seconds,steps_per_second,peak_rss_mb
NAMES=(lightworld-vanir taxi-qlearner fourrooms-rmax naoarm-vanir)
CONFIGS=(
  "--agent texplore --env lightworld --v 1 --n 3 --rollouts 100 --steps 300 --trials 1"
  "--agent qlearner --env taxi --steps 3000 --trials 1"
  "--agent rmax --env fourrooms --steps 1000 --trials 1"
  "--agent texplore --env naoarm --v 3 --n 10 --rollouts 100 --lambda 1 --nstates 30,12,25,25,25,154,1,20 --steps 100 --trials 1"
)

# build REV: prints the path of REV's runner, built once in .build/compare-SHA.
build() {
  local sha base start
  sha=$(git -C "$ROOT" rev-parse --short "$1^{commit}")
  base=$ROOT/.build/compare-$sha
  # The binary reads its package files (the Nao's URDF) from the worktree: both must be there.
  if [ ! -x "$base/devel/lib/rl_experiment/experiment" ] || [ ! -d "$base/src" ]; then
    start=$SECONDS
    echo "[compare] building $sha's experiment in $base (log: $base/build.log)" >&2
    [ -d "$base/src" ] || git -C "$ROOT" worktree add --detach "$base/src" "$sha" >&2
    cmake -S "$base/src" -B "$base/build" -DCATKIN_DEVEL_PREFIX="$base/devel" \
      -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCATKIN_ENABLE_TESTING=OFF >"$base/configure.log" 2>&1 || { cat "$base/configure.log" >&2; exit 1; }
    cmake --build "$base/build" --target experiment -- -j2 >"$base/build.log" 2>&1 ||
      { tail -n 40 "$base/build.log" >&2; exit 1; }
    echo "[compare] built $sha in $((SECONDS - start)) s" >&2
  fi
  echo "$base/devel/lib/rl_experiment/experiment"
}

OLD=$(build "${REVS[0]}")
OLD_NAME=$(git -C "$ROOT" rev-parse --short "${REVS[0]}^{commit}")
if [ ${#REVS[@]} -eq 2 ]; then
  NEW=$(build "${REVS[1]}")
  NEW_NAME=$(git -C "$ROOT" rev-parse --short "${REVS[1]}^{commit}")
else
  "$ROOT/rl" build >/dev/null
  NEW=$ROOT/.build/devel/lib/rl_experiment/experiment
  NEW_NAME="the working tree"
fi

TMP=$(mktemp -d "${TMPDIR:-/tmp}/compare-trajectories.XXXXXX")
if [ "$KEEP" -eq 1 ]; then
  trap 'echo "[compare] outputs kept in $TMP"' EXIT
else
  trap 'rm -rf "$TMP"' EXIT
fi

# run SIDE BINARY SEED NAME ARGS...: one configuration into $TMP/SIDE/NAME. The binary's own
# libraries come first (a sourced workspace's LD_LIBRARY_PATH would override its RUNPATH).
run() {
  local side=$1 bin=$2 seed=$3 name=$4
  shift 4
  mkdir -p "$TMP/$side"
  LD_LIBRARY_PATH="${bin%/rl_experiment/experiment}${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
    "$bin" "$@" --seed "$seed" --progress off --out "$TMP/$side/$name" >"$TMP/$side/$name.log" 2>&1
}

# strip FILE: FILE without the TIMING_COLUMNS (matched by header name).
strip() {
  awk -F, -v drop="$TIMING_COLUMNS" '
    BEGIN { n = split(drop, d, ","); for (i = 1; i <= n; i++) skip[d[i]] = 1 }
    NR == 1 { for (i = 1; i <= NF; i++) keep[i] = !($i in skip) }
    { line = ""; sep = ""
      for (i = 1; i <= NF; i++) if (keep[i]) { line = line sep $i; sep = "," }
      print line }' "$1"
}

echo "[compare] old: $OLD_NAME ($OLD)"
echo "[compare] new: $NEW_NAME ($NEW)"
[ "$SEED_NEW" = "$SEED" ] || echo "[compare] self-check: the new side runs with seed $SEED_NEW"
status=0
for i in "${!NAMES[@]}"; do
  name=${NAMES[$i]}
  read -ra args <<<"${CONFIGS[$i]}"
  failed=""
  run old "$OLD" "$SEED" "$name" "${args[@]}" || failed="old"
  run new "$NEW" "$SEED_NEW" "$name" "${args[@]}" || failed="${failed:+$failed and }new"
  if [ -n "$failed" ]; then
    printf '%-17s %8s steps rows  DIFFERENT: the %s run failed\n' "$name" - "$failed"
    for side in old new; do tail -n 5 "$TMP/$side/$name.log" | sed "s/^/    $side: /"; done
    status=1
    continue
  fi
  rows=0
  first=""
  # The steps files first, so that a difference is shown where the trajectory departs.
  files=()
  for kind in steps accuracy; do
    mapfile -t -O ${#files[@]} files < <(find "$TMP/old/$name" "$TMP/new/$name" -maxdepth 1 \
      -type f -name "$kind-*.csv" -printf '%f\n' | sort -u)
  done
  [ ${#files[@]} -gt 0 ] || first="    no steps-*.csv written"
  mkdir -p "$TMP/cmp/old/$name" "$TMP/cmp/new/$name"
  for f in "${files[@]}"; do
    o=$TMP/old/$name/$f
    n=$TMP/new/$name/$f
    if [ ! -f "$o" ] || [ ! -f "$n" ]; then
      [ -n "$first" ] || first="    $f: written by only one side ($( [ -f "$o" ] && echo old || echo new))"
      continue
    fi
    [[ $f == steps-* ]] && rows=$((rows + $(wc -l <"$o") - 1))
    strip "$o" >"$TMP/cmp/old/$name/$f"
    strip "$n" >"$TMP/cmp/new/$name/$f"
    if ! cmp -s "$TMP/cmp/old/$name/$f" "$TMP/cmp/new/$name/$f" && [ -z "$first" ]; then
      # The first hunk of the diff: its header (e.g. 12c12) and first old and new lines.
      first=$(diff "$TMP/cmp/old/$name/$f" "$TMP/cmp/new/$name/$f" |
        awk 'NR > 1 && /^[0-9]/ { exit } NR == 1 || (/^</ && !o++) || (/^>/ && !n++)' | head -n 3 | cut -c1-200 |
        sed "s|^|    $f: |" || true)
    fi
  done
  if [ -z "$first" ]; then
    printf '%-17s %8d steps rows  identical\n' "$name" "$rows"
  else
    printf '%-17s %8d steps rows  DIFFERENT\n%s\n' "$name" "$rows" "$first"
    status=1
  fi
done
exit "$status"
