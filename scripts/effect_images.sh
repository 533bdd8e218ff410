#!/usr/bin/env bash
# The pictures of SPEC §6's effects the README shows: each effect scene (scenes/effect_*.scene) rendered with the
# build's trazo into docs/images/NAME.png, and with --plots each one's time-against-error curve from
# convergence_bench into docs/images/convergence/NAME.png (its CSV and printed table beside it).
# Usage: scripts/effect_images.sh [BUILD] [--size N] [--passes P] [--plots]   (defaults: build, 256, 48)
set -euo pipefail
cd "$(dirname "$0")/.."
build=build
size=256
passes=48
plots=0
while (($#)); do
  case $1 in
    --size) size=$2; shift ;;
    --passes) passes=$2; shift ;;
    --plots) plots=1 ;;
    *) build=$1 ;;
  esac
  shift
done
out=docs/images
mkdir -p "$out"
for scene in scenes/effect_*.scene; do
  name=$(basename "$scene" .scene)
  echo "effect_images: $name ($size², $passes passes)" >&2
  "$build/app/trazo" --render "$scene" -o "$out/$name.png" --width "$size" --height "$size" --spp "$passes" --quiet
  if ((plots)); then
    mkdir -p "$out/convergence"
    "$build/bench/convergence/convergence_bench" "$scene" --width 128 --height 128 --max-passes 256 \
      --reference-passes 1024 --out-dir "$out/convergence" >"$out/convergence/$name.md"
  fi
done
