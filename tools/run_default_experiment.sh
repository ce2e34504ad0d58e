#!/usr/bin/env bash
# The default experiment behind `./rl run`: TEXPLORE-VANIR (--agent texplore --v 1 --n 3) on
# LightWorld, the paper's protocol in small: 4 trials (2 at a time) of the paper's 1000
# exploration steps without external reward, then 1000 task steps on the learned model; the
# model's accuracy every 25 steps. UCT plans 100 rollouts per step with λ = 1 (with the
# original's 0.1 the agent fixates on self-loops: README, "Known limits"). Logs and figures go
# to a new folder under results/.
# Extra arguments go to the runner, e.g. `./rl run --trials 8 --rollouts 200`.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
OUT=${RL_RUN_OUT:-$ROOT/results/run-$(date +%Y%m%d-%H%M%S)}
EXPERIMENT=${RL_EXPERIMENT:-$(catkin_find --first-only rl_experiment experiment)}
JOBS=${RL_JOBS:-$(nproc)}

echo "[rl run] TEXPLORE-VANIR on LightWorld: 4 trials x (1000 exploration + 1000 task steps)"
echo "[rl run] logs: $OUT"
"$EXPERIMENT" --agent texplore --v 1 --n 3 --rollouts 100 --lambda 1 --env lightworld \
  --explore-steps 1000 --task-steps 1000 --eval-every 25 --eval-samples 2000 \
  --trials 4 --jobs "$JOBS" --seed 1 --label texplore-vanir --out "$OUT" "$@"
/usr/bin/python3 "$ROOT/rl_experiment/scripts/plot_results.py" --out "$OUT/figures" \
  --title "LightWorld, TEXPLORE-VANIR" "$OUT"
echo "[rl run] figures: $OUT/figures/{reward,accuracy,press}.{png,pdf}; table: $OUT/figures/results.md"
