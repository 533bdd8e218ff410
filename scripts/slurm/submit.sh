#!/usr/bin/env bash
# Submits a Trazo render to Slurm: a job array with one pass range per task, and a merge job that runs when
# every task succeeded (afterok) and writes the image. Prints the job ids and where the image will be.
#
# Usage: submit.sh SCENE --passes N --tasks K [options] [-- extra trazo options]
#   --passes N        passes per pixel of the whole render (the image equals `trazo --render SCENE --passes 0:N`)
#   --tasks K         array tasks; task i renders passes floor(i*N/K) .. floor((i+1)*N/K)-1
#   --gpu             one GPU per task (--gres=gpu:1, trazo --backend cuda); CPU tasks otherwise
#   --cpus C          CPUs per task (--cpus-per-task, trazo --threads for CPU tasks; default 1)
#   --time MIN        Slurm time limit of each job in minutes; trazo renders for a little less and hands back
#                     the passes it rendered (see docs/CLUSTER.md)
#   --partition P     Slurm partition
#   --sbatch-arg ARG  any other sbatch option for every job (repeatable), e.g. --sbatch-arg=--account=lab
#   --out DIR         render directory, on a file system the nodes share (default ./trazo-SCENE-DATE)
#   --image FILE      the merged image, relative to DIR unless absolute (default image.exr; pfm keeps floats)
#   --trazo PATH      the trazo binary the nodes run (default: $TRAZO, else trazo on PATH, else build/app/trazo)
# Extra trazo options after -- (e.g. -- --seed 7 --width 1920 --height 1080) go to every task.
set -euo pipefail
# shellcheck source=common.sh
source "$(dirname "$0")/common.sh"

usage() {  # $1: the exit status (0 for --help)
    sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2
    exit "${1:-2}"
}

scene='' passes='' tasks='' gpu=0 cpus=1 time_min='' partition='' out='' image=image.exr trazo=${TRAZO:-}
sbatch_args=()
extra=()
while [ $# -gt 0 ]; do
    case $1 in
        --passes) passes=${2:?}; shift 2 ;;
        --tasks) tasks=${2:?}; shift 2 ;;
        --gpu) gpu=1; shift ;;
        --cpus) cpus=${2:?}; shift 2 ;;
        --time) time_min=${2:?}; shift 2 ;;
        --partition) partition=${2:?}; shift 2 ;;
        --sbatch-arg) sbatch_args+=("${2:?}"); shift 2 ;;
        --sbatch-arg=*) sbatch_args+=("${1#--sbatch-arg=}"); shift ;;
        --out) out=${2:?}; shift 2 ;;
        --image) image=${2:?}; shift 2 ;;
        --trazo) trazo=${2:?}; shift 2 ;;
        -h | --help) usage 0 ;;
        --) shift; extra=("$@"); break ;;
        -*) die "unknown option $1 (extra trazo options go after --)" ;;
        *) [ -z "$scene" ] || die "one scene only ($scene, $1)"; scene=$1; shift ;;
    esac
done
[ -n "$scene" ] && [ -n "$passes" ] && [ -n "$tasks" ] || usage
[ -f "$scene" ] && [ -r "$scene" ] || die "$scene: no such scene file"
[[ $passes =~ ^[1-9][0-9]*$ ]] || die "--passes $passes: a positive number of passes"
[[ $tasks =~ ^[1-9][0-9]*$ ]] || die "--tasks $tasks: a positive number of tasks"
((tasks <= passes)) || die "--tasks $tasks: more tasks than the $passes passes to share"
[[ $cpus =~ ^[1-9][0-9]*$ ]] || die "--cpus $cpus: a positive number of CPUs"
[ -z "$time_min" ] || [[ $time_min =~ ^[1-9][0-9]*$ ]] || die "--time $time_min: whole minutes"
for option in "${extra[@]}"; do
    case $option in
        --passes* | --partial* | --spp* | --time* | --backend* | --threads* | -o | --output* | --target-error*)
            die "$option is set by the scripts (use --passes, --time, --gpu, --cpus of submit.sh)" ;;
    esac
done

if [ -z "$trazo" ]; then
    if command -v trazo >/dev/null 2>&1; then
        trazo=$(command -v trazo)
    else
        trazo=$slurm_scripts/../../build/app/trazo
    fi
fi
[ -x "$trazo" ] || die "$trazo: no trazo binary there (give --trazo PATH)"
trazo=$(cd "$(dirname "$trazo")" && pwd)/$(basename "$trazo")
scene=$(cd "$(dirname "$scene")" && pwd)/$(basename "$scene")
need_tool sbatch
need_tool squeue

[ -n "$out" ] || out=trazo-$(basename "$scene" .scene)-$(date +%Y%m%d-%H%M%S)
[ -e "$out/render.conf" ] && die "$out already holds a render (pick another --out, or resubmit.sh $out)"
mkdir -p "$out/parts" "$out/logs"
out=$(cd "$out" && pwd)
[[ $image = /* ]] || image=$out/$image
[ -n "$partition" ] && sbatch_args=(--partition="$partition" "${sbatch_args[@]}")

{
    echo "# Written by scripts/slurm/submit.sh; read by every job of this render."
    printf 'TRAZO=%q\nSCENE=%q\nPASSES=%s\nTASKS=%s\nGPU=%s\nCPUS=%s\nTIME_MIN=%s\nIMAGE=%q\n' \
        "$trazo" "$scene" "$passes" "$tasks" "$gpu" "$cpus" "$time_min" "$image"
    EXTRA=("${extra[@]}")
    SBATCH_ARGS=("${sbatch_args[@]}")
    # -g: load_render sources this inside a function.
    declare -p EXTRA SBATCH_ARGS | sed 's/^declare -a /declare -ga /'
} >"$out/render.conf"
for ((i = 0; i < tasks; i++)); do
    echo "$((i * passes / tasks)) $(((i + 1) * passes / tasks))"
done >"$out/ranges.txt"

load_render "$out"
array=$(submit_tasks "$render_dir/ranges.txt" "0-$((tasks - 1))" "$TIME_MIN")
merge=$(submit_merge "afterok:$array")

each="$CPUS CPU"
((CPUS > 1)) && each+=s
[ "$GPU" = 1 ] && each="1 GPU, $each"
echo "trazo: job array $array: $tasks tasks of $passes passes of $(basename "$scene") ($each each)"
echo "trazo: merge job $merge runs when they all succeed"
echo "trazo: image: $IMAGE"
echo "trazo: check: scripts/slurm/status.sh $render_dir"
