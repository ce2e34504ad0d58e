#!/usr/bin/env bash
# The default experiment behind `./rl run`: TEXPLORE-VANIR (--agent texplore --v 1 --n 3) on
# LightWorld. Until that agent lands (issue 4), this runs what exists and says so.
set -euo pipefail
if rosrun rl_experiment experiment --agent texplore --env lightworld --nepisodes 0 \
  >/dev/null 2>&1; then
  exec rosrun rl_experiment experiment --agent texplore --v 1 --n 3 --env lightworld "$@"
fi
echo "[rl run] The TEXPLORE-VANIR agent has not landed yet (issue #4). Running what exists:"
echo "[rl run] Q-learning on LightWorld for 1000 steps (rosrun rl_experiment experiment)."
rosrun rl_experiment experiment --agent qlearner --env lightworld --nepisodes 1000 "$@" \
  2> >(awk '/^-?[0-9.e+-]+$/ {s += $1; n++; next} {print > "/dev/stderr"}
            END {if (n) printf "[rl run] stderr stream: %d per-step rewards, sum %g\n", n, s}')
