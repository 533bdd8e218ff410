#!/usr/bin/env bash
# Renders again what a render directory lacks, then merges: a new job array and a new merge job (afterok on the
# new tasks, afterany on this render's tasks still queued). A merge job left waiting on a failed task is cancelled.
#
# Usage: resubmit.sh DIR [TASK...] [--split S] [--time MIN]
#   TASK...       rerun these tasks of the first array with their own ranges (a task that failed or was
#                 cancelled); its partial file is replaced
#   (no TASK)     ask `trazo merge` which passes are missing (every task must have ended) and render each
#                 missing range in a new task: what time limits or signals cut short
#   --split S     split each missing range into S tasks (ranges shorter than S passes into one per pass)
#   --time MIN    a new time limit for these tasks (default: the one submit.sh was given)
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"

usage() {  # $1: the exit status (0 for --help)
    sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2
    exit "${1:-2}"
}
[ $# -ge 1 ] || usage
case $1 in -h | --help) usage 0 ;; esac
load_render "$1"
shift
task_ids=() split=1 time_min=$TIME_MIN
while [ $# -gt 0 ]; do
    case $1 in
        --split) split=${2:?}; shift 2 ;;
        --time) time_min=${2:?}; shift 2 ;;
        *) [[ $1 =~ ^[0-9]+$ ]] || die "unknown argument $1"; task_ids+=("$1"); shift ;;
    esac
done
[[ $split =~ ^[1-9][0-9]*$ ]] || die "--split $split: a positive number of tasks"
[ -z "$time_min" ] || [[ $time_min =~ ^[1-9][0-9]*$ ]] || die "--time $time_min: whole minutes"
need_tool sbatch
need_tool squeue

if [ ${#task_ids[@]} -gt 0 ]; then
    ranges=$render_dir/ranges.txt
    for t in "${task_ids[@]}"; do
        ((t < TASKS)) || die "task $t: the render has tasks 0 to $((TASKS - 1))"
        read -r first end <<<"$(sed -n "$((t + 1))p" "$ranges")"
        # A part inside the task's range from an earlier fill would overlap the rerun.
        shopt -s nullglob
        for part in "$render_dir"/parts/*-*.partial; do
            name=$(basename "$part" .partial)
            a=${name%-*} b=${name#*-}
            [ "$name" = "$first-$end" ] && continue
            if ((a < end && b > first)); then
                die "$part overlaps task $t's passes $first:$end: remove it first, or fill only the missing passes with resubmit.sh $render_dir"
            fi
        done
    done
    spec=$(IFS=,; echo "${task_ids[*]}")
    what="task(s) $spec of the first array again"
else
    if [ -n "$(queued_jobs array)" ]; then
        die "tasks of this render are still queued or running (scripts/slurm/status.sh $render_dir); wait for them, or name the tasks to rerun"
    fi
    check=$(bash "$slurm_scripts/merge.sh" "$render_dir" --check 2>&1) && {
        echo "$check" >&2
        echo "resubmit.sh: nothing to render; merging" >&2
        exec bash "$slurm_scripts/merge.sh" "$render_dir"
    }
    missing=$(sed -n 's/.*passes \([0-9]*\):\([0-9]*\) are missing.*/\1 \2/p' <<<"$check")
    if [ -z "$missing" ]; then
        echo "$check" >&2
        die "the parts cannot be merged for another reason than missing passes (above)"
    fi
    n=1
    while [ -e "$render_dir/ranges-$n.txt" ]; do n=$((n + 1)); done
    ranges=$render_dir/ranges-$n.txt
    while read -r first end; do
        pieces=$split
        ((pieces > end - first)) && pieces=$((end - first))
        for ((i = 0; i < pieces; i++)); do
            echo "$((first + i * (end - first) / pieces)) $((first + (i + 1) * (end - first) / pieces))"
        done
    done <<<"$missing" >"$ranges"
    count=$(wc -l <"$ranges")
    spec=0-$((count - 1))
    what="$count task(s) for the missing passes $(awk '{ printf "%s%s:%s", (NR > 1 ? "," : ""), $1, $2 }' <<<"$missing")"
fi

# The merge jobs still waiting would wait forever on the failed task (afterok), or merge before the new tasks.
mapfile -t stale < <(queued_jobs merge | awk '$2 == "PENDING" { print $1 }')
[ ${#stale[@]} -eq 0 ] || scancel "${stale[@]}"

still=$(queued_jobs array | awk '{ print $1 }' | sort -u | paste -sd: -)
array=$(submit_tasks "$ranges" "$spec" "$time_min")
dependency=afterok:$array
[ -z "$still" ] || dependency="$dependency,afterany:$still"
merge=$(submit_merge "$dependency")

echo "trazo: job array $array: $what ($ranges)"
[ ${#stale[@]} -eq 0 ] || echo "trazo: cancelled the merge job(s) waiting on the earlier tasks: ${stale[*]}"
echo "trazo: merge job $merge runs when they succeed"
echo "trazo: image: $IMAGE"
echo "trazo: check: scripts/slurm/status.sh $render_dir"
