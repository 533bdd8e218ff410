#!/usr/bin/env bash
# SPEC §6's depth of field and Fresnel glass beside POV-Ray 3.7 (issue 24, item 5: a peer no one here wrote).
#
#   bench/peers/effects/run_effects.sh [OUT]          (default /tmp/effects)
#
# 1. coc_calibration.sh: POV-Ray's lens radius per unit of `aperture`, k (Trazo's own thin lens checked
#    against the closed form on the way).
# 2. dof.scene / dof.pov: Trazo (seeds 1 and 2, --spp DOF_SPP) and POV-Ray at aperture 0.25/k (blur_samples
#    1024, and 768 for its own spread); the relative error of POV-Ray against Trazo beside each one's own noise;
#    two pinhole rows that split the rest: pixel centres only (the shading) and Trazo's 4×4 Antialiasing grid
#    against POV-Ray's box filter (focal blur jitters every sample over the pixel).
# 3. fresnel.scene / fresnel.pov: Trazo (seeds 1 and 2, --spp FRESNEL_SPP) and POV-Ray (max_trace_level 32,
#    adc_bailout 1e-6; and its defaults 8 and 1/255 for its truncation), the centre pixel of both against
#    (1 − F)/(1 + F) = 0.923077, and `rgbf 1` against `rgbt 1`.
# Writes OUT/effects.md (printed too), OUT/coc_calibration.md and the images.
# Environment: TRAZO (default build/app/trazo), IMAGE_ERROR (default build/bench/peers/image_error),
# DOF_SPP (2048), FRESNEL_SPP (8192), CENTRE_SPP (1000000), and coc_calibration.sh's SIZE, TRAZO_SPP, POV_BLUR_SAMPLES.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../common.sh"
out=${1:-/tmp/effects}
mkdir -p "$out"
out=$(cd "$out" && pwd)
TRAZO=$(cd "$(dirname "${TRAZO:-build/app/trazo}")" && pwd)/$(basename "${TRAZO:-build/app/trazo}")
imageError=$(cd "$(dirname "${IMAGE_ERROR:-build/bench/peers/image_error}")" && pwd)/$(basename "${IMAGE_ERROR:-build/bench/peers/image_error}")
export TRAZO
trazo=$TRAZO
dofSpp=${DOF_SPP:-2048}
fresnelSpp=${FRESNEL_SPP:-8192}
spot="python3 $here/spot_radius.py"
start=$(now)

pov() {  # pov SCENE.pov OUT_BASE W H [Declare=...]: EXR for image_error and linear 16-bit PPM for pixel reads
  local scene=$1 base=$2 w=$3 h=$4
  shift 4
  local t0
  t0=$(now)
  nice -n 10 povray +I"$scene" +W"$w" +H"$h" -A +WT1 +FE -D -GA +O"$base.exr" "$@" >"$base.log" 2>&1 ||
    { echo "povray failed: $base.log" >&2; exit 1; }
  elapsed "$t0" "$(now)" >"$base.time"
  nice -n 10 povray +I"$scene" +W"$w" +H"$h" -A +WT1 +FP16 File_Gamma=1.0 -D -GA +O"$base.ppm" "$@" >>"$base.log" 2>&1 ||
    { echo "povray failed: $base.log" >&2; exit 1; }
}

trazo_render() {  # trazo_render SCENE OUT_BASE SEED SPP
  nice -n 10 "$trazo" --render "$1" -o "$2.pfm" --seed "$3" --spp "$4" --threads 1 --quiet --stats "$2.json" \
    >/dev/null 2>"$2.log" || { echo "trazo failed: $2.log" >&2; exit 1; }
}

rel() { field "$("$imageError" "$1" "$2")" rel_error; }
relsd() { field "$("$imageError" --variance "$1" "$2")" rel_sd; }

# 1. calibration
"$here/coc_calibration.sh" "$out" >/dev/null
k=$(cat "$out/coc_k.txt")
aperture=$(awk -v k="$k" 'BEGIN { printf "%.4f", 0.25 / k }')

# 2. depth of field
mkdir -p "$out/dof"
d=$out/dof
for s in 1 2; do trazo_render "$here/dof.scene" "$d/trazo_$s" $s "$dofSpp"; done
pov "$here/dof.pov" "$d/pov_1024" 160 160 Declare=APERTURE="$aperture" Declare=BLUR=1024
pov "$here/dof.pov" "$d/pov_768" 160 160 Declare=APERTURE="$aperture" Declare=BLUR=768
pov "$here/dof.pov" "$d/pov_k025" 160 160 Declare=APERTURE=1.0 Declare=BLUR=1024
# pinholes: Trazo Aperture 0 with its 4×4 grid and with the pixel centre; POV-Ray's box filter (a lens too small
# to blur, so that focal blur's per-sample pixel jitter stays on) and its pixel centre (-A, no focal blur)
sed 's/^    Aperture 0.25$/    Aperture 0/' "$here/dof.scene" >"$d/pinhole_aa16.scene"
sed 's/^    Aperture 0.25$/    Aperture 0/; s/^    Antialiasing 16$/    Antialiasing 1/' "$here/dof.scene" >"$d/pinhole_aa1.scene"
trazo_render "$d/pinhole_aa16.scene" "$d/trazo_pin16" 1 16
trazo_render "$d/pinhole_aa1.scene" "$d/trazo_pin1" 1 1
pov "$here/dof.pov" "$d/pov_pinbox" 160 160 Declare=APERTURE=0.00001 Declare=BLUR=1024
pov "$here/dof.pov" "$d/pov_pin1" 160 160 Declare=APERTURE=0

dofErr=$(rel "$d/pov_1024.exr" "$d/trazo_1.pfm")
dofErr768=$(rel "$d/pov_768.exr" "$d/trazo_1.pfm")
dofErrK025=$(rel "$d/pov_k025.exr" "$d/trazo_1.pfm")
dofTrazoSd=$(relsd "$d/trazo_1.pfm" "$d/trazo_2.pfm")
dofTrazoPair=$(rel "$d/trazo_2.pfm" "$d/trazo_1.pfm")
dofPovPair=$(rel "$d/pov_768.exr" "$d/pov_1024.exr")
pinCentre=$(rel "$d/pov_pin1.exr" "$d/trazo_pin1.pfm")
pinFilter=$(rel "$d/pov_pinbox.exr" "$d/trazo_pin16.pfm")

# 3. Fresnel glass
mkdir -p "$out/fresnel"
g=$out/fresnel
for s in 1 2; do trazo_render "$here/fresnel.scene" "$g/trazo_$s" $s "$fresnelSpp"; done
pov "$here/fresnel.pov" "$g/pov" 161 161
pov "$here/fresnel.pov" "$g/pov_defaults" 161 161 Declare=TRACE_LEVEL=8 Declare=BAILOUT=0.00392157
pov "$here/fresnel.pov" "$g/pov_rgbf" 161 161 Declare=TRANSMIT=0
frErr=$(rel "$g/pov.exr" "$g/trazo_1.pfm")
frTrazoSd=$(relsd "$g/trazo_1.pfm" "$g/trazo_2.pfm")
frTrazoPair=$(rel "$g/trazo_2.pfm" "$g/trazo_1.pfm")
frPovDefaults=$(rel "$g/pov_defaults.exr" "$g/pov.exr")
frRgbf=$(rel "$g/pov_rgbf.exr" "$g/pov.exr")
centre() { $spot pixel "$1" 80 80 | awk '{ printf "%.6f", ($1 + $2 + $3) / 3 }'; }
cPov=$(centre "$g/pov.ppm")
cT1=$(centre "$g/trazo_1.pfm")
cT2=$(centre "$g/trazo_2.pfm")
# Trazo splits at the entry (weights F and 1 − F) and picks one branch at random inside, so a centre-pixel pass
# is 0.96 (the ray leaves towards the white stripe) or 0 (back towards the black behind the camera): one pass's
# standard deviation is 0.96·sqrt(p(1 − p)), p = 0.923077/0.96. A 1×1 image is the same axial ray (its one
# pixel centre is the image centre), cheap enough for CENTRE_SPP passes.
centreSpp=${CENTRE_SPP:-1000000}
passSd() { awk -v n="$1" 'BEGIN { p = 0.923077 / 0.96; printf "%.5f", 0.96 * sqrt(p * (1 - p) / n) }'; }
cSd=$(passSd "$fresnelSpp")
cMean=$(awk -v a="$cT1" -v b="$cT2" 'BEGIN { printf "%.6f", (a + b) / 2 }')
cMeanSd=$(passSd $((2 * fresnelSpp)))
for s in 1 2; do
  nice -n 10 "$trazo" --render "$here/fresnel.scene" -o "$g/centre_$s.pfm" --width 1 --height 1 --seed $s \
    --spp "$centreSpp" --threads 1 --quiet >/dev/null 2>"$g/centre_$s.log" || { echo "trazo failed: $g/centre_$s.log" >&2; exit 1; }
done
c1=$($spot pixel "$g/centre_1.pfm" 0 0 | awk '{ printf "%.6f", ($1 + $2 + $3) / 3 }')
c2=$($spot pixel "$g/centre_2.pfm" 0 0 | awk '{ printf "%.6f", ($1 + $2 + $3) / 3 }')
cBig=$(awk -v a="$c1" -v b="$c2" 'BEGIN { printf "%.6f", (a + b) / 2 }')
cBigSd=$(passSd $((2 * centreSpp)))

pct() { awk -v v="$1" 'BEGIN { printf "%.2f %%", 100 * v }'; }
total=$(elapsed "$start" "$(now)")
report=$out/effects.md
{
  echo "# SPEC §6 depth of field and Fresnel glass beside POV-Ray 3.7"
  echo
  echo "\`bench/peers/effects/run_effects.sh\`, $(date -u +%Y-%m-%d), POV-Ray $(povray --version 2>&1 | sed -n 's/^POV-Ray \([0-9][^ ]*\).*/\1/p' | head -n 1),"
  echo "one thread each, $(awk -v t="$total" 'BEGIN { printf "%.0f", t }') s in all. Relative error: RMSE over the reference's mean (\`image_error\`)."
  echo
  echo "## 1. POV-Ray's aperture (coc_calibration.sh)"
  echo
  cat "$out/coc_calibration.md"
  echo
  echo "## 2. Depth of field (dof.scene, dof.pov, 160²)"
  echo
  echo "Trazo Aperture 0.25, --spp $dofSpp; POV-Ray aperture 0.25/k = $aperture, blur_samples 1024 (variance 0)."
  echo
  echo "| comparison | relative error |"
  echo "|---|---|"
  echo "| **POV-Ray (1024) against Trazo seed 1** | **$(pct "$dofErr")** |"
  echo "| POV-Ray (768) against Trazo seed 1 | $(pct "$dofErr768") |"
  echo "| POV-Ray (1024) at the source's k = 1/4 (aperture 1.0) against Trazo seed 1 | $(pct "$dofErrK025") |"
  echo "| Trazo's own noise: seed 2 against seed 1 (one image's relative deviation) | $(pct "$dofTrazoPair") ($(pct "$dofTrazoSd")) |"
  echo "| POV-Ray's own spread: blur_samples 768 against 1024 | $(pct "$dofPovPair") |"
  echo "| pinholes, pixel centres only (Trazo Antialiasing 1, POV-Ray -A): the shading | $(pct "$pinCentre") |"
  echo "| pinholes, Trazo's 4×4 Antialiasing grid against POV-Ray's box filter (aperture 1e-5): the pixel filter | $(pct "$pinFilter") |"
  echo
  echo "## 3. Fresnel glass (fresnel.scene, fresnel.pov, 161²)"
  echo
  echo "Trazo --spp $fresnelSpp; POV-Ray max_trace_level 32, adc_bailout 1e-6, pixel centres (-A) as Trazo's Antialiasing 1."
  echo
  echo "| comparison | relative error |"
  echo "|---|---|"
  echo "| **POV-Ray against Trazo seed 1** | **$(pct "$frErr")** |"
  echo "| Trazo's own noise: seed 2 against seed 1 (one image's relative deviation) | $(pct "$frTrazoPair") ($(pct "$frTrazoSd")) |"
  echo "| POV-Ray at its defaults (max_trace_level 8, adc_bailout 1/255) against the above | $(pct "$frPovDefaults") |"
  echo "| POV-Ray \`rgbf 1\` against \`rgbt 1\` | $(pct "$frRgbf") |"
  echo
  echo "Centre pixel (80, 80), the ray through the sphere's centre onto the white stripe (emission 1); closed form"
  echo "(1 − F)/(1 + F) = 0.923077:"
  echo
  echo "| renderer | centre pixel |"
  echo "|---|---|"
  echo "| POV-Ray | $cPov |"
  echo "| Trazo seed 1 | $cT1 (± $cSd, one standard deviation of $fresnelSpp passes) |"
  echo "| Trazo seed 2 | $cT2 |"
  echo "| Trazo, both seeds | $cMean (± $cMeanSd) |"
  echo "| Trazo, the same ray as a 1×1 image, seeds 1 and 2, $centreSpp passes each | $c1, $c2: $cBig (± $cBigSd) |"
} >"$report"
cat "$report"
