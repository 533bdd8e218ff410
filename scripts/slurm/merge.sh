#!/usr/bin/env bash
# Merges a render directory's parts into its image and stats.json (`trazo merge`). The merge job of submit.sh
# runs it; run it by hand after resubmitting or to see what is missing. Status 2 when passes are missing or
# repeated (trazo names their ranges; nothing is written), 0 when the image is written.
# Usage: merge.sh DIR [--check] [--allow-gaps]
#   --check       report what is missing without writing the image (a scratch merge, deleted)
#   --allow-gaps  write the image of the passes there are, naming the missing ones
set -uo pipefail
[ $# -ge 1 ] || { echo "usage: merge.sh DIR [--check] [--allow-gaps]" >&2; exit 2; }
dir=$(cd "$1" 2>/dev/null && pwd) || { echo "merge.sh: $1: no such directory" >&2; exit 2; }
shift
check=0
gaps=()
for arg in "$@"; do
    case $arg in
        --check) check=1 ;;
        --allow-gaps) gaps=(--allow-gaps) ;;
        *) echo "merge.sh: unknown option $arg" >&2; exit 2 ;;
    esac
done
[ -f "$dir/render.conf" ] || { echo "merge.sh: $dir: not a render directory (no render.conf)" >&2; exit 2; }
# shellcheck disable=SC1091
source "$dir/render.conf"

shopt -s nullglob
parts=("$dir"/parts/*.partial)
if [ ${#parts[@]} -eq 0 ]; then
    echo "trazo: merge: passes 0:$PASSES are missing (no part in $dir/parts yet)" >&2
    exit 2
fi

image=$IMAGE
stats=(--stats "$dir/stats.json")
if [ "$check" = 1 ]; then
    image=$(mktemp "$dir/.check-XXXXXX.pfm")
    stats=()
    trap 'rm -f "$image"' EXIT
fi
# --passes: the whole render, so that a part missing at the end is named too.
"$TRAZO" merge "${parts[@]}" -o "$image" "${stats[@]}" --passes "0:$PASSES" "${gaps[@]}"
status=$?
if [ $status -eq 0 ] && [ "$check" = 1 ]; then
    echo "merge.sh: nothing is missing: $dir/parts hold passes 0:$PASSES" >&2
elif [ $status -eq 0 ]; then
    echo "merge.sh: wrote $IMAGE and $dir/stats.json" >&2
elif [ $status -eq 2 ]; then
    echo "merge.sh: render the missing passes with: scripts/slurm/resubmit.sh $dir" >&2
fi
exit $status
