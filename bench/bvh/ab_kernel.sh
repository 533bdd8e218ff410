#!/usr/bin/env bash
# A bvh_bench (or trazo) binary whose CPU kernels for one ISA see modified copies of some renderer headers, for a
# quick A/B of a traversal, leaf-test or shading idea without the rebuild a header change costs: only the kernel
# units of that ISA are recompiled (with OVERRIDES ahead of renderer/ on the include path) into a copy of the
# library, and the binary is relinked against it. The build's own files are left as they are.
#
#   bench/bvh/ab_kernel.sh BUILD OVERRIDES OUT [ISA] [TARGET]
#     BUILD      a configured build folder (ninja) whose TARGET is up to date
#     OVERRIDES  a folder laid out as renderer/ holding only the changed headers, e.g. OVERRIDES/accel/wide8_traverse.h
#     OUT        the binary to write
#     ISA        avx512 (default), avx2 or sse2: the kernel units to rebuild (what TRAZO_CPU_ISA or the CPU selects)
#     TARGET     bvh_bench (default): backends/cpu/tile_render_<isa>.cpp, which holds the ray queries bvh_bench
#                times, is recompiled; trazo: tile_render_<isa>.cpp and camera_tile_render_<isa>.cpp (the camera
#                blocks and packets most seed scenes render with; ~6 minutes on 2 cores), and the app is relinked
#
# Then interleave the two binaries, e.g. for r in 1 2 3; do for b in BUILD/bench/bvh/bvh_bench OUT; do
# $b --scene bunny --threads 1 --repeat 2 --no-build; done; done. Headers are found this way because every
# include under renderer/ names its folder ("accel/...", "geometry/..."). What other units inline from the same
# headers keeps the original, so compare against a binary made the same way with an empty OVERRIDES folder when
# the rest of the library might matter.
set -euo pipefail

if [[ $# -lt 3 ]]; then
    sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'
    exit 2
fi
build=$(cd "$1" && pwd)
overrides=$(cd "$2" && pwd)
out=$(realpath -m "$3")
isa=${4:-avx512}
target=${5:-bvh_bench}
case "$isa" in
    avx512 | avx2 | sse2) ;;
    *) echo "ab_kernel.sh: ISA must be avx512, avx2 or sse2, not $isa" >&2; exit 2 ;;
esac
case "$target" in
    bvh_bench) binary=bench/bvh/bvh_bench units=(tile_render) ;;
    trazo) binary=app/trazo units=(tile_render camera_tile_render) ;;
    *) echo "ab_kernel.sh: TARGET must be bvh_bench or trazo, not $target" >&2; exit 2 ;;
esac

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$build"
cp renderer/libtrazo_renderer.a "$work/libtrazo_renderer.a"
for unit in "${units[@]}"; do
    object=renderer/CMakeFiles/trazo_renderer.dir/backends/cpu/${unit}_$isa.cpp.o
    compile=$(ninja -t commands "$object" | tail -1)
    source_dir=$(sed -n 's|.* -I\([^ ]*/renderer\) .*|\1|p' <<<"$compile")
    [[ -n "$source_dir" ]] || { echo "ab_kernel.sh: no -I.../renderer in the compile command" >&2; exit 1; }
    # The kernel unit, with the overrides first on the include path and no dependency file.
    compile=${compile/ -I$source_dir / -I$overrides -I$source_dir }
    compile=$(sed -e 's| -MD -MT [^ ]* -MF [^ ]*||' <<<"$compile")
    compile=${compile/ -o $object / -o $work/$(basename "$object") }
    echo "ab_kernel.sh: compiling ${unit}_$isa.cpp against $overrides" >&2
    eval "$compile"
    ar r "$work/libtrazo_renderer.a" "$work/$(basename "$object")"
done

link=$(ninja -t commands "$binary" | tail -1)
link=${link//renderer\/libtrazo_renderer.a/$work/libtrazo_renderer.a}
link=${link/ -o $binary / -o $out }
eval "$link"
echo "ab_kernel.sh: wrote $out" >&2
