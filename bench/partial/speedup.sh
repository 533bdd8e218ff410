#!/usr/bin/env bash
# The expected speed-up of a render split over N nodes, from one node's measured times (docs/PARTIAL_FORMAT.md,
# "Scale"). Every node renders P/N passes and writes a partial; one merge job then reads them all:
#   T(N) = F + (P/N)·t + w + m0 + (N-1)·m + i        T(1) = F + P·t + i        S(N) = T(1) / T(N)
# F: a task's fixed cost (scene read and build, upload: the stats' parse_s + upload_s), t: render seconds per
# pass, w: writing the partial, m0: a merge of one part (its buffers' first touch included), m: each further
# part (reading, checking and adding it; from a merge of 4 parts), i: writing the image.
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
for k in 0 1 2; do  # three 1-pass parts more, for the merge's cost per part
    "$trazo" --render "$scene" --passes "$((measured + k)):$((measured + k + 1))" --partial "$dir/b$k.part" --quiet \
        "$@" 2>/dev/null
done
"$trazo" merge "$dir/a.part" -o "$dir/image.png" --stats "$dir/m.json" --quiet 2>/dev/null
"$trazo" merge "$dir"/a.part "$dir"/b?.part --partial "$dir/all.part" --stats "$dir/m4.json" --quiet 2>/dev/null
F=$(awk -v p="$(value parse_s "$dir/a.json")" -v u="$(value upload_s "$dir/a.json")" 'BEGIN { print p + u }')
t=$(awk -v r="$(value render_s "$dir/a.json")" -v n="$measured" 'BEGIN { print r / n }')
w=$(value write_s "$dir/a.json")
m0=$(value merge_s "$dir/m.json")
m=$(awk -v a="$m0" -v b="$(value merge_s "$dir/m4.json")" 'BEGIN { d = (b - a) / 3; print (d > 0 ? d : 0) }')
i=$(value write_s "$dir/m.json")
size=$(stat -c %s "$dir/a.part")
echo "scene $scene, $(value width "$dir/a.json")x$(value height "$dir/a.json"), $*"
echo "measured over $measured passes: F = $F s, t = $t s a pass, w = $w s, m0 = $m0 s, m = $m s a part," \
     "i = $i s;" \
     "a partial is $size bytes"
echo "modelled render of $modelled passes:"
awk -v F="$F" -v t="$t" -v w="$w" -v m0="$m0" -v m="$m" -v i="$i" -v P="$modelled" 'BEGIN {
    T1 = F + P * t + i
    printf "  %5s  %10s  %8s  %10s\n", "N", "T(N) s", "S(N)", "efficiency"
    split("1 4 16 64 256", nodes, " ")
    for (k = 1; k <= 5; ++k) {
        N = nodes[k]
        T = F + P * t / N + w + m0 + (N - 1) * m + i
        printf "  %5d  %10.3f  %8.2f  %9.0f%%\n", N, T, T1 / T, 100 * T1 / T / N
    }
}'
