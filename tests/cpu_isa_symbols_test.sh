#!/usr/bin/env bash
# The AVX2 and AVX-512 kernels' objects (tile_render_*.cpp, camera_tile_render_*.cpp, generated from
# renderer/backends/cpu/*_isa.cpp.in) define no global code but their entry point: every inline function and
# template they emit stays local (-fno-weak), so no baseline caller can be linked to an AVX copy and the binary
# runs on any x86-64. Arguments: trazo_renderer's objects.
set -euo pipefail
checked=0
for object in "$@"; do
  case "$object" in
    *camera_tile_render_avx2.cpp.o) entry=cameraPacketKernelsAvx2 ;;
    *camera_tile_render_avx512.cpp.o) entry=cameraPacketKernelsAvx512 ;;
    *tile_render_avx2.cpp.o) entry=cpuKernelsAvx2 ;;
    *tile_render_avx512.cpp.o) entry=cpuKernelsAvx512 ;;
    *) continue ;;
  esac
  # Global code: T (text), W (weak), i (ifunc), u (unique global).
  leaks=$(nm --defined-only -g "$object" | awk '$2 ~ /^[TWiu]$/ {print $3}' | grep -v "$entry" || true)
  if [ -n "$leaks" ]; then
    echo "FAIL: $object exports code beyond its entry point:" >&2
    echo "$leaks" | c++filt | head -20 >&2
    exit 1
  fi
  nm --defined-only -g "$object" | grep -q "$entry" || { echo "FAIL: $object lacks $entry" >&2; exit 1; }
  checked=$((checked + 1))
done
if [ "$checked" -eq 0 ]; then
  echo "SKIP: no AVX kernel objects in this build (not x86-64 with GCC)"
  exit 77
fi
echo "OK: $checked AVX kernel objects export their entry point only"
