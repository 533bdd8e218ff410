#!/usr/bin/env bash
# The measurement behind the headless block rule (render/strata_plan.cpp headlessBlocks): one scene rendered
# with several --blocks choices, each with seeds 1 and 2, and each choice's Monte Carlo efficiency
# 1 / (time × two-seed variance) relative to the first choice's.
# Usage: bench/peers/blocks_sweep.sh SCENE CHOICE...    CHOICE: fixed (--fixed-grid), auto, or a --blocks value
#   e.g. SIZE=128 THREADS=1 bench/peers/blocks_sweep.sh scenes/scene9_indirect.scene fixed 1 auto 1,whole,whole,1
# Environment: BUILD (default build), THREADS (2), OUT (blocks_sweep: the images), SIZE (512).
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
source "$repo/bench/peers/common.sh"
[ $# -ge 2 ] || { sed -n '2,7p' "$0" >&2; exit 2; }
scene=$1
shift
run_arguments blocks_sweep "${BUILD:-build}" "${THREADS:-2}" "${OUT:-}"
[ -x "$trazo" ] && [ -x "$imageError" ] || { echo "build trazo and image_error first" >&2; exit 2; }

echo "$scene at ${size}², $threads threads: efficiency 1/(time × two-seed variance), relative to $1"
echo
echo "| blocks | passes | render s | rel. deviation of one image | efficiency |"
echo "|---|---|---|---|---|"
first=""
for choice in "$@"; do
  flags=(--blocks "$choice"); [ "$choice" = fixed ] && flags=(--fixed-grid)
  prefix="$out/$(basename "$scene" .scene)_${choice//,/_}"
  measured=$(two_seeds "$prefix" --render "$scene" --threads "$threads" --width "$size" --height "$size" \
    "${flags[@]}")  # a failed render stops the script
  read -r t v sd <<<"$measured"
  efficiency=$(awk -v t="$t" -v v="$v" 'BEGIN { printf "%.6g", (t > 0 && v > 0) ? 1 / (t * v) : 0 }')
  [ -n "$first" ] || first=$efficiency
  awk -v c="$choice" -v p="$(json_field "${prefix}_1.json" spp)" -v t="$t" -v sd="$sd" -v e="$efficiency" \
    -v f="$first" 'BEGIN { ratio = f > 0 ? sprintf("%.2f", e / f) : "no noise"
                           printf "| %s | %s | %.3f | %.3f%% | %s |\n", c, p, t, 100 * sd, ratio }'
done
