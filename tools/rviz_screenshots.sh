#!/usr/bin/env bash
# The README's rviz screenshots, taken from real runs under a virtual X server:
#   docs/images/lightworld_rviz.png  lightworld_experiment.launch rviz:=true
#   docs/images/nao_arm_rviz.png     nao_arm_exploration.launch rviz:=true (simulated arm)
# Needs xvfb and imagemagick (docs only, not in the suite's set: `apt-get install xvfb
# imagemagick`) and a built workspace with rviz (./rl test or ./rl run installs and builds it).
# Usage: tools/rviz_screenshots.sh [WAIT_SECONDS] (default 25: how long each run goes before
# the shot, so the arm has moved and the grid has an agent trail).
set -euo pipefail
export PATH=/usr/sbin:/usr/bin:/sbin:/bin:$PATH
here="$(cd "$(dirname "$0")/.." && pwd)"
wait_s="${1:-25}"
for tool in xvfb-run import roslaunch rviz; do
  command -v "$tool" >/dev/null || { echo "rviz_screenshots: $tool not found" >&2; exit 2; }
done
[[ -f "$here/.build/devel/setup.bash" ]] || {
  echo "rviz_screenshots: no built workspace in $here/.build (run ./rl test first)" >&2; exit 2; }
# shellcheck disable=SC1091
set +u; source "$here/.build/devel/setup.bash"; set -u
mkdir -p "$here/docs/images"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

# One shot: a fresh roscore and launch inside one Xvfb screen; the shot is the whole screen,
# where rviz opens at its config's size.
shot() {
  local png="$1"; shift
  xvfb-run -a -s "-screen 0 1280x800x24" bash -c '
    set -u
    png="$1" wait_s="$2"; shift 2
    export ROS_MASTER_URI=http://localhost:11411
    roscore -p 11411 >/dev/null 2>&1 & core=$!
    sleep 3
    roslaunch "$@" output:=log >/dev/null 2>&1 & run=$!
    sleep "$wait_s"
    import -window root "$png"
    kill -INT $run; wait $run 2>/dev/null
    kill -INT $core; wait $core 2>/dev/null
    true' _ "$png" "$wait_s" "$@"
  echo "wrote $png"
}

shot "$here/docs/images/lightworld_rviz.png" rl_texplore_launch lightworld_experiment.launch \
  rviz:=true steps:=2000 out:="$out/lightworld" required:=false
shot "$here/docs/images/nao_arm_rviz.png" rl_texplore_launch nao_arm_exploration.launch \
  rviz:=true steps:=2000 out:="$out/nao" required:=false audio:=false
