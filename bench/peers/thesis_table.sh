#!/usr/bin/env bash
# The thesis's table redone: every seed scene at its file's own settings (the rows of results.csv that do
# not say "instead of"), rendered by Trazo's default and by --fixed-grid, each with seeds 1 and 2, beside
# the thesis's GTX 560 time; Monte Carlo efficiency 1 / (time × variance), the variance from the two seeds.
# Usage: bench/peers/thesis_table.sh [BUILD_DIR] [THREADS] [OUT_DIR]      (defaults: build 2 thesis_table)
# Environment: SIZE (image side, default 512 as the thesis), BACKEND (cpu, default, or cuda/auto),
#   TRAZO_SEED_DIR (folder of the thesis's results.csv; default ../shared/seed beside the repository, else
#   the copy bench/peers/thesis_results.csv, so a clone alone works).
# Writes OUT_DIR/thesis_table.md, .csv and .png (bars: GTX 560, Trazo default, Trazo fixed grid; log scale).
#
# Times are the stats JSON "render_s" (render phase only, as the thesis's exec_s), the mean of the two
# seeds. Variance = mean over pixels and channels of (A − B)² / 2 (image_error --variance); scenes with no
# sampling noise (point light, Antialiasing 1, no indirect light) have variance 0 and no efficiency.
# With SIZE < 512 the times are also projected to 512² by the pixel count (the "@512²" columns) for the
# comparison with the GTX 560; only SIZE=512 measures it.
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
source "$repo/bench/peers/common.sh"
run_arguments thesis_table "$@"
backend=${BACKEND:-cpu}
seedCsv="${TRAZO_SEED_DIR:-$repo/../shared/seed}/results.csv"
[ -f "$seedCsv" ] || seedCsv="$repo/bench/peers/thesis_results.csv"
barChart="$build/bench/peers/bar_chart"
[ -x "$trazo" ] && [ -x "$imageError" ] && [ -x "$barChart" ] || { echo "build trazo, image_error, bar_chart" >&2; exit 2; }
work="$out/images"
mkdir -p "$work"

scale=$(awk -v s="$size" 'BEGIN { printf "%.6g", 512 * 512 / (s * s) }')  # time at SIZE² → at 512²
csv="$out/thesis_table.csv"
echo "scene_file,variant,gtx560_exec_s,size,backend,default_s,default_passes,default_mrays_s,default_est_rel_error,default_variance,fixed_s,fixed_variance,efficiency_ratio_default_over_fixed,default_s_at_512,fixed_s_at_512,speed_vs_gtx560" > "$csv"
chart="$out/thesis_table_chart.csv"
echo "scene,GTX 560,Trazo default,Trazo fixed grid" > "$chart"

# Rows: scene file, variant, GTX 560 exec_s (fields 9, 2, 7; the file has no quoted commas).
awk -F, 'NR > 1 && $9 != "" && $11 !~ /instead of/ { print $9 "\t" $2 "\t" $7 }' "$seedCsv" |
while IFS=$'\t' read -r sceneFile variant gtx; do
  name=${sceneFile%.scene}
  echo "== $sceneFile ($variant)" >&2
  for mode in default fixed; do
    flags=(); [ $mode = fixed ] && flags=(--fixed-grid)
    measured=$(two_seeds "$work/${name}_$mode" --render "$repo/scenes/$sceneFile" --backend "$backend" \
      --threads "$threads" --width "$size" --height "$size" "${flags[@]}")  # a failed render stops the script
    read -r t v _ <<<"$measured"
    eval "${mode}_t=\$t ${mode}_v=\$v"
  done
  j="$work/${name}_default_1.json"  # passes, Mrays/s and the estimate: the default render, seed 1
  passes=$(json_field "$j" spp) mrays=$(json_field "$j" mrays_per_s) estErr=$(json_field "$j" estimated_rel_error)
  awk -v f="$sceneFile" -v var="$variant" -v g="$gtx" -v size="$size" -v be="$backend" -v dt="$default_t" \
    -v p="$passes" -v m="$mrays" -v e="$estErr" -v dv="$default_v" -v ft="$fixed_t" -v fv="$fixed_v" \
    -v sc="$scale" 'BEGIN {
      ratio = (dv > 0 && fv > 0) ? sprintf("%.4g", (ft * fv) / (dt * dv)) : "";
      printf "%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%.4f,%.4f,%.4g\n", f, var, g, size, be, dt, p, m, e, dv, ft, fv,
        ratio, dt * sc, ft * sc, g / (dt * sc) }' >> "$csv"
  awk -v f="$name" -v g="$gtx" -v dt="$default_t" -v ft="$fixed_t" -v sc="$scale" \
    'BEGIN { printf "%s,%s,%.4f,%.4f\n", f, g, dt * sc, ft * sc }' >> "$chart"
done

# Markdown, the count, the chart.
{
  echo "The thesis's seed scenes at their own settings: Trazo ($backend, $threads threads, ${size}²) beside the GTX 560"
  echo "($(date -u +%Y-%m-%d), $(uname -n)). Times: render phase, mean of seeds 1 and 2. Efficiency ratio ="
  echo "(1 / (t·Var)) default over fixed grid, Var from the two seeds (> 1: the default is more efficient)."
  [ "$size" = 512 ] || echo "Rendered at ${size}²: the @512² times and the speed are projected by the pixel count."
  echo
  echo "| # | scene file | variant | GTX 560 s | Trazo default s | passes | Mrays/s | est. rel error | fixed-grid s | efficiency default/fixed | speed vs GTX 560 |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
  tail -n +2 "$csv" | awk -F, -v proj="$([ "$size" = 512 ] && echo 0 || echo 1)" '{
      d = proj ? sprintf("%.3f (@512² %.2f)", $6, $14) : sprintf("%.3f", $6);
      fx = proj ? sprintf("%.3f (@512² %.2f)", $11, $15) : sprintf("%.3f", $11);
      est = ($9 ~ /^[0-9.eE+-]+$/) ? sprintf("%.2f%%", 100 * $9) : "n/a";  # no estimate from one pass
      printf "| %d | %s | %s | %s | %s | %s | %.2f | %s | %s | %s | %.2f× |\n", NR, $1, $2, $3, d, $7, $8,
        est, fx, ($13 == "" ? "no noise" : sprintf("%.2f", $13)), $16 }'
  echo
  tail -n +2 "$csv" | awk -F, '{ n++; if ($14 <= $3) k++ } END {
      printf "Trazo default at or under the GTX 560 time on %d of %d scenes.\n", k, n }'
} | tee "$out/thesis_table.md"
title="Thesis scenes at 512x512: render seconds"
[ "$size" = 512 ] || title="Thesis scenes: render seconds (Trazo at ${size}x$size, projected to 512x512)"
"$barChart" "$chart" "$out/thesis_table.png" --title "$title" \
  --ylabel "seconds" --xlabel "row of thesis_table.md"
echo "wrote $out/thesis_table.md, thesis_table.csv, thesis_table.png" >&2
