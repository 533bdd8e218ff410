#!/usr/bin/env bash
# Kernel translation units see no host scene (docs/ARCHITECTURE.md, "Folders and include order"): the headers
# the CUDA render kernels include (integrator/sample_variants.h, through backends/cuda/render_pass_launch.h)
# and the CPU's camera packets reach only core/, accel/, geometry/, lights/, objects/, shading/ and integrator/, and no
# allocating STL container. A kind's host half (scene/kinds/) and the flattened arrays (flatten/) stay out.
# Usage: kernel_includes_test.sh CXX
set -euo pipefail
cxx=$1
cd "$(dirname "$0")/../renderer"
bad=0
for entry in integrator/sample_variants.h integrator/packets/camera_packet.h; do
    deps=$("$cxx" -std=c++17 -M -I. -x c++ "$entry" | tr ' \\' '\n\n' | grep -v '^$' | tail -n +2)
    while IFS= read -r dep; do
        case $dep in
            core/* | accel/* | geometry/* | lights/* | objects/* | shading/* | integrator/*) ;;
            */vector | */memory | */functional | */map | */unordered_map | */deque | */list) echo "$entry reaches <${dep##*/}>"; bad=1 ;;
            /*) ;;
            *) echo "$entry reaches $dep, outside the kernel folders"; bad=1 ;;
        esac
    done <<<"$deps"
done
[ $bad = 0 ] && echo "kernel includes: the kernels' headers reach only kernel folders and no allocating container"
exit $bad
