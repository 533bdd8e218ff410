#!/usr/bin/env bash
# gpu_full_tests.sh — run HERE after scripts/gpu_check.sh on a lent GPU machine: the whole of trazo_tests
# (not only the CUDA suites gpu_check runs), sharded over every core, with the GPU present. It catches tests
# that only break where a CUDA device exists (the default backend `auto` picks it, say).
#
#   bash scripts/gpu_full_tests.sh [SECONDS]      # default 90: each shard's time limit
#
# Needs gpu-carry/ (scripts/gpu_prepare.sh) and the links gpu_check.sh makes to the compiled-in source and
# trazo paths. Writes $OUT/full_tests.txt (counts and every failure's name and first lines) and
# $OUT/full_tests.tar.gz (every shard's log). Tests that need peers the machine lacks (POV-Ray, Embree, Slurm,
# Xvfb) fail or skip there; read the names.
set -uo pipefail
export LC_ALL=C
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$repo"
limit=${1:-90}
carry=${GPU_CARRY:-$repo/gpu-carry}
OUT=${OUT:-$(mktemp -d /tmp/gpu_full_tests.XXXXXX)}
work=$(mktemp -d /tmp/gpu_full_tests_work.XXXXXX)
report=$OUT/full_tests.txt
tests=$carry/bin/trazo_tests
if [ ! -x "$tests" ]; then echo "gpu_full_tests: no $tests (run scripts/gpu_prepare.sh here)" | tee "$report"; exit 1; fi
shards=$(nproc)
start=$(date +%s)
for ((k = 0; k < shards; ++k)); do
    GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$k timeout -k 5 "$limit" "$tests" --gtest_brief=0 \
        >"$work/shard_$k.log" 2>&1 </dev/null &
done
wait
seconds=$(( $(date +%s) - start ))
count() { cat "$work"/shard_*.log | grep -o "^\[  $1 *\] [0-9][0-9]* test" | grep -o '[0-9][0-9]*' | awk '{s += $1} END {print s + 0}'; }
unfinished=$(for f in "$work"/shard_*.log; do grep -q '^\[==========\] .* ran' "$f" || basename "$f" .log; done | tr '\n' ' ')
{
    echo "trazo_tests, $shards shards in parallel, ${seconds} s, $(date -u +%Y-%m-%dT%H:%M:%SZ), $(uname -n):"
    echo "$(count PASSED) passed, $(count SKIPPED) skipped, $(count FAILED) failed${unfinished:+; shards that did not finish: $unfinished}"
    echo
    echo "## Failed"
    grep -h '^\[  FAILED  \] [A-Za-z]' "$work"/shard_*.log | sed 's/^\[  FAILED  \] //; s/ (.*//' | sort -u
    echo
    echo "## Skipped (reasons, counted)"
    grep -h -B1 '^\[  SKIPPED \] [A-Za-z]' "$work"/shard_*.log | grep -v '^\[\|^--' | sed 's/^.*: //' | sort | uniq -c | sort -rn | head -n 30
    echo
    echo "## The failures' messages (first 12 lines each)"
    for f in "$work"/shard_*.log; do
        awk '/^\[ RUN      \]/ {name = $4; n = 0; buf = ""} {if (n < 12) {buf = buf $0 "\n"; n++}}
             /^\[  FAILED  \] [A-Za-z]/ && $4 == name {printf "%s\n", buf; name = ""}' "$f"
    done
} >"$report"
tar -C "$work" -czf "$OUT/full_tests.tar.gz" .
rm -rf "$work"
head -n 2 "$report"
