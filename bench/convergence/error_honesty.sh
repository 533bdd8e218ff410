#!/usr/bin/env bash
# Every seed scene's default render beside its true error: the render's own estimate (the error probe,
# `estimated_rel_error`) against the error measured with image_error from a reference of REF_FACTOR times
# the passes and another seed (the reference's own estimate removed in quadrature), as root mean squares
# over SEEDS renders. Writes OUT/error_honesty.md and .csv; the ratio estimate/true should lie in [2/3, 3/2].
# Usage: bench/convergence/error_honesty.sh [BUILD] [THREADS] [OUT]   (SIZE, default 256; SEEDS, default 4;
#        REF_FACTOR, default 16)
set -euo pipefail
cd "$(dirname "$0")/../.."
source bench/peers/common.sh
run_arguments error_honesty "$@"
size=${SIZE:-256}
seeds=${SEEDS:-4}
refFactor=${REF_FACTOR:-16}
csv="$out/error_honesty.csv"
echo "scene,passes,estimated,true,ratio,reference_estimate" > "$csv"

render() {  # render SCENE SEED OUT [trazo options]: the stats JSON beside OUT
  local scene=$1 seed=$2 image=$3
  shift 3
  "$trazo" --render "$scene" --width "$size" --height "$size" --threads "$threads" --seed "$seed" --quiet \
    -o "$image" --stats "${image%.pfm}.json" "$@" 2>/dev/null
}

for scene in scenes/*.scene; do
  name=$(basename "$scene" .scene)
  render "$scene" 1 "$out/$name.pfm" || { echo "$name: trazo failed" >&2; continue; }
  passes=$(json_field "$out/$name.json" spp)
  render "$scene" 1000 "$out/${name}_ref.pfm" --spp $((refFactor * passes))
  refErr=$(json_field "$out/${name}_ref.json" estimated_rel_error)
  est2=0 true2=0
  for seed in $(seq 1 "$seeds"); do
    render "$scene" "$seed" "$out/$name.pfm"
    e=$(json_field "$out/$name.json" estimated_rel_error)
    t=$(field "$("$imageError" "$out/$name.pfm" "$out/${name}_ref.pfm")" rel_error)
    est2=$(awk -v s="$est2" -v e="$e" -v n="$seeds" 'BEGIN { printf "%.10g", s + e * e / n }')
    true2=$(awk -v s="$true2" -v t="$t" -v n="$seeds" 'BEGIN { printf "%.10g", s + t * t / n }')
  done
  awk -v n="$name" -v p="$passes" -v e2="$est2" -v t2="$true2" -v r="$refErr" 'BEGIN {
    e = sqrt(e2); t2 -= r * r; t = sqrt(t2 > 0 ? t2 : 0)
    printf "%s,%d,%.5f,%.5f,%s,%.5f\n", n, p, e, t, (t > 1e-7 ? sprintf("%.3f", e / t) : "noiseless"), r }' >> "$csv"
  tail -n 1 "$csv"
done

{
  echo "Each seed scene's default render, ${size}², $threads threads, seeds 1–$seeds; reference: ${refFactor}× the"
  echo "passes, seed 1000. Errors as root mean squares over the seeds (relative, as \`compareToReference\`)."
  echo
  echo "| scene | passes | estimated | true | estimated / true |"
  echo "|---|---|---|---|---|"
  tail -n +2 "$csv" | awk -F, '{ printf "| %s | %d | %.3f%% | %.3f%% | %s |\n", $1, $2, 100 * $3, 100 * $4, $5 }'
} > "$out/error_honesty.md"
cat "$out/error_honesty.md"
