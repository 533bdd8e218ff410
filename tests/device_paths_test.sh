#!/usr/bin/env bash
# device_paths_test.sh TRAZO TRAZO_DEVICE_PATHS SCENES_DIR: every shipped scene, rendered by trazo and by
# trazo_device_paths (the same renderer with the CUDA kernels' code paths on the CPU: lane loops instead of
# SSE, run-time triangle axes, the device's 64-entry traversal stack, branch-free BRDFs), must give the same
# image bit for bit. Those paths are written to compute the host's IEEE operations in the host's order, so
# any difference is a bug in one of them; the GPU's own rounding (fast math) is CudaAgreement's to check.
# Exit 0 pass, 1 fail, 77 skipped: the others agree but the bunny's scenes were left out (scripts/setup.sh
# fetches scenes/assets/bunny.obj; a fresh clone has none).
set -euo pipefail
host=$1 device=$2 scenes=$3
tmp=$(mktemp -d /tmp/device_paths_test.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
fails=0 count=0 absent=()
for scene in "$scenes"/*.scene; do
  name=$(basename "$scene" .scene)
  if grep -q 'assets/bunny\.obj' "$scene" && [[ ! -f $scenes/assets/bunny.obj ]]; then absent+=("$name"); continue; fi
  # 48×40 (not square, so rows and columns cannot be swapped unnoticed), two passes: both halves of the
  # estimate, and the second pass's strata.
  args=(--render "$scene" --width 48 --height 40 --spp 2 --threads 2 --seed 3 --quiet)
  "$host" "${args[@]}" -o "$tmp/$name.host.pfm" 2>"$tmp/$name.host.log" || { echo "FAIL: $name: trazo failed"; cat "$tmp/$name.host.log"; fails=$((fails + 1)); continue; }
  "$device" "${args[@]}" -o "$tmp/$name.device.pfm" 2>"$tmp/$name.device.log" || { echo "FAIL: $name: trazo_device_paths failed"; cat "$tmp/$name.device.log"; fails=$((fails + 1)); continue; }
  if cmp -s "$tmp/$name.host.pfm" "$tmp/$name.device.pfm"; then
    echo "ok: $name: the device's paths give the host's image bit for bit"
  else
    echo "FAIL: $name: the device's paths give a different image"
    fails=$((fails + 1))
  fi
  count=$((count + 1))
done
(( count > 0 )) || { echo "FAIL: no scenes in $scenes"; exit 1; }
(( fails == 0 )) || { echo "$fails of $count scenes differ"; exit 1; }
if (( ${#absent[@]} > 0 )); then
  echo "SKIP: ${absent[*]} not compared: $scenes/assets/bunny.obj is absent (scripts/setup.sh fetches it); the other $count scenes agree"
  exit 77
fi
echo "all $count scenes agree"
