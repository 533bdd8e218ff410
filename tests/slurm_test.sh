#!/usr/bin/env bash
# scripts/slurm on a real single-node Slurm that this test starts (tests/support/slurm_cluster.sh: munged,
# slurmctld and slurmd as child processes, every file in a temporary directory, stopped by PID at exit):
#  (a) a 4-task job array of scene1_area (64x48, 4 passes a task) merges, in the merge job that depends on it,
#      to the image of one `trazo --render --passes 0:16` (every float within one ulp: docs/PARTIAL_FORMAT.md);
#  (b) a task cancelled mid-render (scancel) leaves the merge job waiting forever (afterok), merge.sh names the
#      passes the task did not render (status 2, no image), and resubmitting that task alone completes the render,
#      which again equals the single render;
#  (c) a part cut short as a time limit cuts it (trazo --time) leaves its tail missing; resubmit.sh without tasks
#      renders just that tail (split in two tasks) and the merge equals the single render.
# Usage: slurm_test.sh TRAZO SCENES_DIR. Exit 77 (CTest SKIP_RETURN_CODE) where Slurm cannot start here.
set -u
trazo=$(realpath "$1")
scenes=$(realpath "$2")
tests=$(cd "$(dirname "$0")" && pwd)
slurm=$tests/../scripts/slurm
scene=$scenes/scene1_area.scene
size=(--seed 5 --width 64 --height 48)

work=$(mktemp -d)
# shellcheck source=support/slurm_cluster.sh
source "$tests/support/slurm_cluster.sh"
cleanup() {
    slurm_cluster_stop
    rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 1' INT TERM
started=$SECONDS

fail() {
    echo "FAIL: $*"
    local log
    for log in "$work"/*/logs/*.log; do
        [ -f "$log" ] && { echo "--- $log"; tail -n 20 "$log"; }
    done
    slurm_cluster_logs
    exit 1
}

slurm_cluster_start "$work/cluster" || exit $?
echo "Slurm up in $((SECONDS - started)) s: $(sinfo -h -o '%P %D %t %c CPUs')"

# Waits up to $2 s (default 90) until job $1 (an array: every task) has left the queue.
wait_job() {
    local deadline=$((SECONDS + ${2:-90}))
    while squeue -h -o %F | grep -qx "$1"; do
        ((SECONDS < deadline)) || fail "job $1 still queued after ${2:-90} s: $(squeue -h -o '%i %T %R')"
        # Well inside CTest's TIMEOUT, which would kill this shell before it stops the daemons.
        ((SECONDS - started < 240)) || fail "the test has run for 4 minutes: $(squeue -h -o '%i %T %R')"
        sleep 0.2
    done
}
job_state() { scontrol show job "$1" | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | head -n 1; }
job_reason() { scontrol show job "$1" | sed -n 's/.*Reason=\([A-Za-z_]*\).*/\1/p' | head -n 1; }
# The job ids in submit.sh's or resubmit.sh's output.
array_of() { sed -n 's/^trazo: job array \([0-9]*\):.*/\1/p' <<<"$1"; }
merge_of() { sed -n 's/^trazo: merge job \([0-9]*\) .*/\1/p' <<<"$1"; }

# Same header, and every float (little-endian PFM: pixels are non-negative) within one ulp.
within_one_ulp() {
    local header
    header=$(head -n 3 "$1" | wc -c)
    [ "$(head -c "$header" "$1")" = "$(head -c "$header" "$2")" ] || return 1
    cmp -s "$1" "$2" && { echo "identical"; return 0; }
    paste <(od -An -v -t u4 -w4 -j "$header" "$1") <(od -An -v -t u4 -w4 -j "$header" "$2") |
        awk '{ d = $1 - $2; if (d < 0) d = -d; if (d > 1) bad++; else if (d == 1) ulp++; n++ }
             END { if (bad) { print bad " of " n " floats differ by more than one ulp"; exit 1 }
                   print n - ulp " of " n " floats identical, " ulp " one ulp apart" }'
}
reference() {  # reference N: the single render of passes 0:N
    "$trazo" --render "$scene" --passes "0:$1" -o "$work/reference-$1.pfm" "${size[@]}" --backend cpu --quiet \
        2>"$work/reference.log" || fail "the single render of passes 0:$1: $(cat "$work/reference.log")"
}
expect_image() {  # expect_image DIR N
    [ -f "$1/image.pfm" ] || fail "$1: no merged image"
    local how
    how=$(within_one_ulp "$work/reference-$2.pfm" "$1/image.pfm") ||
        fail "$1/image.pfm differs from the single render of passes 0:$2 ($how)"
    grep -q "\"spp\": $2," "$1/stats.json" || fail "$1/stats.json does not count $2 passes: $(cat "$1/stats.json")"
    echo "  image = single render of 0:$2 ($how)"
}

# (a) 4 tasks of 4 passes, merged by the merge job. A 5-minute limit: trazo is given 270 s.
echo "(a) a 4-task array and its merge job"
reference 16
out=$("$slurm/submit.sh" "$scene" --passes 16 --tasks 4 --time 5 --out "$work/a" --image image.pfm \
    --trazo "$trazo" -- "${size[@]}" 2>&1) || fail "submit.sh: $out"
echo "$out" | sed 's/^/  /'
array=$(array_of "$out") merge=$(merge_of "$out")
[ -n "$array" ] && [ -n "$merge" ] || fail "submit.sh printed no job ids"
wait_job "$array"
wait_job "$merge"
for task in 0 1 2 3; do
    [ "$(job_state "${array}_$task")" = COMPLETED ] || fail "task $task: $(job_state "${array}_$task")"
done
[ "$(job_state "$merge")" = COMPLETED ] || fail "merge job $merge: $(job_state "$merge")"
scontrol show job "${array}_0" | grep -q "TimeLimit=00:05:00" || fail "task 0 has no 5-minute limit"
grep -q -- "--passes 0:4 --partial $work/a/parts/0-4.partial --quiet --backend cpu --threads 1 --time 270 " \
    "$work/a/logs/task-${array}_0.log" || fail "task 0 ran: $(tail -n 1 "$work/a/logs/task-${array}_0.log")"
[ "$(cd "$work/a/parts" && ls | sort -n | paste -sd' ' -)" = "0-4.partial 4-8.partial 8-12.partial 12-16.partial" ] ||
    fail "parts: $(ls "$work/a/parts")"
expect_image "$work/a" 16

# (b) 2 tasks long enough to cancel one mid-render: about 4 s a task, from the time of 40 passes here.
echo "(b) a task cancelled mid-render, then resubmitted alone"
render_ns() {  # the wall time of a one-thread render of $1 passes, start-up included
    local start
    start=$(date +%s%N)
    "$trazo" --render "$scene" --passes "0:$1" -o "$work/timing.pfm" "${size[@]}" --backend cpu --threads 1 --quiet \
        2>/dev/null || fail "the timing render"
    echo $(($(date +%s%N) - start))
}
short=$(render_ns 10) long=$(render_ns 50)
per_pass_ms=$(((long - short) / 40000000 + 1))
half=$((4000 / per_pass_ms))
((half < 40)) && half=40
((half > 4000)) && half=4000
passes=$((2 * half))
echo "  ${per_pass_ms} ms a pass: 2 tasks of $half passes"
reference "$passes"
out=$("$slurm/submit.sh" "$scene" --passes "$passes" --tasks 2 --out "$work/b" --image image.pfm --trazo "$trazo" \
    -- "${size[@]}" 2>&1) || fail "submit.sh: $out"
array=$(array_of "$out") merge=$(merge_of "$out")
deadline=$((SECONDS + 60))
until [ "$(job_state "${array}_1")" = RUNNING ] && grep -q "passes $half:$passes" "$work/b/logs/task-${array}_1.log" 2>/dev/null; do
    ((SECONDS < deadline)) || fail "task 1 did not start in 60 s"
    sleep 0.1
done
sleep 0.5
scancel "${array}_1"
wait_job "$array"
[ "$(job_state "${array}_1")" = CANCELLED ] ||
    fail "task 1 ended $(job_state "${array}_1") before scancel reached it: its render is too short here"
[ "$(job_state "${array}_0")" = COMPLETED ] || fail "task 0: $(job_state "${array}_0")"
# afterok can no longer be satisfied: the merge job waits, never runs (22.05 keeps it pending, with this reason
# once the scheduler has looked at it again).
deadline=$((SECONDS + 30))
until [ "$(job_reason "$merge")" = DependencyNeverSatisfied ]; do
    [ "$(job_state "$merge")" = PENDING ] && ((SECONDS < deadline)) ||
        fail "merge job $merge: $(job_state "$merge") $(job_reason "$merge"), not pending on DependencyNeverSatisfied"
    sleep 0.2
done
"$slurm/merge.sh" "$work/b" >"$work/b-merge.log" 2>&1
status=$?
cat "$work/b-merge.log" | sed 's/^/  /'
[ $status -eq 2 ] || fail "merge.sh after the cancel: status $status, not 2"
[ ! -e "$work/b/image.pfm" ] || fail "merge.sh wrote an image with passes missing"
cut=$(sed -n "s/^trazo: merge: passes \([0-9]*\):$passes are missing$/\1/p" "$work/b-merge.log")
[ -n "$cut" ] && ((cut >= half && cut < passes)) ||
    fail "merge.sh does not name the cancelled task's passes (X:$passes with $half <= X)"
[ "$(grep -c 'are missing' "$work/b-merge.log")" = 1 ] || fail "merge.sh names other ranges too"
echo "  task 1 rendered passes $half:$cut before the cancel"
out=$("$slurm/resubmit.sh" "$work/b" 1 2>&1) || fail "resubmit.sh: $out"
echo "$out" | sed 's/^/  /'
grep -q "cancelled the merge job(s) waiting on the earlier tasks: $merge" <<<"$out" ||
    fail "resubmit.sh did not cancel the merge job $merge left waiting"
array=$(array_of "$out") merge=$(merge_of "$out")
wait_job "$array"
wait_job "$merge"
[ "$(job_state "$merge")" = COMPLETED ] || fail "the new merge job $merge: $(job_state "$merge")"
expect_image "$work/b" "$passes"

# (c) a part cut short (what a time limit hands back), its tail rendered by resubmit.sh in 2 tasks.
echo "(c) the missing tail of a part cut short, filled by resubmit.sh --split 2"
part=$work/a/parts/8-12.partial
"$trazo" --render "$scene" --passes 8:12 --partial "$part" --time 0.000001 "${size[@]}" --backend cpu --quiet \
    2>"$work/c-cut.log" || fail "the cut render: $(cat "$work/c-cut.log")"
rm "$work/a/image.pfm" "$work/a/stats.json"
"$slurm/merge.sh" "$work/a" --check >"$work/c-merge.log" 2>&1
[ $? -eq 2 ] || fail "merge.sh --check after the cut: $(cat "$work/c-merge.log")"
grep -q "passes [0-9]*:12 are missing" "$work/c-merge.log" || fail "merge.sh: $(cat "$work/c-merge.log")"
out=$("$slurm/resubmit.sh" "$work/a" --split 2 2>&1) || fail "resubmit.sh: $out"
echo "$out" | sed 's/^/  /'
array=$(array_of "$out") merge=$(merge_of "$out")
wait_job "$array"
wait_job "$merge"
[ "$(job_state "$merge")" = COMPLETED ] || fail "the fill's merge job $merge: $(job_state "$merge")"
expect_image "$work/a" 16

# (d) --gpu: the tasks ask for one GPU each and run trazo --backend cuda (the test cluster counts one GPU; the
# tasks succeed only where trazo has CUDA and the machine a GPU).
echo "(d) --gpu tasks"
out=$("$slurm/submit.sh" "$scene" --passes 4 --tasks 2 --gpu --out "$work/d" --image image.pfm --trazo "$trazo" \
    -- "${size[@]}" 2>&1) || fail "submit.sh --gpu: $out"
array=$(array_of "$out") merge=$(merge_of "$out")
wait_job "$array"
scontrol show job "${array}_0" | grep -q "TresPerNode=gres:gpu:1" || fail "task 0 asked for no GPU"
grep -q -- "--backend cuda" "$work/d/logs/task-${array}_0.log" || fail "task 0 did not run trazo --backend cuda"
if [ "$(job_state "${array}_0")" = COMPLETED ]; then
    wait_job "$merge"
    [ "$(job_state "$merge")" = COMPLETED ] || fail "the GPU render's merge job: $(job_state "$merge")"
    echo "  2 GPU tasks and their merge completed"
else
    echo "  GPU tasks scheduled with gres/gpu=1; trazo here: $(tail -n 1 "$work/d/logs/task-${array}_0.log")"
fi

echo "PASS in $((SECONDS - started)) s"
