#!/usr/bin/env bash
# One task of a Trazo job array (submitted by submit.sh or resubmit.sh; sbatch copies this script, so it reads
# everything else from the render directory). Renders the passes of line SLURM_ARRAY_TASK_ID+1 of RANGES into
# DIR/parts/FIRST-END.partial. With a time budget trazo stops there and writes the passes it rendered; on
# Slurm's SIGTERM (scancel, the time limit) it finishes the current batch, writes them and exits 3.
# Usage: task.sh DIR RANGES [BUDGET_SECONDS]
set -euo pipefail
dir=$1
ranges=$2
budget=${3:-}
# shellcheck disable=SC1091
source "$dir/render.conf"

task=${SLURM_ARRAY_TASK_ID:?task.sh runs as a task of a Slurm job array}
line=$(sed -n "$((task + 1))p" "$ranges")
read -r first end <<<"$line"
if ! [[ ${first:-} =~ ^[0-9]+$ && ${end:-} =~ ^[0-9]+$ ]]; then
    echo "task.sh: $ranges has no range for task $task" >&2
    exit 2
fi

args=(--render "$SCENE" --passes "$first:$end" --partial "$dir/parts/$first-$end.partial" --quiet)
if [ "$GPU" = 1 ]; then
    args+=(--backend cuda)
else
    # The CPUs Slurm gave the task, not all the node's cores.
    args+=(--backend cpu --threads "${SLURM_CPUS_PER_TASK:-1}")
fi
[ -n "$budget" ] && args+=(--time "$budget")

echo "trazo task $task of job ${SLURM_ARRAY_JOB_ID:-?}: passes $first:$end on $(hostname)"
echo "$(printf '%q ' "$TRAZO" "${args[@]}" "${EXTRA[@]}")"
# exec: trazo itself receives Slurm's signals and its status is the task's.
exec "$TRAZO" "${args[@]}" "${EXTRA[@]}"
