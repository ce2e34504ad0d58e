# Sourced by tools/bench_against.sh and tools/trial_against.sh: an older revision's build.
#
#   old_build REV TARGET   builds TARGET of REV in a git worktree under .build/bench-SHA (once)
#                          and sets OLD_DEVEL to its devel folder and OLD_SHA to the short hash.
# Needs ROOT (the repository) to be set.
old_build() {
  OLD_SHA=$(git -C "$ROOT" rev-parse --short "$1")
  local base=$ROOT/.build/bench-$OLD_SHA
  OLD_DEVEL=$base/devel
  if [ ! -x "$OLD_DEVEL/lib/rl_experiment/$2" ]; then
    [ -d "$base/src" ] || git -C "$ROOT" worktree add --detach "$base/src" "$OLD_SHA" >&2
    cmake -S "$base/src" -B "$base/build" -DCATKIN_DEVEL_PREFIX="$OLD_DEVEL" \
      -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCATKIN_ENABLE_TESTING=OFF >"$base/configure.log" 2>&1 || { cat "$base/configure.log"; exit 1; }
    cmake --build "$base/build" --target "$2" -- -j"$(nproc)" >&2
  fi
}
