#!/usr/bin/env bash
# gpu_check_test.sh [REPO]: scripts/gpu_check.sh where there is no GPU must exit 0 and say, in summary.md,
# that every step was skipped and why (CI has no GPU; the script is for the lent GPU machines). Two runs:
#   1. the machine as it is, with whatever carry folder exists: skipped for "no GPU" (on a machine that has a
#      GPU this run is left out, since the steps would really run there);
#   2. GPU_CHECK_NO_GPU=1 and a carry folder that does not exist: every step that needs the carry folder
#      says "no carry folder, run scripts/gpu_prepare.sh";
#   3. scripts/gpu_full_tests.sh over a stand-in trazo_tests: its report counts and names what the shards said.
# Needs no build and no carry folder; takes seconds. Exit 0 pass, 1 fail.
set -euo pipefail
repo=${1:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}
steps=(nvidia_smi cuda_render egl_interop cuda_tests bvh_bench scene_timings memcheck register_cap)
tmp=$(mktemp -d /tmp/gpu_check_test.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "FAIL: $*"; fails=$(( fails + 1 )); }

# run_check NAME EXPECTED_REASON ENV...: runs gpu_check.sh with ENV, OUT=$tmp/NAME; checks exit 0, a line
# "- STEP: skipped — REASON" for every step, no step that ran or failed, and EXPECTED_REASON in each
# reason (for the steps given after --carry-steps-only, see below).
run_check() {
    local name=$1 expect=$2 out=$tmp/$1 rc=0 t0 secs
    shift 2
    mkdir -p "$out"
    t0=$(date +%s)
    env OUT="$out" "$@" timeout 60 bash "$repo/scripts/gpu_check.sh" >"$tmp/$name.stdout" 2>&1 || rc=$?
    secs=$(( $(date +%s) - t0 ))
    echo "== $name: exit $rc in ${secs}s"
    [ $rc = 0 ] || { fail "$name: gpu_check.sh exited $rc"; tail -n 20 "$tmp/$name.stdout"; }
    [ -s "$out/summary.md" ] || { fail "$name: no summary.md in OUT"; return; }
    sed 's/^/    /' "$out/summary.md"
    local step line reason
    for step in "${steps[@]}"; do
        line=$(grep -m1 "^- $step: " "$out/summary.md" || true)
        if [ -z "$line" ]; then fail "$name: no summary line for $step"; continue; fi
        [[ $line == "- $step: skipped — "?* ]] || { fail "$name: $step not skipped with a reason: $line"; continue; }
        reason=${line#"- $step: skipped — "}
        # nvidia_smi needs only a GPU, so its reason is about the GPU even when the carry folder is missing.
        if [ "$step" = nvidia_smi ]; then
            [[ $reason == *"no GPU"* ]] || fail "$name: nvidia_smi's reason does not say 'no GPU': $reason"
        elif [[ $reason != *"$expect"* ]]; then
            fail "$name: $step's reason lacks '$expect': $reason"
        fi
    done
    if grep -E '^- [a-z_]+: (ran|failed)' "$out/summary.md"; then fail "$name: a step ran or failed without a GPU"; fi
}

if command -v nvidia-smi >/dev/null 2>&1 && timeout 20 nvidia-smi -L 2>/dev/null | grep -q '^GPU [0-9]'; then
    echo "== as_is: left out (this machine has a GPU: gpu_check.sh would run its steps)"
else
    run_check as_is "no GPU"
fi
run_check no_carry "no carry folder, run scripts/gpu_prepare.sh" GPU_CHECK_NO_GPU=1 GPU_CARRY="$tmp/no-such-carry"

# 3. scripts/gpu_full_tests.sh, which runs after it on a GPU machine, over a stand-in trazo_tests that prints
# gtest's lines: one test passes in every shard, and the last shard has one failure.
mkdir -p "$tmp/carry/bin" "$tmp/full"
cat >"$tmp/carry/bin/trazo_tests" <<'FAKE'
#!/usr/bin/env bash
k=${GTEST_SHARD_INDEX:-0} last=$(( ${GTEST_TOTAL_SHARDS:-1} - 1 ))
echo "[ RUN      ] Fake.Passes$k"
echo "[       OK ] Fake.Passes$k (0 ms)"
if [ "$k" = "$last" ]; then
    printf '%s\n' "[ RUN      ] Fake.Fails" "fake_test.cpp:3: Failure" "Expected: 1 == 2" "[  FAILED  ] Fake.Fails (0 ms)"
fi
echo "[==========] $(( k == last ? 2 : 1 )) tests from 1 test suite ran. (0 ms total)"
echo "[  PASSED  ] 1 test."
if [ "$k" = "$last" ]; then printf '%s\n' "[  FAILED  ] 1 test, listed below:" "[  FAILED  ] Fake.Fails"; exit 1; fi
FAKE
chmod +x "$tmp/carry/bin/trazo_tests"
shards=$(nproc)
OUT="$tmp/full" GPU_CARRY="$tmp/carry" timeout 60 bash "$repo/scripts/gpu_full_tests.sh" 20 >"$tmp/full.stdout" 2>&1 \
    || fail "gpu_full_tests.sh exited non-zero: $(cat "$tmp/full.stdout")"
report=$tmp/full/full_tests.txt
echo "== gpu_full_tests:"
sed 's/^/    /' "$report" 2>/dev/null | head -n 20
grep -q "^$shards passed, 0 skipped, 1 failed$" "$report" || fail "gpu_full_tests: the counts are not $shards passed, 1 failed"
[ "$(sed -n '/^## Failed/,/^$/p' "$report" | grep -c '^Fake.Fails$')" = 1 ] || fail "gpu_full_tests: Fake.Fails not listed once"
grep -q "Expected: 1 == 2" "$report" || fail "gpu_full_tests: the failure's message is missing"
[ -s "$tmp/full/full_tests.tar.gz" ] || fail "gpu_full_tests: no full_tests.tar.gz"

if (( fails > 0 )); then echo "gpu_check_test: $fails failures"; exit 1; fi
echo "gpu_check_test: ok"
