#!/usr/bin/env bash
# POV-Ray's focal-blur `aperture` against Trazo's thin lens (SPEC §6), by the circle of confusion.
#
#   bench/peers/effects/coc_calibration.sh [OUT]        (default /tmp/coc_calibration)
#
# A tiny emissive sphere on the optical axis at depth z, the lens focused at f = 10: a thin lens of radius r
# images it as a uniform disk of radius ρ = r·|z − f|/z on the focal plane. The spot's intensity-weighted
# second moment about its centroid is E[r²] = ρ²/2 plus the emitter's own image (a disk of radius s·f/z:
# + (s·f/z)²/2) plus the pixel filter (POV-Ray: a box, + 1/6 px²; Trazo's 4×4 Antialiasing grid: + 5/32 px²),
# so ρ = sqrt(2·E[r²] − a² − filter). Both renderers are measured at z = 5 (|z − f|/z = 1) and z = 20 (1/2):
# POV-Ray at several apertures A (k = ρ/(A·|z − f|/z) is the lens radius per unit of `aperture`), Trazo at
# lens radii r (ρ/(r·|z − f|/z) must be 1: the measurement's own check).
# Writes OUT/coc_calibration.md (the table) and OUT/coc_k.txt (the mean k); prints the table.
# Environment: TRAZO (default build/app/trazo), SIZE (default 128), TRAZO_SPP (default 2048),
# POV_BLUR_SAMPLES (default 256), POV_APERTURES (default "0.4 0.8 1.6").
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=${1:-/tmp/coc_calibration}
mkdir -p "$out/calibration"
out=$(cd "$out" && pwd)
work=$out/calibration
trazo=${TRAZO:-build/app/trazo}
size=${SIZE:-128}
spp=${TRAZO_SPP:-2048}
blurSamples=${POV_BLUR_SAMPLES:-256}
apertures=${POV_APERTURES:-0.4 0.8 1.6}
spot="python3 $here/spot_radius.py"
f=10
fov=20
emitterImage=0.02   # the emitter's radius on the focal plane, s·f/z: s = 0.002·z

# pixels per scene unit on the focal plane: (SIZE/2) / (f·tan(FOV/2))
ppu=$(awk -v n="$size" -v f=$f -v fov=$fov 'BEGIN { printf "%.6f", (n / 2) / (f * sin(fov * 3.14159265358979 / 360) / cos(fov * 3.14159265358979 / 360)) }')

trazo_scene() {  # trazo_scene R Z > FILE
  cat <<SCENE
# coc_calibration.sh: an emitter of radius $(awk -v z="$2" 'BEGIN { print 0.002 * z }') at depth $2, lens radius $1 focused at $f.
SceneSettings
{
    BackgroundColor 0 0 0
    RenderWidth $size
    RenderHeight $size
    ReflectionQuality 0
    IndirectQuality 0
    Antialiasing 16
}
Camera
{
    POV 0 0 $f
    POI 0 0 0
    FOV $fov
    Aperture $1
    FocalDistance $f
    LensQuality 8
}
Material
{
    Name matEmit
    DiffuseColor 0 0 0
    SpecularColor 0 0 0
    EmissiveColor 1 1 1
    Roughness 0
}
Sphere
{
    Material matEmit
    Center 0 0 $(awk -v z="$2" -v f=$f 'BEGIN { print f - z }')
    Radius $(awk -v z="$2" 'BEGIN { print 0.002 * z }')
}
SCENE
}

pov_scene() {  # pov_scene A Z > FILE
  cat <<SCENE
// coc_calibration.sh: an emitter of radius $(awk -v z="$2" 'BEGIN { print 0.002 * z }') at depth $2, aperture $1 focused at $f.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 0 max_trace_level 1 }
background { rgb 0 }
camera {
  perspective location <0, 0, $f> look_at <0, 0, 0> right -x up y angle $fov
  aperture $1 blur_samples $blurSamples, $blurSamples focal_point <0, 0, 0> confidence 0.99 variance 0
}
sphere { <0, 0, $(awk -v z="$2" -v f=$f 'BEGIN { print f - z }')>, $(awk -v z="$2" 'BEGIN { print 0.002 * z }')
  pigment { rgb 1 } finish { ambient 0 diffuse 0 specular 0 emission 1 } }
SCENE
}

# rho R2 FILTER: the disk radius in scene units from the measured second moment (pixels²).
rho() {
  awk -v r2="$1" -v filt="$2" -v a="$emitterImage" -v ppu="$ppu" \
    'BEGIN { v = 2 * r2 - (a * ppu) ^ 2 - filt; printf "%.5f", (v > 0 ? sqrt(v) : 0) / ppu }'
}

table=$out/coc_calibration.md
{
  echo "Focus f = $f, FOV $fov°, ${size}², emitter image radius $emitterImage on the focal plane"
  echo "($(awk -v p="$ppu" 'BEGIN { printf "%.2f", p }') px per unit there). POV-Ray: blur_samples $blurSamples, variance 0; Trazo: --spp $spp, LensQuality 8, Antialiasing 16."
  echo
  echo "| renderer | setting | depth z | \|z−f\|/z | E[r²] px² | measured ρ | closed form ρ | ratio k |"
  echo "|---|---|---|---|---|---|---|---|"
} >"$table"

ks=()
for z in 5 20; do
  factor=$(awk -v z=$z -v f=$f 'BEGIN { d = z - f; if (d < 0) d = -d; printf "%.6f", d / z }')
  for a in $apertures; do
    pov_scene "$a" "$z" >"$work/pov_A${a}_z$z.pov"
    nice -n 10 povray +I"$work/pov_A${a}_z$z.pov" +W"$size" +H"$size" -A +WT1 +FP16 File_Gamma=1.0 -D -GA \
      +O"$work/pov_A${a}_z$z.ppm" >"$work/pov_A${a}_z$z.log" 2>&1 || { echo "povray failed: $work/pov_A${a}_z$z.log" >&2; exit 1; }
    r2=$($spot moment "$work/pov_A${a}_z$z.ppm" | awk '{ print $8 }')
    measured=$(rho "$r2" 0.333333)
    k=$(awk -v m="$measured" -v a="$a" -v q="$factor" 'BEGIN { printf "%.4f", m / (a * q) }')
    ks+=("$k")
    echo "| POV-Ray | aperture $a | $z | $factor | $r2 | $measured | k·$a·$factor | $k |" >>"$table"
  done
  for r in 0.1 0.2 0.4; do
    trazo_scene "$r" "$z" >"$work/trazo_r${r}_z$z.scene"
    nice -n 10 "$trazo" --render "$work/trazo_r${r}_z$z.scene" -o "$work/trazo_r${r}_z$z.pfm" --spp "$spp" --seed 1 \
      --threads 1 --quiet >/dev/null 2>"$work/trazo_r${r}_z$z.log" || { echo "trazo failed: $work/trazo_r${r}_z$z.log" >&2; exit 1; }
    r2=$($spot moment "$work/trazo_r${r}_z$z.pfm" | awk '{ print $8 }')
    measured=$(rho "$r2" 0.3125)
    closed=$(awk -v r="$r" -v q="$factor" 'BEGIN { printf "%.5f", r * q }')
    ratio=$(awk -v m="$measured" -v c="$closed" 'BEGIN { printf "%.4f", m / c }')
    echo "| Trazo | Aperture $r | $z | $factor | $r2 | $measured | $closed | $ratio |" >>"$table"
  done
done
k=$(printf '%s\n' "${ks[@]}" | awk '{ s += $1; ss += $1 * $1; n++ } END { m = s / n; printf "%.4f %.4f", m, sqrt((ss / n - m * m) > 0 ? ss / n - m * m : 0) }')
echo "${k%% *}" >"$out/coc_k.txt"
{
  echo
  echo "POV-Ray's lens radius per unit of \`aperture\`: k = ${k%% *} (mean of the ${#ks[@]} POV-Ray rows; spread ${k##* }):"
  echo "POV-Ray \`aperture A\` is Trazo \`Aperture k·A\`. Trazo's ratio column is its thin lens against the closed form."
} >>"$table"
cat "$table"
