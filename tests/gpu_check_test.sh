#!/usr/bin/env bash
# gpu_check_test.sh [REPO]: scripts/gpu_check.sh where there is no GPU must exit 0 and say, in summary.md,
# that every step was skipped and why (CI has no GPU; the script is for the lent GPU machines). Two runs:
#   1. the machine as it is, with whatever carry folder exists: skipped for "no GPU" (on a machine that has a
#      GPU this run is left out, since the steps would really run there);
#   2. GPU_CHECK_NO_GPU=1 and a carry folder that does not exist: every step that needs the carry folder
#      says "no carry folder, run scripts/gpu_prepare.sh".
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

if (( fails > 0 )); then echo "gpu_check_test: $fails failures"; exit 1; fi
echo "gpu_check_test: ok"
