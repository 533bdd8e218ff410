#!/usr/bin/env bash
# The expected speed-up of a render split over N nodes, from one node's measured times (docs/PARTIAL_FORMAT.md,
# "Scale"). Every node renders P/N passes and writes a partial; one merge job then reads them all:
#   T(N) = F + (P/N)·t + w + N·m + i        T(1) = F + P·t + i        S(N) = T(1) / T(N)
# F: a task's fixed cost (scene read and build, upload: the stats' parse_s + upload_s), t: render seconds per
# pass, w: writing the partial, m: merging one part (reading and adding it), i: writing the image.
# Queueing, node start-up and file-system contention are left out: they add to every T(N) with N > 1.
#   usage: bench/partial/speedup.sh TRAZO SCENE MEASURED_PASSES MODELLED_PASSES [trazo options...]
#   e.g.   bench/partial/speedup.sh build/app/trazo scenes/scene1_area.scene 4 1024 --backend cpu
set -euo pipefail
trazo=$1 scene=$2 measured=$3 modelled=$4
shift 4
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
value() { sed -n "s/.*\"$1\": \([0-9.eE+-]*\).*/\1/p" "$2"; }

"$trazo" --render "$scene" --passes "0:$measured" --partial "$dir/a.part" --stats "$dir/a.json" --quiet "$@" 2>/dev/null
"$trazo" merge "$dir/a.part" -o "$dir/image.png" --stats "$dir/m.json" --quiet 2>/dev/null
F=$(awk -v p="$(value parse_s "$dir/a.json")" -v u="$(value upload_s "$dir/a.json")" 'BEGIN { print p + u }')
t=$(awk -v r="$(value render_s "$dir/a.json")" -v n="$measured" 'BEGIN { print r / n }')
w=$(value write_s "$dir/a.json")
m=$(value merge_s "$dir/m.json")
i=$(value write_s "$dir/m.json")
size=$(stat -c %s "$dir/a.part")
echo "scene $scene, $(value width "$dir/a.json")x$(value height "$dir/a.json"), $*"
echo "measured over $measured passes: F = $F s, t = $t s a pass, w = $w s, m = $m s a part, i = $i s;" \
     "a partial is $size bytes"
echo "modelled render of $modelled passes:"
awk -v F="$F" -v t="$t" -v w="$w" -v m="$m" -v i="$i" -v P="$modelled" 'BEGIN {
    T1 = F + P * t + i
    printf "  %5s  %10s  %8s  %10s\n", "N", "T(N) s", "S(N)", "efficiency"
    split("1 4 16 64 256", nodes, " ")
    for (k = 1; k <= 5; ++k) {
        N = nodes[k]
        T = F + P * t / N + w + N * m + i
        printf "  %5d  %10.3f  %8.2f  %9.0f%%\n", N, T, T1 / T, 100 * T1 / T / N
    }
}'
