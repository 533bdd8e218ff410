#!/usr/bin/env bash
# Seed scene 1 (area and point light) rendered in one run, on the same threads, by Trazo (default and
# --fixed-grid), POV-Ray 3.7 and the plain Embree 3 renderer (embree_render) in both its forms, single rays
# (--mode single) and packets + shadow streams (--mode stream); each image's relative error against that
# renderer's own converged reference is printed beside its time, then Trazo's time over each Embree time.
# Usage: bench/peers/run_peers.sh [BUILD_DIR] [THREADS] [OUT_DIR]      (defaults: build 2 peers_out)
# Environment: SIZE (image side, default 512 as the scenes), RUNS (timed runs, median taken, default 3),
#   TRAZO_REF_PASSES (fixed-grid passes of Trazo's reference, default 16), POV_REF_CELLS (grid side of
#   POV-Ray's reference light, default 40), EMBREE_REF_SAMPLES (points per cell of Embree's reference, 16).
#
# Columns: render_s = the renderer's own render time (Trazo: stats JSON "render_s"; POV-Ray: its "Trace
# Time"; Embree: its printed "render"), each the median of RUNS runs; process_s = the whole process (scene
# reading, build, render, image writing; POV-Ray's start-up), median wall time from `date +%s.%N`;
# rays = rays traced as each tool counts them (POV-Ray: camera rays + "Shadow Ray Tests"); rel_error = the
# first run's image against the renderer's own reference (RMSE / mean of the reference, image_error).
# References: Trazo --fixed-grid --spp TRAZO_REF_PASSES --seed 999 (each pass evaluates every light cell, so
# 16 passes are 1600 jittered points per pixel, 16 of the default's cycles, at a fraction of their cost);
# POV-Ray the same light split into POV_REF_CELLS² jittered cells (its random table is fixed, so another
# seed is not available: a denser grid is its converged image); Embree --samples-per-cell 16 --seed 999 in
# the mode measured. The two Embree modes draw the same light points, so their seed-1 images are compared
# too (image_error stream vs single, and with --packet 1, camera rays one at a time, which must give 0).
# The point-light images have no sampling noise at Antialiasing 1, so their error is ~0 by construction.
set -euo pipefail
repo=$(cd "$(dirname "$0")/../.." && pwd)
source "$repo/bench/peers/common.sh"
run_arguments peers_out "$@"
runs=${RUNS:-3}
trazoRef=${TRAZO_REF_PASSES:-16}
povRefCells=${POV_REF_CELLS:-40}
embreeRef=${EMBREE_REF_SAMPLES:-16}

embree="$build/bench/peers/embree_render"
[ -x "$trazo" ] && [ -x "$imageError" ] || { echo "build trazo and image_error first" >&2; exit 2; }
havePov=0; command -v povray >/dev/null && havePov=1
haveEmbree=0; [ -x "$embree" ] && haveEmbree=1
[ $havePov = 1 ] || echo "povray not found: its rows are skipped (apt-get install povray)" >&2
[ $haveEmbree = 1 ] || echo "$embree not built (Embree 3 missing): its rows are skipped" >&2

csv="$out/peers.csv"
echo "renderer,light,threads,size,render_s,process_s,rays,rel_error" > "$csv"

# One timed process: runs "$@", leaves its wall time in $wall.
timed() {
  local t0 t1
  t0=$(now)
  "$@"
  t1=$(now)
  wall=$(elapsed "$t0" "$t1")
}

trazoRun() {  # trazoRun SCENE OUT.pfm STATS.json [flags...]
  local scene=$1 image=$2 stats=$3
  shift 3
  timed "$trazo" --render "$scene" --threads "$threads" --width "$size" --height "$size" --quiet \
    -o "$image" --stats "$stats" "$@" >/dev/null 2>&1
}

povRun() {  # povRun POVFILE OUT.exr LOG [options...]: linear OpenEXR output, no antialiasing
  local pov=$1 image=$2 log=$3
  shift 3
  timed povray +I"$pov" +L"$repo/bench/peers" +W"$size" +H"$size" -A +WT"$threads" +FE -D -V +O"$image" "$@" \
    >"$log" 2>&1
}

povTraceSeconds() { sed -n 's/.*Trace Time:.*(\([0-9.]*\) seconds).*/\1/p' "$1" | head -n 1; }
povRays() {
  awk '/^Rays:/ { r += $2 } /^Shadow Ray Tests:/ { r += $4 } END { print r }' "$1"
}

row() {  # row RENDERER LIGHT RENDER_TIMES PROCESS_TIMES RAYS REL_ERROR
  echo "$1,$2,$threads,$size,$(median $3),$(median $4),$5,$6" >> "$csv"
}

# embreeRows NAME TAG LIGHT SCENE [FLAGS...]: embree_render FLAGS, its reference (TAG_LIGHT_ref.pfm) and RUNS
# timed runs (TAG_LIGHT.pfm, .log), one row.
embreeRows() {
  local name=$1 tag=$2 light=$3 scene=$4 i err
  shift 4
  local common=("$scene" --threads "$threads" --width "$size" --height "$size" "$@")
  timed "$embree" "${common[@]}" --seed 999 --samples-per-cell "$embreeRef" -o "$out/${tag}_${light}_ref.pfm" >/dev/null
  local r=() p=()
  for i in $(seq "$runs"); do
    timed "$embree" "${common[@]}" --seed 1 -o "$out/${tag}_$light.pfm" > "$out/${tag}_$light.log"
    r+=("$(sed -n 's/.*render \([0-9.]*\) s.*/\1/p' "$out/${tag}_$light.log")"); p+=("$wall")
    [ "$i" = 1 ] && err=$(field "$("$imageError" "$out/${tag}_$light.pfm" "$out/${tag}_${light}_ref.pfm")" rel_error)
  done
  row "$name" "$light" "${r[*]}" "${p[*]}" "$(sed -n 's/.* \([0-9]*\) rays.*/\1/p' "$out/${tag}_$light.log")" "$err"
}

echo "light,image,rel_error_vs_embree_single" > "$out/embree_modes.csv"
for light in area point; do
  scene="$repo/scenes/scene1_$light.scene"
  pov="$repo/bench/peers/scene1_$light.pov"
  echo "== scene1_$light: references" >&2
  trazoRun "$scene" "$out/trazo_${light}_ref.pfm" "$out/trazo_${light}_ref.json" --fixed-grid --spp "$trazoRef" --seed 999
  if [ $havePov = 1 ]; then
    refDecl=(); [ $light = area ] && refDecl=(Declare=CELLS="$povRefCells")
    povRun "$pov" "$out/pov_${light}_ref.exr" "$out/pov_${light}_ref.log" "${refDecl[@]}"
  fi

  for mode in default fixed-grid; do
    flags=(); [ $mode = fixed-grid ] && flags=(--fixed-grid)
    r=(); p=()
    for i in $(seq "$runs"); do
      trazoRun "$scene" "$out/trazo_${light}_$mode.pfm" "$out/trazo_${light}_$mode.json" --seed 1 "${flags[@]}"
      r+=("$(json_field "$out/trazo_${light}_$mode.json" render_s)"); p+=("$wall")
      [ "$i" = 1 ] && err=$(field "$("$imageError" "$out/trazo_${light}_$mode.pfm" "$out/trazo_${light}_ref.pfm")" rel_error)
    done
    row "trazo $mode" "$light" "${r[*]}" "${p[*]}" "$(json_field "$out/trazo_${light}_$mode.json" rays)" "$err"
  done

  if [ $havePov = 1 ]; then
    r=(); p=()
    for i in $(seq "$runs"); do
      povRun "$pov" "$out/pov_$light.exr" "$out/pov_$light.log"
      r+=("$(povTraceSeconds "$out/pov_$light.log")"); p+=("$wall")
      [ "$i" = 1 ] && err=$(field "$("$imageError" "$out/pov_$light.exr" "$out/pov_${light}_ref.exr")" rel_error)
    done
    row "povray 3.7" "$light" "${r[*]}" "${p[*]}" "$(povRays "$out/pov_$light.log")" "$err"
  fi

  if [ $haveEmbree = 1 ]; then
    embreeRows "embree 3 single" embree "$light" "$scene" --mode single
    embreeRows "embree 3 stream" embree_stream "$light" "$scene" --mode stream
    "$embree" "$scene" --threads "$threads" --width "$size" --height "$size" --seed 1 --mode stream --packet 1 \
      -o "$out/embree_stream_packet1_$light.pfm" >/dev/null
    for image in embree_stream embree_stream_packet1; do
      echo "$light,$image,$(field "$("$imageError" "$out/${image}_$light.pfm" "$out/embree_$light.pfm")" rel_error)"
    done >> "$out/embree_modes.csv"
  fi
done

# The Markdown table from the CSV.
{
  echo "Seed scene 1 at ${size}², $threads threads, median of $runs runs ($(date -u +%Y-%m-%d), $(uname -n))"
  echo
  echo "| renderer | light | render s | process s | rays | rel. error vs own reference |"
  echo "|---|---|---|---|---|---|"
  tail -n +2 "$csv" | awk -F, '{ printf "| %s | %s | %.3f | %.3f | %s | %.2f%% |\n", $1, $2, $5, $6, ($7 == "" ? "?" : sprintf("%.1f M", $7 / 1e6)), 100 * $8 }'
  if [ $haveEmbree = 1 ]; then
    echo
    echo "Trazo's render s over each Embree form's, this run (above 1: Trazo slower)"
    echo
    echo "| light | trazo | trazo s | ÷ embree single | ÷ embree stream |"
    echo "|---|---|---|---|---|"
    awk -F, 'NR > 1 { t[$1 "|" $2] = $5 } END {
      split("area point", lights, " "); split("default fixed-grid", modes, " ")
      for (l = 1; l <= 2; ++l) for (m = 1; m <= 2; ++m) {
        tr = t["trazo " modes[m] "|" lights[l]]; s1 = t["embree 3 single|" lights[l]]; st = t["embree 3 stream|" lights[l]]
        printf "| %s | %s | %.3f | %.2f | %.2f |\n", lights[l], modes[m], tr, tr / s1, tr / st
      } }' "$csv"
    echo
    echo "Embree stream vs single, seed 1 (image_error; --packet 1 traces the camera rays one at a time):"
    tail -n +2 "$out/embree_modes.csv" | awk -F, '{ printf "%s %s: rel. error %.3g%s\n", $1, ($2 == "embree_stream" ? "stream" : "stream --packet 1"), $3, ($3 == 0 ? " (identical)" : "") }'
  fi
} | tee "$out/peers.md"
