# shellcheck shell=bash
# Shared by submit.sh, resubmit.sh and status.sh (sourced; not run by the jobs themselves).
#
# A render directory holds:
#   render.conf        what every job needs: trazo, the scene, the passes, the options (bash, sourced)
#   ranges.txt         the pass ranges of the first job array, one "FIRST END" line per task (passes FIRST..END-1)
#   ranges-N.txt       the ranges of the N-th resubmission that filled missing passes
#   jobs.txt           every job submitted: "array JOBID RANGES_FILE TASKS" or "merge JOBID"
#   parts/FIRST-END.partial   what the task asked for FIRST:END wrote (fewer passes when a time limit stopped it)
#   logs/              the jobs' output
#   stats.json and the image, written by the merge

slurm_scripts=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

die() {
    echo "${0##*/}: $*" >&2
    exit 2
}

need_tool() {
    command -v "$1" >/dev/null 2>&1 || die "$1 not found: run this on a machine that submits Slurm jobs"
}

# The job id of `sbatch --parsable` output ("ID" or "ID;CLUSTER").
job_id_of() {
    local out=$1
    out=${out%%;*}
    [[ $out =~ ^[0-9]+$ ]] || return 1
    echo "$out"
}

# Seconds of rendering for a Slurm time limit of $1 minutes: a tenth less, at least 30 s less (scene loading,
# writing the partial), never below half. trazo stops there and writes its passes before Slurm's SIGTERM.
render_budget_s() {
    local limit=$(($1 * 60))
    local margin=$((limit / 10))
    ((margin < 30)) && margin=30
    ((margin > limit / 2)) && margin=$((limit / 2))
    echo $((limit - margin))
}

# Loads DIR/render.conf into this shell (TRAZO, SCENE, PASSES, TASKS, GPU, CPUS, TIME_MIN, IMAGE, EXTRA,
# SBATCH_ARGS).
load_render() {
    render_dir=$(cd "$1" 2>/dev/null && pwd) || die "$1: no such directory"
    [ -f "$render_dir/render.conf" ] || die "$render_dir: not a render directory (no render.conf; see submit.sh)"
    # shellcheck disable=SC1091
    source "$render_dir/render.conf"
}

# sbatch options every job of the render shares: partition, time limit, the user's --sbatch-arg options.
common_sbatch_args() {
    local time_min=$1
    local args=("${SBATCH_ARGS[@]}")
    [ -n "$time_min" ] && args+=(--time="$time_min")
    [ ${#args[@]} -eq 0 ] || printf '%s\n' "${args[@]}"
}

# Submits a job array of task.sh over the ranges file $1 (array spec $2, e.g. 0-3 or 2,5), time limit $3 minutes
# (empty: the partition's). Prints the job id; records it in jobs.txt.
submit_tasks() {
    local ranges=$1 spec=$2 time_min=$3
    local args=() budget=
    mapfile -t args < <(common_sbatch_args "$time_min")
    [ -n "$time_min" ] && budget=$(render_budget_s "$time_min")
    if [ "$GPU" = 1 ]; then
        args+=(--gres=gpu:1 --cpus-per-task="$CPUS")
    else
        args+=(--cpus-per-task="$CPUS")
    fi
    local out id
    out=$(sbatch --parsable --job-name="trazo-$(basename "$SCENE" .scene)" --array="$spec" \
        --output="$render_dir/logs/task-%A_%a.log" "${args[@]}" \
        "$slurm_scripts/task.sh" "$render_dir" "$ranges" "$budget") || die "sbatch refused the job array"
    id=$(job_id_of "$out") || die "unexpected sbatch output: $out"
    echo "array $id $ranges $spec" >>"$render_dir/jobs.txt"
    echo "$id"
}

# Submits the merge job with dependency $1 (e.g. afterok:123). Prints the job id; records it in jobs.txt.
submit_merge() {
    local dependency=$1
    local args=() out id
    mapfile -t args < <(common_sbatch_args "$TIME_MIN")
    out=$(sbatch --parsable --job-name=trazo-merge --dependency="$dependency" \
        --output="$render_dir/logs/merge-%j.log" "${args[@]}" \
        "$slurm_scripts/merge.sh" "$render_dir") || die "sbatch refused the merge job"
    id=$(job_id_of "$out") || die "unexpected sbatch output: $out"
    echo "merge $id" >>"$render_dir/jobs.txt"
    echo "$id"
}

# "JOBID STATE" of this render's jobs still known to squeue (array tasks by their array's id), one per line.
queued_jobs() {
    local kind=$1  # array or merge
    local ids
    ids=$(awk -v k="$kind" '$1 == k { print $2 }' "$render_dir/jobs.txt" 2>/dev/null | sort -u)
    [ -n "$ids" ] || return 0
    # %F: the array's job id (the job's own for a plain job), as sbatch printed it.
    squeue -h -u "$(id -un)" -o '%F %T' 2>/dev/null | awk -v ids="$ids" '
        BEGIN { n = split(ids, list, "\n"); for (i = 1; i <= n; i++) want[list[i]] = 1 }
        $1 in want' | sort -u
}
