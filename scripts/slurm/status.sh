#!/usr/bin/env bash
# Where a render stands: its jobs still in the queue, the parts written, and the image, or, when every job has
# ended without one, the passes that are missing and the command that renders them.
# Usage: status.sh DIR
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"

[ $# -eq 1 ] || { echo "usage: status.sh DIR" >&2; exit 2; }
load_render "$1"
need_tool squeue

echo "render: $render_dir ($PASSES passes of $(basename "$SCENE") in $TASKS tasks)"
queue=$(squeue -h -u "$(id -un)" -o '%i %j %T %M %R' 2>/dev/null | awk -v ids="$(awk '{ print $2 }' "$render_dir/jobs.txt" 2>/dev/null | sort -u)" '
    BEGIN { n = split(ids, list, "\n"); for (i = 1; i <= n; i++) want[list[i]] = 1 }
    { id = $1; sub(/_.*/, "", id) } id in want')
if [ -n "$queue" ]; then
    echo "queued or running (job, name, state, time, reason):"
    sed 's/^/  /' <<<"$queue"
else
    echo "no job of this render is queued or running"
fi
shopt -s nullglob
parts=("$render_dir"/parts/*.partial)
echo "parts written: ${#parts[@]} ($(cd "$render_dir/parts" && ls -- *.partial 2>/dev/null | sed 's/\.partial$//' | sort -n | paste -sd' ' -))"
if [ -f "$IMAGE" ]; then
    echo "image: $IMAGE ($(date -r "$IMAGE" '+%F %T'))"
    [ -f "$render_dir/stats.json" ] && grep -E '"(spp|passes|missing|estimated_rel_error)"' "$render_dir/stats.json" | sed 's/^ */  /'
elif [ -z "$queue" ]; then
    echo "image: not written; what the merge says:"
    bash "$slurm_scripts/merge.sh" "$render_dir" --check 2>&1 | sed 's/^/  /' || true
else
    echo "image: not yet ($IMAGE)"
fi
