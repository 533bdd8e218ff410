#!/usr/bin/env bash
# Registers, stack frame and spills of every CUDA kernel, as ptxas reports them (-Xptxas -v), one translation
# unit at a time with the build's own flags; needs nvcc only, no GPU.
# Usage: scripts/kernel_resources.sh [--check] [ARCH]     (default ARCH 90: sm_90, the lent H100/H200)
# Prints a Markdown table: kernel (render-pass variants by their feature bits), registers, stack bytes,
# spill stores/loads, the warps per SM the registers allow for the kernel's block, and the budget verdict.
# --check: exits 1 when any kernel is over its budget (the ctest kernel_budget runs this).
#
# The budget, per thread on sm_90 (65 536 registers and 64 warps an SM):
# - registers ≤ 128: two 256-thread blocks, 16 warps an SM. Latency, not arithmetic, limits a ray tracer's
#   kernel (each BVH node is a dependent load), and the warps an SM can switch between are what hide it;
#   the render kernel's __launch_bounds__ holds ptxas to this, spilling rather than halving the warps.
# - spill stores ≤ 256 bytes, or ≤ 656 bytes in variants with indirect light, which hold two shading points
#   (P and the point Q its indirect ray finds) while Q's shadow rays traverse: spill traffic stays in L1,
#   a halved warp count would not. (640 until SPEC §6's thin lens took 16 more in the four indirect variants
#   with reflection or refraction: 620–628 → 636–644 bytes. Kept in RenderSettings rather than the per-pass
#   CameraFrame, whose growth cost 52; a called-not-inlined lens cost more through the call's saves.)
#   ≤ 752 bytes in the three indirect variants with area lights and reflection or refraction: the hit point
#   each object kind computes from its own surface (objects/<kind>.h objectHitPoint, issue 49) took 636–644 →
#   736–744 there, with the sphere's, cylinder's, mesh's and CSG's called rather than inlined (all inlined:
#   748–756; the box's stays inlined, where calling it cost more); the other variants stay within their old
#   budgets.
#   ≤ 704 bytes in the 17th variant, every feature with SPEC §6's dispersion and subsurface scattering (660
#   at its introduction: 16 over the indirect variant with reflection and refraction, for the dispersing ray's
#   channel and the walk's state); only scenes that use those two effects run it.
#   ≤ 640 bytes in the path tracer's one instance (SPEC §7, renderPassKernel<path, 0>): a path holds its BSDF
#   (frame, lobe weights and probabilities) and its throughput while the light sample's shadow ray traverses,
#   as an indirect variant holds its two shading points; it keeps no pending-ray stack.
# - stack ≤ 1536 bytes + the spill slots + the pending-ray stack (kMaxPendingRays × 44 bytes = 1408) where
#   reflection or refraction is compiled in. The frame is reserved for every thread the device can hold, but
#   only what a thread touches costs bandwidth: a few pending rays and a traversal stack as deep as the BVH.
#   The path tracer: + 512 bytes for the subsurface walk's traversal stack, live while the light samples taken
#   at its scatterings trace their shadow rays on stacks of their own (1808 bytes before those samples).
set -euo pipefail
cd "$(dirname "$0")/.."
check=0
if [[ ${1:-} == --check ]]; then check=1; shift; fi
arch=${1:-90}
nvcc=${NVCC:-/usr/local/cuda/bin/nvcc}
command -v "$nvcc" >/dev/null 2>&1 || { echo "kernel_resources: no nvcc at $nvcc (set NVCC)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The units compile in parallel, as the build does; each writes its own log.
units=(renderer/backends/cuda/render_pass_variants_*.cu renderer/backends/cuda/cuda_backend.cu)
jobs=$(nproc 2>/dev/null || echo 2)
printf '%s\n' "${units[@]}" | xargs -P "$jobs" -I{} bash -c '
  unit={}; name=$(basename "$unit" .cu)
  echo "kernel_resources: compiling $unit" >&2
  "$0" -std=c++17 -O3 -DNDEBUG -Irenderer --use_fast_math -lineinfo --expt-relaxed-constexpr \
    -gencode "arch=compute_$1,code=sm_$1" -Xptxas -v -c "$unit" -o "$2/$name.o" >"$2/$name.log" 2>&1 ||
    { cat "$2/$name.log" >&2; exit 1; }' "$nvcc" "$arch" "$work"

# ptxas prints, per entry: "Compiling entry function 'NAME'", then "N bytes stack frame, S bytes spill
# stores, L bytes spill loads", then "Used R registers".
cat "$work"/*.log | awk '
  /Compiling entry function/ { match($0, /'"'"'[^'"'"']+'"'"'/); name = substr($0, RSTART + 1, RLENGTH - 2) }
  /bytes stack frame/ && name != "" { stack = $1; spillStores = $5; spillLoads = $9 }
  /Used [0-9]+ registers/ && name != "" {
    for (i = 1; i <= NF; ++i) if ($i == "Used") regs = $(i + 1)
    print name, regs, stack, spillStores, spillLoads
    name = ""
  }' >"$work/kernels.txt"
[[ -s $work/kernels.txt ]] || { echo "kernel_resources: ptxas reported no kernels" >&2; exit 1; }

table=$(while read -r mangled regs stack stores loads; do
  # renderPassKernel<(trazo::IntegratorKind)0, 66u>(…) reads renderPassKernel<thesis, 66u> (integrator 0 of
  # core/integrator_kinds.h, feature bits 66).
  kernel=$(echo "$mangled" | c++filt | sed -E 's/^void //; s/^trazo::(\(anonymous namespace\)::)?//;
    s/\(trazo::IntegratorKind\)0/thesis/; s/\(trazo::IntegratorKind\)1/path/; s/>\(.*/>/; s/^([A-Za-z]+)\(.*/\1/')
  block=256; [[ $kernel == rayQueryKernel* ]] && block=128
  perWarp=$(( (regs * 32 + 255) / 256 * 256 ))
  warps=$(( 65536 / perWarp )); (( warps > 64 )) && warps=64
  warps=$(( warps / (block / 32) * (block / 32) ))
  # Feature bits (core/feature_mask.h): 2 area lights, 4 reflection, 16 refraction, 64 indirect, 1024
  # dispersion, 2048 subsurface, 4096 environment map.
  features=0
  [[ $kernel =~ [\<\ ]([0-9]+)u?\> ]] && features=${BASH_REMATCH[1]}
  spillBudget=256; (( features & 64 )) && spillBudget=656
  (( (features & 64) && (features & 2) && (features & (4 | 16)) )) && spillBudget=752
  (( features & (1024 | 2048 | 4096) )) && spillBudget=704
  [[ $kernel == renderPassKernel\<path* ]] && spillBudget=640
  stackBudget=$(( 1536 + (stores + 15) / 16 * 16 ))  # spill slots take whole 16-byte steps of the frame
  (( features & (4 | 16) )) && stackBudget=$(( stackBudget + 1408 ))
  [[ $kernel == renderPassKernel\<path* ]] && stackBudget=$(( stackBudget + 512 ))
  verdict=ok
  (( regs > 128 )) && verdict="over: $regs registers > 128"
  (( stores > spillBudget )) && verdict="over: $stores spill bytes > $spillBudget"
  (( stack > stackBudget )) && verdict="over: $stack stack bytes > $stackBudget"
  echo "$features|$kernel|$regs|$stack|$stores/$loads|$warps|$verdict"
  [[ $verdict == ok ]] || echo "OVER" >"$work/over"
done <"$work/kernels.txt" | sort -t'|' -k1,1n)

echo "| kernel (sm_$arch) | registers | stack bytes | spill stores/loads | warps per SM | budget |"
echo "|---|---|---|---|---|---|"
while IFS='|' read -r _ kernel regs stack spills warps verdict; do
  echo "| $kernel | $regs | $stack | $spills | $warps | $verdict |"
done <<<"$table"
if [[ -e $work/over ]]; then
  echo "kernel_resources: some kernels are over budget (see the table)" >&2
  (( check )) && exit 1
fi
exit 0
