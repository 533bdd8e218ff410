#!/usr/bin/env bash
# Fuzzes Trazo's readers with libFuzzer (bench/fuzz): builds the clang targets (ASan + UBSan) in build-fuzz/
# and runs each harness for SECONDS (default 60) from its seed corpus, growing a working corpus of its own.
#   scripts/fuzz.sh [SECONDS] [HARNESS...]        HARNESS: scene csg obj texture (default: all four, in turn)
# Per harness, build-fuzz/fuzz-out/<harness>/ holds corpus/ (inputs found, kept between runs), artifacts/
# (crash-*, timeout-*, oom-*, leak-*: reproducers) and log. Exits 1 when any harness left an artifact.
# A reproducer replays with: build-fuzz/bench/fuzz/trazo_fuzz_<harness> <file>  (or the GCC build's same target).
# Environment: TRAZO_FUZZ_BUILD (build folder, default build-fuzz), TRAZO_FUZZ_BUILD_JOBS (default 2),
# TRAZO_FUZZ_RSS_MB (default 2560), TRAZO_FUZZ_TIMEOUT (seconds an input may take, default 10),
# TRAZO_FUZZ_KEEP_GOING=1 (libFuzzer's -fork=1 with -ignore_crashes/timeouts/ooms: keep fuzzing past a finding,
# collecting every artifact, for the whole SECONDS).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
[[ $# -gt 0 ]] && shift
harnesses=("$@")
[[ ${#harnesses[@]} -eq 0 ]] && harnesses=(scene csg obj texture)
build=${TRAZO_FUZZ_BUILD:-$root/build-fuzz}
jobs=${TRAZO_FUZZ_BUILD_JOBS:-2}
rss=${TRAZO_FUZZ_RSS_MB:-2560}
timeout=${TRAZO_FUZZ_TIMEOUT:-10}
if ! [[ $seconds =~ ^[0-9]+$ ]]; then
  echo "usage: $0 [SECONDS] [scene|csg|obj|texture ...]" >&2
  exit 2
fi
for h in "${harnesses[@]}"; do
  case $h in scene|csg|obj|texture) ;; *) echo "fuzz.sh: unknown harness '$h' (scene, csg, obj, texture)" >&2; exit 2;; esac
done

if [[ ! -f $build/build.ninja ]]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DTRAZO_FUZZ=ON \
    -DTRAZO_ENABLE_CUDA=OFF -DTRAZO_BUILD_VIEWER=OFF -DTRAZO_BUILD_TESTS=OFF >/dev/null
fi
targets=()
for h in "${harnesses[@]}"; do targets+=("trazo_fuzz_$h"); done
ninja -C "$build" -j "$jobs" "${targets[@]}" >/dev/null

# The longest input each takes: scenes and CSG files are a few KB; bunny.obj, the largest OBJ seed, ~110 KB.
max_len() { case $1 in scene|csg) echo 16384;; obj) echo 131072;; texture) echo 65536;; esac; }

export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_stack_use_after_return=1:allocator_may_return_null=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
found=0
summary=()
for h in "${harnesses[@]}"; do
  out=$build/fuzz-out/$h
  mkdir -p "$out/corpus" "$out/artifacts"
  seeds=$build/bench/fuzz/corpus/$h
  echo "fuzz.sh: $h for ${seconds}s (log: $out/log)"
  extra=()
  [[ ${TRAZO_FUZZ_KEEP_GOING:-0} == 1 ]] && extra=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
  set +e
  "$build/bench/fuzz/trazo_fuzz_$h" "$out/corpus" "$seeds" -max_total_time="$seconds" -max_len="$(max_len "$h")" \
    -rss_limit_mb="$rss" -malloc_limit_mb="$rss" -timeout="$timeout" -print_final_stats=1 \
    -artifact_prefix="$out/artifacts/" "${extra[@]}" >"$out/log" 2>&1
  status=$?
  set -e
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$out/log" | tail -1)
  speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$out/log" | tail -1)
  if [[ -z $runs ]]; then  # fork mode: the last status line, "#RUNS: cov: ... exec/s: N ..."
    last=$(grep -E '^#[0-9]+' "$out/log" | tail -1 || true)
    runs=$(sed -E 's/^#([0-9]+).*/\1/' <<<"$last")
    speed=""
    [[ -n $runs && $seconds -gt 0 ]] && speed=$((runs / seconds))  # the status lines give one job's rate
  fi
  artifacts=$(find "$out/artifacts" -type f | sort)
  line="$h: ${runs:-?} executions in ${seconds}s (${speed:-?} exec/s), corpus $(find "$out/corpus" -type f | wc -l) inputs, exit $status"
  if [[ -n $artifacts || $status -ne 0 ]]; then
    found=1
    line+=", FINDINGS:"$'\n'"$(printf '  %s\n' $artifacts)"
    grep -m3 -E "ERROR: (AddressSanitizer|libFuzzer|UndefinedBehaviorSanitizer)|runtime error|ALARM|trazo fuzz:" "$out/log" | sed 's/^/    /' || true
  fi
  echo "$line"
  summary+=("$line")
done
echo "fuzz.sh: summary"
printf '  %s\n' "${summary[@]}"
exit $found
