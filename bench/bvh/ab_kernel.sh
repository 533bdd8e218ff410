#!/usr/bin/env bash
# A bvh_bench binary whose CPU kernels for one ISA see modified copies of some renderer headers, for a quick
# A/B of a traversal or leaf-test idea without the ~200-object rebuild a header change costs: only
# backends/cpu/tile_render_<isa>.cpp is recompiled (with OVERRIDES ahead of renderer/ on the include path) into a
# copy of the library, and bvh_bench is relinked against it. The build's own files are left as they are.
#
#   bench/bvh/ab_kernel.sh BUILD OVERRIDES OUT [ISA]
#     BUILD      a configured build folder (ninja) whose bvh_bench is up to date
#     OVERRIDES  a folder laid out as renderer/ holding only the changed headers, e.g. OVERRIDES/accel/wide8_traverse.h
#     OUT        the binary to write
#     ISA        avx512 (default), avx2 or sse2: the kernel unit to rebuild (what TRAZO_CPU_ISA or the CPU selects)
#
# Then interleave the two binaries, e.g. for r in 1 2 3; do for b in BUILD/bench/bvh/bvh_bench OUT; do
# $b --scene bunny --threads 1 --repeat 2 --no-build; done; done. Headers are found this way because every
# include under renderer/ names its folder ("accel/...", "geometry/..."). tile_render_<isa>.cpp holds the ray
# queries bvh_bench times; what other units inline from the same headers (camera_tile_render_<isa>.cpp's camera
# blocks, the rest of the library) keeps the original.
set -euo pipefail

if [[ $# -lt 3 ]]; then
    sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'
    exit 2
fi
build=$(cd "$1" && pwd)
overrides=$(cd "$2" && pwd)
out=$(realpath -m "$3")
isa=${4:-avx512}
case "$isa" in
    avx512 | avx2 | sse2) ;;
    *) echo "ab_kernel.sh: ISA must be avx512, avx2 or sse2, not $isa" >&2; exit 2 ;;
esac

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$build"
object=renderer/CMakeFiles/trazo_renderer.dir/backends/cpu/tile_render_$isa.cpp.o
compile=$(ninja -t commands "$object" | tail -1)
link=$(ninja -t commands bench/bvh/bvh_bench | tail -1)
source_dir=$(sed -n 's|.* -I\([^ ]*/renderer\) .*|\1|p' <<<"$compile")
[[ -n "$source_dir" ]] || { echo "ab_kernel.sh: no -I.../renderer in the compile command" >&2; exit 1; }

# The kernel unit, with the overrides first on the include path and no dependency file.
compile=${compile/ -I$source_dir / -I$overrides -I$source_dir }
compile=$(sed -e 's| -MD -MT [^ ]* -MF [^ ]*||' <<<"$compile")
compile=${compile/ -o $object / -o $work/$(basename "$object") }
echo "ab_kernel.sh: compiling tile_render_$isa.cpp against $overrides" >&2
eval "$compile"

cp renderer/libtrazo_renderer.a "$work/libtrazo_renderer.a"
ar r "$work/libtrazo_renderer.a" "$work/$(basename "$object")"
link=${link//renderer\/libtrazo_renderer.a/$work/libtrazo_renderer.a}
link=${link/ -o bench\/bvh\/bvh_bench / -o $out }
eval "$link"
echo "ab_kernel.sh: wrote $out" >&2
