#!/usr/bin/env bash
# The thesis's scene 9 and 10 tables (IndirectQuality 3, 4, 5, 10; area-light versions) redone with Trazo:
# convergence_bench with the fixed-grid estimator too for each, keeping the summary lines (the CSVs and the
# PNG plots go to OUT_DIR).
# Usage: bench/convergence/thesis_tables.sh [BUILD_DIR] [SIZE] [REFERENCE_PASSES] [MAX_PASSES] [OUT_DIR]
#        (defaults: build 128 2048 1024 thesis_tables)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
size=${2:-128}
reference=${3:-2048}
maxPasses=${4:-1024}
out=${5:-thesis_tables}
mkdir -p "$out"
variant=""
trap 'rm -f "$variant"' EXIT
for scene in scene9_indirect scene10_bunny_indirect_area; do
  for q in 3 4 5 10; do
    # Beside the original, so the scene's relative asset paths still resolve; removed afterwards.
    variant="scenes/thesis_${scene}_q$q.scene"
    sed -E "s/^([[:space:]]*IndirectQuality)[[:space:]]+[0-9]+/\1 $q/" "scenes/$scene.scene" > "$variant"
    echo "== $scene, IndirectQuality $q (${size}x$size) =="
    "$build/bench/convergence/convergence_bench" "$variant" --width "$size" --height "$size" --fixed-grid-too \
      --reference-passes "$reference" --max-passes "$maxPasses" --out-dir "$out" |
      grep -E "^# |^thesis quality|^time to reach|^log-log"
    rm -f "$variant"
  done
done
