#!/usr/bin/env bash
# The Cornell box (scenes/cornell_box.scene, SPEC §7 path mode) in Trazo and in Blender 3.4's Cycles
# (bench/peers/cycles/cornell_cycles.py), at 64² and 256² on THREADS threads: a converged reference from
# each renderer (two seeds each, averaged), their agreement, then both renderers at several sample counts
# with render time, process time, relative MSE against the reference and efficiency 1/(relMSE × time).
#
#   bench/peers/cornell_compare.sh [BUILD=build] [THREADS=2] [OUT=cornell_out]
#   QUICK=1 bench/peers/cornell_compare.sh            # about 2 minutes: smaller references, fewer runs
#
# Needs `blender` (bench/peers/cycles/install.sh installs Debian's 3.4.1) and the targets trazo and
# image_error (cmake --build BUILD --target trazo image_error). Writes OUT/cornell.md, OUT/cornell.csv,
# OUT/*.png (sRGB, side by side: Trazo left, Cycles right), the images (.pfm) and the logs.
# Environment: SIZES ["64 256"], SPP_<size> (test sample counts), RUNS_<size> (seeds per count),
# REF_SPP_<size> (each reference's samples, rendered as two seeds of half), BOUNCES [64], TRAZO, BLENDER,
# IMAGE_ERROR, SCENE.
#
# relMSE = mean over pixels and channels of (x − r)²/(r² + 0.01), r = Cycles' reference, leaving out the 48
# (64²) / 444 (256²) pixels whose square touches the light (pfm_tool.py lightmask): a light pixel is
# 18.387 in both, and the pixels that the light's edge crosses are a coverage estimate, not light transport.
# Render s is each tool's own time for the sampling: Trazo's stats `render_s` (after parsing and the BVH);
# Cycles' time from its "Sample 0/N" report to the end of the render (after scene sync, shaders, BVH and
# lookup tables: about 0.06–0.25 s here, listed as `cycles setup s`). Process s is the whole process
# (Blender's start-up is ~1–2 s of it). Efficiency ε = 1/(mean relMSE over the runs × least render s over
# the runs): the VM is shared, and the least time is the one least disturbed (the CSV keeps every run).
set -euo pipefail

BUILD=${1:-build}
THREADS=${2:-2}
OUT=${3:-cornell_out}
HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../.." && pwd)
TRAZO=${TRAZO:-$BUILD/app/trazo}
IMAGE_ERROR=${IMAGE_ERROR:-$BUILD/bench/peers/image_error}
BLENDER=${BLENDER:-blender}
SCENE=${SCENE:-$ROOT/scenes/cornell_box.scene}
BOUNCES=${BOUNCES:-64}
CYCLES_PY=$HERE/cycles/cornell_cycles.py
PFM=(python3 "$HERE/cycles/pfm_tool.py")
SIZES=${SIZES:-"64 256"}
if [ "${QUICK:-0}" = 1 ]; then
  : "${SPP_64:=16 64}" "${RUNS_64:=1}" "${REF_SPP_64:=1024}"
  : "${SPP_256:=4 16}" "${RUNS_256:=1}" "${REF_SPP_256:=256}"
else
  : "${SPP_64:=16 64 256}" "${RUNS_64:=3}" "${REF_SPP_64:=4096}"
  : "${SPP_256:=4 16 64}" "${RUNS_256:=2}" "${REF_SPP_256:=1024}"
fi

for tool in "$TRAZO" "$IMAGE_ERROR"; do
  [ -x "$tool" ] || { echo "cornell_compare: $tool missing: cmake --build $BUILD --target trazo image_error" >&2; exit 2; }
done
command -v "$BLENDER" >/dev/null || { echo "cornell_compare: no blender: bench/peers/cycles/install.sh" >&2; exit 2; }
mkdir -p "$OUT/img" "$OUT/log"
OUT=$(cd "$OUT" && pwd)

# The scene with absolute mesh paths and this run's bounce limit.
sed -e "s#Source \"cornell_box/#Source \"$(dirname "$SCENE")/cornell_box/#" \
    -e "s#^\( *\)MaxBounces .*#\1MaxBounces $BOUNCES#" "$SCENE" > "$OUT/cornell_box.scene"
grep -q "^ *Integrator path" "$OUT/cornell_box.scene" ||
  echo "cornell_compare: warning: $SCENE does not say Integrator path" >&2

now() { date +%s.%N; }
# trazo NAME SIZE SPP SEED -> "render_s process_s"
trazo() {
  local name=$1 size=$2 spp=$3 seed=$4 t0 t1
  t0=$(now)
  "$TRAZO" --render "$OUT/cornell_box.scene" -o "$OUT/img/$name.pfm" --width "$size" --height "$size" \
    --spp "$spp" --seed "$seed" --threads "$THREADS" --stats "$OUT/log/$name.json" --quiet \
    > "$OUT/log/$name.log" 2>&1 || { cat "$OUT/log/$name.log" >&2; exit 1; }
  t1=$(now)
  local render
  render=$(sed -n 's/.*"render_s": *\([0-9.eE+-]*\).*/\1/p' "$OUT/log/$name.json")
  echo "$render $(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.4f", b - a }')"
}
# cycles NAME SIZE SPP SEED -> "trace_s process_s render_s" (render_s: the whole render call)
cycles() {
  local name=$1 size=$2 spp=$3 seed=$4 t0 t1
  t0=$(now)
  "$BLENDER" -b --factory-startup --python "$CYCLES_PY" -- --res "$size" --spp "$spp" --seed "$seed" \
    --bounces "$BOUNCES" --threads "$THREADS" --out "$OUT/img/$name.pfm" > "$OUT/log/$name.log" 2>&1 ||
    { tail -20 "$OUT/log/$name.log" >&2; exit 1; }
  t1=$(now)
  local trace render
  trace=$(sed -n 's/^cycles_trace_s //p' "$OUT/log/$name.log")
  render=$(sed -n 's/^cycles_render_s //p' "$OUT/log/$name.log")
  [ -n "$trace" ] || { echo "cornell_compare: no time in $OUT/log/$name.log" >&2; exit 1; }
  echo "$trace $(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.4f", b - a }') $render"
}
# relmse A REF MASK -> the image_error --relmse line
relmse() { "$IMAGE_ERROR" --relmse "$1" "$2" --mask "$3"; }
field() { awk -v k="$1" '{ for (i = 1; i < NF; ++i) if ($i == k) { print $(i + 1); exit } }'; }
means() { awk -v k="$1" '{ for (i = 1; i < NF; ++i) if ($i == k) { printf "%s %s %s", $(i + 1), $(i + 2), $(i + 3); exit } }'; }

CSV=$OUT/cornell.csv
MD=$OUT/cornell.md
echo "size,renderer,spp,seed,render_s,process_s,cycles_render_call_s,relmse,relmse_trazo_ref,mean_r,mean_g,mean_b" > "$CSV"
{
  echo "# Cornell box: Trazo (SPEC §7 path mode) and Cycles $("$BLENDER" -b --factory-startup --version 2>/dev/null | sed -n 's/^Blender //p' | head -1)"
  echo
  echo "\`bench/peers/cornell_compare.sh $BUILD $THREADS ${3:-cornell_out}\` on $(nproc) cores, $THREADS threads, MaxBounces $BOUNCES; $(date -u +%Y-%m-%d)"
  echo "(QUICK=${QUICK:-0}). Trazo $(git -C "$ROOT" rev-parse --short HEAD 2>/dev/null || echo '?'); load before: $(cut -d' ' -f1-3 /proc/loadavg)."
  echo
} > "$MD"

for S in $SIZES; do
  eval "spps=\${SPP_$S:-\"16 64\"}; runs=\${RUNS_$S:-1}; refspp=\${REF_SPP_$S:-1024}"
  half=$(( (refspp + 1) / 2 ))
  "${PFM[@]}" lightmask "$OUT/img/mask$S.pfm" "$S" "$S" > "$OUT/log/mask$S.log"
  masked=$(sed -n 's/lightmask \([0-9]*\).*/\1/p' "$OUT/log/mask$S.log")
  MASK=$OUT/img/mask$S.pfm
  echo "== ${S}²: references, $half spp × 2 seeds each" >&2

  # References: two seeds each (their difference estimates the reference's own error), then averaged.
  read -r tra tpa < <(trazo "trazo_ref${S}_a" "$S" "$half" 1001)
  read -r trb tpb < <(trazo "trazo_ref${S}_b" "$S" "$half" 1002)
  read -r cra cpa cca < <(cycles "cycles_ref${S}_a" "$S" "$half" 1001)
  read -r crb cpb ccb < <(cycles "cycles_ref${S}_b" "$S" "$half" 1002)
  for r in trazo cycles; do
    "${PFM[@]}" average "$OUT/img/${r}_ref$S.pfm" "$OUT/img/${r}_ref${S}_a.pfm" "$OUT/img/${r}_ref${S}_b.pfm"
  done
  TREF=$OUT/img/trazo_ref$S.pfm
  CREF=$OUT/img/cycles_ref$S.pfm
  # relMSE(A, B)/4 estimates the error of (A + B)/2 (E[(A − B)²] = 2 Var(A) = 4 Var((A + B)/2)).
  tnoise=$(relmse "$OUT/img/trazo_ref${S}_a.pfm" "$OUT/img/trazo_ref${S}_b.pfm" "$MASK" | field relmse)
  cnoise=$(relmse "$OUT/img/cycles_ref${S}_a.pfm" "$OUT/img/cycles_ref${S}_b.pfm" "$MASK" | field relmse)
  agree=$(relmse "$TREF" "$CREF" "$MASK")
  tmean=$(echo "$agree" | means mean_a)
  cmean=$(echo "$agree" | means mean_ref)
  tha=$(relmse "$OUT/img/trazo_ref${S}_a.pfm" "$CREF" "$MASK" | means mean_a)
  thb=$(relmse "$OUT/img/trazo_ref${S}_b.pfm" "$CREF" "$MASK" | means mean_a)
  cha=$(relmse "$OUT/img/cycles_ref${S}_a.pfm" "$CREF" "$MASK" | means mean_a)
  chb=$(relmse "$OUT/img/cycles_ref${S}_b.pfm" "$CREF" "$MASK" | means mean_a)
  tlight=$("${PFM[@]}" pixel "$TREF" $((S / 2)) $((S * 9 / 64)))
  clight=$("${PFM[@]}" pixel "$CREF" $((S / 2)) $((S * 9 / 64)))
  {
    echo "## ${S}×${S}"
    echo
    echo "References: $refspp spp each (seeds 1001 and 1002, $half spp each, averaged). Trazo $(awk -v a="$tra" -v b="$trb" 'BEGIN { printf "%.2f", a + b }') s render,"
    echo "Cycles $(awk -v a="$cra" -v b="$crb" 'BEGIN { printf "%.2f", a + b }') s path tracing ($(awk -v a="$cca" -v b="$ccb" 'BEGIN { printf "%.2f", a + b }') s render calls). $masked light pixels left out of every relMSE and mean."
    echo
    echo "| | value |"
    echo "|---|---|"
    echo "| relMSE(Trazo ref, Cycles ref) | $(echo "$agree" | field relmse) |"
    echo "| expected from their noise alone (Trazo ref's + Cycles ref's) | $(awk -v a="$tnoise" -v b="$cnoise" 'BEGIN { printf "%.3g (%.3g + %.3g)", a / 4 + b / 4, a / 4, b / 4 }') |"
    echo "| mean RGB, Trazo ref (seed halves) | $tmean ($tha / $thb) |"
    echo "| mean RGB, Cycles ref (seed halves) | $cmean ($cha / $chb) |"
    echo "| Trazo / Cycles mean − 1 | $(awk -v t="$tmean" -v c="$cmean" 'BEGIN { split(t, a, " "); split(c, b, " "); printf "%+.4f %+.4f %+.4f", a[1] / b[1] - 1, a[2] / b[2] - 1, a[3] / b[3] - 1 }') |"
    echo "| light pixel ($((S / 2)), $((S * 9 / 64))), Trazo / Cycles | $tlight / $clight |"
    echo
  } >> "$MD"

  # Test renders: for each sample count, RUNS seeds, Trazo then Cycles (so that a change of load hits both).
  echo "== ${S}²: spp $spps, $runs run(s) each" >&2
  rows=()
  for N in $spps; do
    for ((k = 1; k <= runs; ++k)); do
      seed=$((k + 10 * N))
      read -r tr tp < <(trazo "trazo_${S}_${N}_$k" "$S" "$N" "$seed")
      read -r cr cp cc < <(cycles "cycles_${S}_${N}_$k" "$S" "$N" "$seed")
      te=$(relmse "$OUT/img/trazo_${S}_${N}_$k.pfm" "$CREF" "$MASK")
      ce=$(relmse "$OUT/img/cycles_${S}_${N}_$k.pfm" "$CREF" "$MASK")
      to=$(relmse "$OUT/img/trazo_${S}_${N}_$k.pfm" "$TREF" "$MASK" | field relmse)
      co=$(relmse "$OUT/img/cycles_${S}_${N}_$k.pfm" "$TREF" "$MASK" | field relmse)
      tm=$(echo "$te" | means mean_a | tr ' ' ',')
      cm=$(echo "$ce" | means mean_a | tr ' ' ',')
      echo "$S,trazo,$N,$seed,$tr,$tp,,$(echo "$te" | field relmse),$to,$tm" >> "$CSV"
      echo "$S,cycles,$N,$seed,$cr,$cp,$cc,$(echo "$ce" | field relmse),$co,$cm" >> "$CSV"
    done
  done
  {
    echo "relMSE and ε against Cycles' reference; the last column is the ratio with both renderers measured against"
    echo "Trazo's reference instead. $runs run(s) per row (seeds 10·spp + 1…): render s is the least over them"
    echo "(their mean in brackets), process s and relMSE the means; ε = 1/(relMSE × render s)."
    echo
    echo "| spp | Trazo render s (mean) | Trazo process s | Trazo relMSE | Trazo ε | Cycles render s (mean) | Cycles process s | Cycles relMSE | Cycles ε | ε Trazo / Cycles | ε ratio, Trazo's ref |"
    echo "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
    awk -F, -v S="$S" -v spps="$spps" '
      $1 == S {
        k = $3 "," $2; n[k]++; r[k] += $5; p[k] += $6; e[k] += $8; o[k] += $9
        if (!(k in m) || $5 < m[k]) m[k] = $5
      }
      END {
        split(spps, list, " ")
        for (i = 1; i in list; ++i) {
          N = list[i]; t = N ",trazo"; c = N ",cycles"
          et = n[t] / (e[t] * m[t]); ec = n[c] / (e[c] * m[c])
          ot = n[t] / (o[t] * m[t]); oc = n[c] / (o[c] * m[c])
          printf "| %d | %.3f (%.3f) | %.3f | %.3g | %.4g | %.3f (%.3f) | %.3f | %.3g | %.4g | **%.2f** | %.2f |\n",
            N, m[t], r[t] / n[t], p[t] / n[t], e[t] / n[t], et, m[c], r[c] / n[c], p[c] / n[c], e[c] / n[c], ec,
            et / ec, ot / oc
        }
      }' "$CSV"
    echo
  } >> "$MD"

  # Pictures (sRGB view, Exposure 0): the references, and the middle sample count, Trazo left, Cycles right.
  set -- $spps
  mid=$(eval echo "\${$(( ($# + 1) / 2 ))}")
  scale=$(( S < 128 ? 2 : 1 ))
  "${PFM[@]}" png "$OUT/cornell_${S}_ref.png" "$TREF" "$CREF" --scale "$scale"
  "${PFM[@]}" png "$OUT/cornell_${S}_${mid}spp.png" "$OUT/img/trazo_${S}_${mid}_1.pfm" "$OUT/img/cycles_${S}_${mid}_1.pfm" --scale "$scale"
  if [ "$S" -ge 256 ]; then  # half size (2×2 means in linear), small enough for a README
    "${PFM[@]}" png "$OUT/cornell_${S}_ref_half.png" "$TREF" "$CREF" --downsample 2
    "${PFM[@]}" png "$OUT/cornell_${S}_${mid}spp_half.png" "$OUT/img/trazo_${S}_${mid}_1.pfm" \
      "$OUT/img/cycles_${S}_${mid}_1.pfm" --downsample 2
  fi
  {
    echo "![${S}², references: Trazo left, Cycles right](cornell_${S}_ref.png)"
    echo "![${S}², $mid spp: Trazo left, Cycles right](cornell_${S}_${mid}spp.png)"
    echo
  } >> "$MD"
done
echo "Load after: $(cut -d' ' -f1-3 /proc/loadavg)." >> "$MD"
cat "$MD"
