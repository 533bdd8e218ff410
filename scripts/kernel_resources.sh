#!/usr/bin/env bash
# Registers, stack frame and spills of every CUDA kernel, as ptxas reports them (-Xptxas -v), one translation
# unit at a time with the build's own flags; needs nvcc only, no GPU.
# Usage: scripts/kernel_resources.sh [ARCH]        (default 90: sm_90, the lent H100/H200)
# Prints a Markdown table: kernel (render-pass variants by their feature bits), registers, stack bytes,
# spill stores/loads, and the warps per SM the registers allow for the kernel's block size.
set -euo pipefail
cd "$(dirname "$0")/.."
arch=${1:-90}
nvcc=${NVCC:-/usr/local/cuda/bin/nvcc}
command -v "$nvcc" >/dev/null 2>&1 || { echo "kernel_resources: no nvcc at $nvcc (set NVCC)" >&2; exit 1; }
log=$(mktemp)
trap 'rm -f "$log" "$log.o"' EXIT
for unit in renderer/backends/cuda/render_pass_variants_*.cu renderer/backends/cuda/cuda_backend.cu; do
  echo "kernel_resources: compiling $unit" >&2
  "$nvcc" -std=c++17 -O3 -DNDEBUG -Irenderer --use_fast_math -lineinfo --expt-relaxed-constexpr \
    -gencode "arch=compute_$arch,code=sm_$arch" -Xptxas -v -c "$unit" -o "$log.o" >>"$log" 2>&1
done
# ptxas prints, per entry: "Compiling entry function 'NAME'", then "N bytes stack frame, S bytes spill
# stores, L bytes spill loads", then "Used R registers".
awk '
  /Compiling entry function/ { match($0, /'"'"'[^'"'"']+'"'"'/); name = substr($0, RSTART + 1, RLENGTH - 2) }
  /bytes stack frame/ { stack = $1; spillStores = $5; spillLoads = $9 }
  /Used [0-9]+ registers/ && name != "" {
    for (i = 1; i <= NF; ++i) if ($i == "Used") regs = $(i + 1)
    print name, regs, stack, spillStores, spillLoads
    name = ""
  }' "$log" | while read -r mangled regs stack stores loads; do
  kernel=$(echo "$mangled" | c++filt | sed -E 's/^void //; s/^trazo::(\(anonymous namespace\)::)?//; s/\(.*//')
  block=256; [[ $kernel == rayQueryKernel* ]] && block=128
  perWarp=$(( (regs * 32 + 255) / 256 * 256 ))
  warps=$(( 65536 / perWarp )); (( warps > 64 )) && warps=64
  warps=$(( warps / (block / 32) * (block / 32) ))
  echo "$kernel|$regs|$stack|$stores/$loads|$warps"
done | sort -t'<' -k2 -n | {
  echo "| kernel (sm_$arch) | registers | stack bytes | spill stores/loads | warps per SM |"
  echo "|---|---|---|---|---|"
  while IFS='|' read -r kernel regs stack spills warps; do
    echo "| $kernel | $regs | $stack | $spills | $warps |"
  done
}
