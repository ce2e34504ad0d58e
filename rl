#!/usr/bin/env bash
# The TEXPLORE suite's one entry point. Run `./rl help` for the subcommands.
#
# Every subcommand that needs the build installs what is missing (apt, via sudo when not root),
# then builds the catkin source space at the repository root out of source into .build/
# (git-ignored), with Debian's ROS 1 and /usr/bin/python3.
set -euo pipefail

ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
BUILD_ROOT=${RL_BUILD_DIR:-$ROOT/.build}
BUILD=$BUILD_ROOT/build
DEVEL=$BUILD_ROOT/devel
JOBS=${RL_JOBS:-$(nproc)}

# System directories first: a pyenv `python3` shim lacks catkin_pkg and the ROS modules.
export PATH=/usr/sbin:/usr/bin:/sbin:/bin:$PATH
export ROS_HOSTNAME=${ROS_HOSTNAME:-localhost}
export ROS_MASTER_URI=${ROS_MASTER_URI:-http://localhost:11311}

# Debian bookworm packages the suite needs (shared/DESIGN.md §5).
APT_PACKAGES=(
  build-essential cmake clang-format
  ros-core-dev catkin python3-catkin-pkg python3-rospy python3-roslaunch python3-rostest
  librostest-dev python3-rostopic python3-rosmsg python3-rosnode python3-rosservice rosbash
  ros-message-generation ros-message-runtime ros-std-msgs ros-std-srvs ros-sensor-msgs
  colcon python3-colcon-ros python3-colcon-cmake python3-colcon-bash python3-colcon-test-result
  libboost-program-options-dev libgtest-dev libgmock-dev libbenchmark-dev
  libeigen3-dev libnanoflann-dev liburdfdom-dev liburdf-dev libopencv-dev
  libcv-bridge-dev liburdfdom-tools python3-sensor-msgs
  ros-visualization-msgs libvisualization-msgs-dev python3-visualization-msgs
  python3-matplotlib python3-numpy python3-rosbag pybind11-dev python3-dev
  slurmctld slurmd slurm-client munge
  rviz ros-robot-state-publisher  # rviz:=true of the launch files works after the set-up commands
)

log() { printf '\033[1m[rl]\033[0m %s\n' "$*" >&2; }

usage() {
  cat <<USAGE
Usage: ./rl <command> [args]

  run [experiment options]  install, build, then run the default LightWorld experiment
  test                      install, build, run every test (gtest, rostest, lint); prints
                            'N passed, N failed' and exits non-zero on any failure
  reproduce lightworld [--quick] [options]
                            install, build, run the paper's LightWorld experiments (Figs. 4-8);
                            writes results/lightworld[-quick]/ with figures and results.md
  reproduce nao [--quick] [options]
                            the paper's Nao arm experiments on the simulated Nao (Figs. 10-14);
                            writes results/nao[-quick]/ with figures and results.md
  setup                     install the Debian packages the suite needs (apt)
  build                     setup, then build into .build/ (RL_BUILD_DIR overrides)
  exec <program> [args]     run a command inside the built workspace (devel/setup.bash)
  help                      this text
USAGE
}

cmd_setup() {
  local missing=() pkg
  for pkg in "${APT_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q 'install ok installed' ||
      missing+=("$pkg")
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return 0
  fi
  local sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { log "need root or sudo to install: ${missing[*]}"; exit 1; }
    sudo=(sudo)
  fi
  log "installing ${#missing[@]} missing packages: ${missing[*]}"
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends \
    "${missing[@]}"
}

cmd_build() {
  cmd_setup
  mkdir -p "$BUILD" "$DEVEL/lib/python3/dist-packages"
  # Keep catkin's and colcon's package crawlers out of the build folder.
  touch "$BUILD_ROOT/CATKIN_IGNORE" "$BUILD_ROOT/COLCON_IGNORE"
  if [ ! -f "$BUILD/CMakeCache.txt" ]; then
    log "configuring into $BUILD"
    cmake -S "$ROOT" -B "$BUILD" -DCATKIN_DEVEL_PREFIX="$DEVEL" \
      -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCATKIN_ENABLE_TESTING=ON >"$BUILD_ROOT/configure.log" 2>&1 ||
      { cat "$BUILD_ROOT/configure.log"; exit 1; }
  fi
  log "building with $JOBS jobs"
  cmake --build "$BUILD" -- -j"$JOBS"
}

source_workspace() {
  set +u
  # shellcheck disable=SC1091
  source "$DEVEL/setup.bash"
  set -u
}

cmd_test() {
  cmd_build
  source_workspace
  log "building tests"
  cmake --build "$BUILD" --target tests -- -j"$JOBS"
  rm -rf "$BUILD/test_results"
  log "running tests"
  # run_tests exits 0 even when tests fail; the verdict comes from the result files.
  cmake --build "$BUILD" --target run_tests -- -j1 >"$BUILD_ROOT/run_tests.log" 2>&1 || true
  run_tsan_tests "$BUILD/test_results/tsan" >>"$BUILD_ROOT/run_tests.log" 2>&1 || true
  run_asan_tests "$BUILD/test_results/asan" >>"$BUILD_ROOT/run_tests.log" 2>&1 || true
  /usr/bin/python3 "$ROOT/tools/test_summary.py" "$BUILD/test_results" ||
    { log "details: $BUILD_ROOT/run_tests.log"; return 1; }
}

# The multi-threaded tests again, built with ThreadSanitizer: any data race fails them.
TSAN_TESTS=(rl_agent_test_real_time_planner rl_agent_test_model_based_agent rl_agent_test_relabel_rewards)
run_tsan_tests() {
  local results=$1 tsan=$BUILD_ROOT/tsan
  mkdir -p "$results" "$tsan/devel/lib/python3/dist-packages"
  log "building the threaded tests with ThreadSanitizer (${TSAN_TESTS[*]})"
  # rl_agent and the packages it depends on (rl_agent needs no environment package).
  local packages="rl_common;rl_msgs;rl_agent"
  if ! grep -qx "CATKIN_WHITELIST_PACKAGES:STRING=$packages" "$tsan/build/CMakeCache.txt" \
    2>/dev/null; then
    cmake -S "$ROOT" -B "$tsan/build" -DCATKIN_DEVEL_PREFIX="$tsan/devel" \
      -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCATKIN_WHITELIST_PACKAGES="$packages" -DCATKIN_ENABLE_TESTING=ON \
      -DCMAKE_CXX_FLAGS="-fsanitize=thread" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" \
      -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=thread" >"$tsan/configure.log" 2>&1 ||
      { sanitizer_failure tsan "$results" build "configure failed; see .build/tsan/configure.log"; return 1; }
  fi
  cmake --build "$tsan/build" --target "${TSAN_TESTS[@]}" -- -j"$JOBS" ||
    { sanitizer_failure tsan "$results" build "the instrumented build failed; see .build/run_tests.log"; return 1; }
  local t rc xml
  for t in "${TSAN_TESTS[@]}"; do
    xml=$results/tsan-$t.xml
    rm -f "$xml"
    rc=0
    # The sourced workspace puts the uninstrumented libraries on LD_LIBRARY_PATH, which
    # overrides the binaries' RUNPATH: put the instrumented ones first.
    LD_LIBRARY_PATH="$tsan/devel/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
      TSAN_OPTIONS="halt_on_error=1 exitcode=66" "$tsan/devel/lib/rl_agent/$t" \
      --gtest_output="xml:$xml" || rc=$?
    # A race aborts the binary (no results) or fails it after passing tests: record it.
    if [ "$rc" -ne 0 ] && { [ ! -s "$xml" ] || grep -q 'failures="0"' "$xml"; }; then
      sanitizer_failure tsan "$results" "$t" \
        "ThreadSanitizer: exit status $rc (data race?); see .build/run_tests.log"
    fi
  done
}

# Every unit-test binary again, built with AddressSanitizer and UndefinedBehaviorSanitizer:
# a memory error, a leak or undefined behaviour fails it. The rostests (nodes under roscore)
# run only in the ordinary build, and so do the two science tests (60 and 40 trials of 1000
# steps: about 15 minutes under ASan, on code paths the agent's unit tests run as well).
ASAN_SKIP=(rl_experiment_test_curiosity_pays_off rl_texplore_tests_test_texplore_learning)
run_asan_tests() {
  local results=$1 asan=$BUILD_ROOT/asan
  mkdir -p "$results" "$asan/devel/lib/python3/dist-packages"
  log "building the unit tests with AddressSanitizer and UndefinedBehaviorSanitizer"
  local san="-fsanitize=address,undefined"
  if [ ! -f "$asan/build/CMakeCache.txt" ]; then
    cmake -S "$ROOT" -B "$asan/build" -DCATKIN_DEVEL_PREFIX="$asan/devel" \
      -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCATKIN_ENABLE_TESTING=ON \
      -DCMAKE_CXX_FLAGS="$san -fno-omit-frame-pointer -fno-sanitize-recover=undefined" \
      -DCMAKE_EXE_LINKER_FLAGS="$san" -DCMAKE_SHARED_LINKER_FLAGS="$san" \
      >"$asan/configure.log" 2>&1 ||
      { sanitizer_failure asan "$results" build "configure failed; see .build/asan/configure.log"; return 1; }
  fi
  # The gtest targets only (catkin_add_gtest: no nodes, no rostest binaries).
  local targets
  mapfile -t targets < <(cmake --build "$asan/build" --target help |
    sed -n 's/^\.\.\. _run_tests_.*_gtest_\([A-Za-z0-9_]*\)$/\1/p' |
    grep -vxF -f <(printf '%s\n' "${ASAN_SKIP[@]}"))
  [ ${#targets[@]} -gt 0 ] || { sanitizer_failure asan "$results" build "no gtest targets found"; return 1; }
  cmake --build "$asan/build" --target "${targets[@]}" -- -j"$JOBS" ||
    { sanitizer_failure asan "$results" build "the instrumented build failed; see .build/run_tests.log"; return 1; }
  local t name rc xml
  for name in "${targets[@]}"; do
    t=$(ls "$asan"/devel/lib/*/"$name" 2>/dev/null | head -n1)
    [ -n "$t" ] || { sanitizer_failure asan "$results" "$name" "no binary built"; continue; }
    xml=$results/asan-$name.xml
    rm -f "$xml"
    rc=0
    # As for TSan: the instrumented libraries first. The binaries run from their package's
    # build folder, as catkin's run_tests runs them.
    (cd "$asan/build/$(basename "$(dirname "$t")")" 2>/dev/null || cd "$asan/build"
      LD_LIBRARY_PATH="$asan/devel/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
        ASAN_OPTIONS="detect_leaks=1 exitcode=67" \
        UBSAN_OPTIONS="print_stacktrace=1 halt_on_error=1" \
        "$t" --gtest_output="xml:$xml") || rc=$?
    if [ "$rc" -ne 0 ] && { [ ! -s "$xml" ] || grep -q 'failures="0"' "$xml"; }; then
      sanitizer_failure asan "$results" "$name" "AddressSanitizer/UndefinedBehaviorSanitizer: exit status $rc; see .build/run_tests.log"
    fi
  done
}

# sanitizer_failure KIND RESULTS NAME MESSAGE: a failing result file KIND-NAME.xml, which the
# summary counts, so a sanitizer's abort (no results of its own) cannot pass silently.
sanitizer_failure() {
  cat >"$2/$1-$3.xml" <<XML
<?xml version="1.0"?>
<testsuite name="$1" tests="1" failures="1"><testcase classname="$1" name="$3">
<failure message="$4"/>
</testcase></testsuite>
XML
}

cmd_exec() {
  source_workspace
  exec "$@"
}

cmd_reproduce() {
  cmd_build
  source_workspace
  if [ "${1:-}" = nao ]; then
    shift
    RL_EXPERIMENT=${RL_EXPERIMENT:-$DEVEL/lib/rl_experiment/experiment} \
      exec /usr/bin/python3 "$ROOT/nao_interface/scripts/reproduce_nao.py" "$@"
  fi
  RL_EXPERIMENT=${RL_EXPERIMENT:-$DEVEL/lib/rl_experiment/experiment} \
    exec /usr/bin/python3 "$ROOT/rl_experiment/scripts/reproduce.py" "$@"
}

cmd_run() {
  cmd_build
  source_workspace
  exec "$ROOT/tools/run_default_experiment.sh" "$@"
}

main() {
  local cmd=${1:-help}
  shift || true
  case "$cmd" in
    setup) cmd_setup ;;
    build) cmd_build ;;
    test) cmd_test ;;
    run) cmd_run "$@" ;;
    reproduce) cmd_reproduce "$@" ;;
    exec) cmd_exec "$@" ;;
    help | -h | --help) usage ;;
    *) usage >&2; log "unknown command '$cmd'; valid: run, reproduce, test, setup, build, exec, help"; exit 2 ;;
  esac
}

main "$@"
