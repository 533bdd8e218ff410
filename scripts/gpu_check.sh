#!/usr/bin/env bash
# gpu_check.sh — the one-call device check of trazo's CUDA backend (issue 14, item 5).
#
# Runs in the repository root of a copy of the tree on a GPU machine (H100/H200: nvcc and CMake, but no apt,
# no internet, none of our Debian libraries), with gpu-carry/ beside the tree, made here by
# scripts/gpu_prepare.sh, which prints the device-tool call (with the unpacking of gpu-carry.tar.xz first when
# the folder is too big to carry as it is):
#     run(command: "bash scripts/gpu_check.sh", carry: ["gpu-carry"], timeout_s: 540)
# Writes to $OUT (default: a new temp dir), at most the 8 files the tool brings back:
#   summary.md        one line per step: ran / skipped — reason / failed — reason (read this first)
#   gpu_check.log     everything, in order (the render smoke, the EGL probe, the viewer, the environment)
#   nvidia-smi.txt    nvidia-smi, its CSV query and the start of nvidia-smi -q
#   cuda_tests.log    trazo_tests on the CUDA suites
#   memcheck.log      compute-sanitizer memcheck of small renders of five seed scenes
#   scene_timings.md  every seed scene on CUDA beside the CPU and the thesis's GTX 560, and their image error;
#                     then the register cap's trade (register_cap)
#   bvh_bench.txt     bvh_bench, with its GPU line (kernel time of primary, shadow and random rays)
#   artifacts.tar.gz  stats JSONs, the timings CSV, the test XML, the smoke image
# Steps, cheap and important first, each under its own timeout and all under GPU_CHECK_BUDGET seconds
# (default 450, so the whole script stays under 8 minutes): nvidia_smi, cuda_render, egl_interop,
# cuda_tests, bvh_bench, scene_timings, memcheck, register_cap. Without a GPU (no nvidia-smi, or it lists none) or without
# the carry folder every step is skipped with its reason and the script exits 0; with them, it exits 1 if a
# step failed.
# Environment: OUT, GPU_CARRY (default <repo>/gpu-carry), GPU_CHECK_BUDGET, GPU_CHECK_ONLY="step,step"
# (a rerun of some steps), GPU_CHECK_TEST_FILTER (gtest filter of the CUDA suites), GPU_CHECK_NO_GPU=1
# (behave as if there were no GPU: the self-test), SIZE (image side of scene_timings, default 512 as the thesis).
set -euo pipefail
export LC_ALL=C

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$repo"
carry=${GPU_CARRY:-$repo/gpu-carry}
case $carry in /*) ;; *) carry=$repo/$carry ;; esac
OUT=${OUT:-$(mktemp -d /tmp/gpu_check.XXXXXX)}
mkdir -p "$OUT"
OUT=$(cd "$OUT" && pwd)
start=$(date +%s)
deadline=$(( start + ${GPU_CHECK_BUDGET:-450} ))
work=$(mktemp -d /tmp/gpu_check_work.XXXXXX)
trap 'rm -rf "$work"' EXIT
art=$work/artifacts
mkdir -p "$art"
log=$OUT/gpu_check.log
summary=$OUT/summary.md
: >"$log"
lines=()
failures=0

say() { printf '%s\n' "$*" | tee -a "$log"; }
header() { say ""; say "=== $1 ($(( $(date +%s) - start )) s elapsed, $(( deadline - $(date +%s) )) s left) ==="; }
# record STEP STATUS DETAIL: one summary line; STATUS is ran, skipped or failed.
record() {
    lines+=("- $1: $2 — $3")
    say "[$1] $2 — $3"
    if [ "$2" = failed ]; then failures=$(( failures + 1 )); fi
}
wanted() { [ -z "${GPU_CHECK_ONLY:-}" ] || [[ ",$GPU_CHECK_ONLY," == *",$1,"* ]]; }
# cap SECONDS: SECONDS, or less when the overall budget is nearer (10 s kept for the summary); 0 when under 5.
cap() {
    local left=$(( deadline - $(date +%s) - 10 ))
    if (( left < 5 )); then echo 0; elif (( left < $1 )); then echo "$left"; else echo "$1"; fi
}
# limited SECONDS FILE CMD...: CMD under timeout (its whole process group), output appended to FILE; prints
# nothing, returns CMD's status (124 or 137 on timeout).
limited() {
    local t=$1 f=$2 rc=0
    shift 2
    printf '$ %s\n' "$*" >>"$f"
    ours timeout -k 5 "$t" "$@" >>"$f" 2>&1 </dev/null || rc=$?
    printf '[exit %s]\n' "$rc" >>"$f"
    return "$rc"
}
# ours CMD...: runs CMD with the carried libstdc++ first on the library path when the machine's is too old.
cxx_fallback=""
ours() { if [ -n "$cxx_fallback" ]; then LD_LIBRARY_PATH="$carry/lib-cxx${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" "$@"; else "$@"; fi; }
# The stats JSON's flat "KEY": value lines: bench/peers/common.sh's json_field (also used by thesis_table.sh).
# shellcheck source=/dev/null
if [ -f "$repo/bench/peers/common.sh" ]; then source "$repo/bench/peers/common.sh"; fi
if ! declare -F json_field >/dev/null; then
    json_field() { sed -n "s/^ *\"$2\": *\"\{0,1\}\([^\",]*\)\"\{0,1\},\{0,1\} *$/\1/p" "$1" | head -n 1; }
fi
jf() { if [ -f "$1" ]; then json_field "$1" "$2" || true; fi; }
seconds_since() { awk -v a="$1" -v b="$(date +%s.%N)" 'BEGIN {printf "%.2f", b - a}'; }

say "trazo gpu_check: repo $repo, OUT $OUT, carry $carry, budget ${GPU_CHECK_BUDGET:-450} s, $(date -u +%Y-%m-%dT%H:%M:%SZ)"
{
    uname -a
    grep -h '^PRETTY_NAME' /etc/os-release 2>/dev/null || true
    ldd --version 2>&1 | head -n 1 || true
    echo "cores: $(nproc)"
    for t in nvidia-smi nvcc compute-sanitizer ncu; do printf '%s: %s\n' "$t" "$(command -v "$t" || echo -)"; done
} >>"$log" 2>&1

# --- what the steps need: a GPU, the carry folder, binaries that start here ---------------------------------
no_gpu=""
if [ "${GPU_CHECK_NO_GPU:-0}" = 1 ]; then
    no_gpu="no GPU (GPU_CHECK_NO_GPU=1 set)"
elif ! command -v nvidia-smi >/dev/null 2>&1; then
    no_gpu="no GPU (nvidia-smi not found)"
elif ! timeout 20 nvidia-smi -L >"$work/smi_l.txt" 2>&1 || ! grep -q '^GPU [0-9]' "$work/smi_l.txt"; then
    no_gpu="no GPU (nvidia-smi lists none: $(head -c 200 "$work/smi_l.txt" | tr '\n' ' '))"
fi
no_carry=""
if [ ! -x "$carry/bin/trazo" ]; then
    no_carry="no carry folder, run scripts/gpu_prepare.sh (no ${carry#"$repo"/}/bin/trazo)"
fi
no_setup=""
B=$carry/bin
GLIBC_NEEDED="" SRC_BAKED="" BIN_BAKED="" REV="" CUDA_ARCHS=""
# shellcheck disable=SC1091
if [ -z "$no_carry" ] && [ -f "$carry/manifest.env" ]; then . "$carry/manifest.env"; fi
if [ -z "$no_gpu" ] && [ -z "$no_carry" ]; then
    header setup
    have_glibc=$(ldd --version 2>&1 | head -n 1 | grep -o '[0-9]*\.[0-9]*$' || true)
    say "binaries at ${REV:-?} for sm_${CUDA_ARCHS:-?}, need glibc ${GLIBC_NEEDED:-?}; this machine has glibc ${have_glibc:-?}"
    if [ -n "$GLIBC_NEEDED" ] && [ -n "$have_glibc" ] \
       && [ "$(printf '%s\n%s\n' "$GLIBC_NEEDED" "$have_glibc" | sort -V | head -n 1)" != "$GLIBC_NEEDED" ]; then
        no_setup="the carried binaries need glibc $GLIBC_NEEDED, this machine has $have_glibc (build them on an older system)"
    else
        # The system's libstdc++ first (newer on most machines); the carried one only if it is too old.
        if ! "$B/trazo" --version >"$work/version.txt" 2>&1 && grep -q 'GLIBCXX\|CXXABI\|GCC_' "$work/version.txt"; then
            cxx_fallback=1
            say "the system's libstdc++ is too old: using the carried lib-cxx/ for our programs"
        fi
        if ! ours "$B/trazo" --version >"$work/version.txt" 2>&1; then
            no_setup="the carried trazo does not start here: $(head -c 300 "$work/version.txt" | tr '\n' ' ')"
        fi
        cat "$work/version.txt" >>"$log"
        for b in "$B"/*; do ours ldd "$b" 2>&1 | grep 'not found' | sed "s|^|$(basename "$b"): |" >>"$log" || true; done
    fi
    if [ -z "$no_setup" ]; then
        # trazo_tests and bvh_bench have the build machine's source dir and trazo path compiled in.
        if [ -n "$SRC_BAKED" ] && [ "$(readlink -f "$SRC_BAKED" 2>/dev/null || true)" != "$repo" ]; then
            if [ ! -e "$SRC_BAKED" ]; then
                if mkdir -p "$(dirname "$SRC_BAKED")" && ln -s "$repo" "$SRC_BAKED"; then say "linked $SRC_BAKED -> $repo"
                else say "WARNING: could not link $SRC_BAKED -> $repo: the tests will not find the scenes"; fi
            else
                say "WARNING: $SRC_BAKED exists here and is not this tree: the tests read scenes from there"
            fi
        fi
        if [ -n "$BIN_BAKED" ] && [ ! -x "$BIN_BAKED" ]; then
            if mkdir -p "$(dirname "$BIN_BAKED")" && ln -sf "$B/trazo" "$BIN_BAKED"; then say "linked $BIN_BAKED -> $B/trazo"
            else say "WARNING: could not link $BIN_BAKED -> $B/trazo: the CLI tests will not find trazo"; fi
        fi
        # The git-ignored scene assets did not travel with the tree.
        for f in "$carry"/assets/*; do
            [ -e "$f" ] || continue
            [ -e "scenes/assets/$(basename "$f")" ] || cp "$f" scenes/assets/
        done
        [ "${REV:-x}" = "$(git rev-parse --short=12 HEAD 2>/dev/null || echo "${REV:-x}")" ] \
            || say "WARNING: the binaries were built at ${REV:-?}, the tree here is at $(git rev-parse --short=12 HEAD)"
    fi
fi
# needs WHAT...: the reason a step cannot run (empty when it can): gpu, carry (the carry folder and binaries
# that start here).
needs() {
    local why=() w
    for w in "$@"; do
        case $w in
            gpu) [ -z "$no_gpu" ] || why+=("$no_gpu") ;;
            carry) if [ -n "$no_carry" ]; then why+=("$no_carry"); elif [ -n "$no_setup" ]; then why+=("$no_setup"); fi ;;
        esac
    done
    local IFS=';'
    echo "${why[*]}"
}
# setup's own line: the carried binaries start here, with the paths they have compiled in linked to this tree.
if [ -n "$no_gpu" ] || [ -n "$no_carry" ]; then
    reason=$(needs gpu carry)
    lines+=("- setup: skipped — ${reason//;/; }")
elif [ -n "$no_setup" ]; then
    record setup failed "$no_setup"
else
    lines+=("- setup: ran — binaries at ${REV:-?} (sm_${CUDA_ARCHS:-?}) start here${cxx_fallback:+ with the carried libstdc++}")
fi
# step NAME NEEDS...: true when the step should run; otherwise records why it is skipped.
step() {
    local name=$1 why
    shift
    if ! wanted "$name"; then lines+=("- $name: skipped — not in GPU_CHECK_ONLY ($GPU_CHECK_ONLY)"); return 1; fi
    header "$name"
    why=$(needs "$@")
    if [ -n "$why" ]; then record "$name" skipped "${why//;/; }"; return 1; fi
    return 0
}

# --- nvidia_smi --------------------------------------------------------------------------------------------
if step nvidia_smi gpu; then
    smi=$OUT/nvidia-smi.txt
    limited 20 "$smi" nvidia-smi || true
    limited 20 "$smi" nvidia-smi --query-gpu=name,driver_version,memory.total,compute_cap,clocks.max.sm,clocks.max.mem,power.limit --format=csv || true
    { echo '$ nvidia-smi -q | head -n 200'; timeout 20 nvidia-smi -q 2>&1 | head -n 200; } >>"$smi" || true
    gpu=$(timeout 20 nvidia-smi --query-gpu=name,driver_version,memory.total,compute_cap --format=csv,noheader 2>/dev/null | head -n 1 || true)
    if [ -n "$gpu" ]; then record nvidia_smi ran "$gpu (name, driver, memory, compute capability)"
    else record nvidia_smi failed "nvidia-smi lists a GPU but its query failed (nvidia-smi.txt)"; fi
fi

# --- cuda_render: one small render on the CUDA backend (the tests below must not skip if this works) ---------
cuda_ok=0
if step cuda_render gpu carry; then
    t0=$(date +%s.%N)
    rc=0
    limited "$(cap 60)" "$work/smoke.log" "$B/trazo" --render scenes/scene1_area.scene --backend cuda --width 96 \
        --height 64 --spp 1 -o "$art/smoke_cuda.png" --stats "$art/smoke_cuda.json" || rc=$?
    wall=$(seconds_since "$t0")
    cat "$work/smoke.log" >>"$log"
    if [ $rc = 0 ] && [ "$(jf "$art/smoke_cuda.json" backend)" = cuda ]; then
        cuda_ok=1
        record cuda_render ran "scene1_area 96x64 on $(jf "$art/smoke_cuda.json" device): upload $(jf "$art/smoke_cuda.json" upload_s) s, render $(jf "$art/smoke_cuda.json" render_s) s, process ${wall} s"
    else
        record cuda_render failed "exit $rc: $(grep -v '^\$\|^\[exit' "$work/smoke.log" | grep -m2 -i 'error\|cuda\|fault' | tr '\n' ' ' | cut -c1-300 || true) (gpu_check.log)"
    fi
fi

# --- egl_interop: the viewer's CUDA-GL path on a headless EGL context ---------------------------------------
if step egl_interop gpu carry; then
    if [ ! -x "$B/egl_interop_probe" ]; then
        record egl_interop skipped "the carry folder has no egl_interop_probe (gpu_prepare.sh could not build it)"
    else
        # The NVIDIA driver's EGL vendor library and its glvnd JSON (the driver is mounted at /usr/local/nvidia
        # on the lent machines); the carried glvnd loaders only if the machine has no libEGL.so.1.
        extra=""
        for d in /usr/local/nvidia/lib64 /usr/local/nvidia/lib; do [ -d "$d" ] && extra=${extra:+$extra:}$d; done
        if ! ldconfig -p 2>/dev/null | grep -q 'libEGL\.so\.1 ' && ! ls /usr/local/nvidia/lib64/libEGL.so.1 >/dev/null 2>&1; then
            extra=${extra:+$extra:}$carry/lib-gl
        fi
        vendor=${__EGL_VENDOR_LIBRARY_FILENAMES:-}
        if [ -z "$vendor" ]; then
            for j in /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json /usr/share/glvnd/egl_vendor.d/10_nvidia.json \
                     /etc/glvnd/egl_vendor.d/10_nvidia.json; do
                if [ -f "$j" ]; then vendor=$j; break; fi
            done
        fi
        f=$work/egl.log
        echo "EGL vendor file: ${vendor:-none}; extra library path: ${extra:-none}" >"$f"
        rc=0
        ( if [ -n "$vendor" ]; then export __EGL_VENDOR_LIBRARY_FILENAMES=$vendor; fi
          export LD_LIBRARY_PATH=${extra}${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
          limited "$(cap 60)" "$f" "$B/egl_interop_probe" ) || rc=$?
        # The viewer itself needs an X display (GLFW 3.3): without one it must say so in one line and exit 1.
        vrc=0
        ( unset DISPLAY WAYLAND_DISPLAY; limited "$(cap 20)" "$work/viewer.log" "$B/trazo" scenes/scene1_point.scene \
              --backend cuda --frames 2 --screenshot "$work/viewer.png" ) || vrc=$?
        cat "$f" "$work/viewer.log" >>"$log"
        cp "$f" "$art/egl_interop.log"
        viewer="viewer without a display: exit $vrc, '$(grep -v '^\$\|^\[exit' "$work/viewer.log" | head -n 1 | cut -c1-120)'"
        gl=$(grep -m1 '^GL:' "$f" | cut -c1-160 || true)
        case $rc in
            0) timing=$(grep -m1 'timing' "$f" | sed 's/^ *//' || true)
               record egl_interop ran "$(grep -m1 'checks, ' "$f" || true); ${gl:-no GL line}; ${timing:+$timing; }$viewer" ;;
            77) record egl_interop skipped "$(grep -m1 '^SKIP' "$f" || echo 'the probe found nothing to check'); $viewer" ;;
            124|137) record egl_interop failed "the probe timed out; $viewer" ;;
            *) record egl_interop failed "probe exit $rc: $(grep 'FAIL' "$f" | head -n 3 | tr '\n' ' ')${gl}; $viewer" ;;
        esac
    fi
fi

# --- cuda_tests ----------------------------------------------------------------------------------------------
# gtest_count FILE PATTERN: the number in gtest's "[  PASSED  ] N tests" style line (0 when absent).
# (The per-test "[  SKIPPED ] Suite.Name" lines have no count, so " test" is required after the number.)
gtest_count() { grep -o "^\[  $2 *\] [0-9][0-9]* test" "$1" 2>/dev/null | tail -n 1 | grep -o '[0-9][0-9]*' || echo 0; }
if step cuda_tests gpu carry; then
    filter=${GPU_CHECK_TEST_FILTER:-*Cuda*:*RayQuer*:*Gpu*:*GPU*}
    f=$OUT/cuda_tests.log
    t=$(cap 150)
    rc=0
    limited "$t" "$f" "$B/trazo_tests" --gtest_filter="$filter" --gtest_output="xml:$art/cuda_tests.xml" || rc=$?
    total=$(grep -o '^\[==========\] [0-9]* tests\? from .* ran' "$f" | grep -o '[0-9]*' | head -n 1 || true)
    passed=$(gtest_count "$f" PASSED)
    skipped=$(gtest_count "$f" SKIPPED)
    failed=$(gtest_count "$f" FAILED)
    nodev=$(grep -c 'no CUDA device' "$f" || true)
    counts="${total:-0} tests matching '$filter': $passed passed, $skipped skipped, $failed failed"
    names=$(grep '^\[  FAILED  \] [A-Za-z]' "$f" | sed 's/^\[  FAILED  \] //; s/ (.*//; s/,.*//' | sort -u | head -n 8 | tr '\n' ' ' || true)
    if [ $rc = 124 ] || [ $rc = 137 ]; then record cuda_tests failed "timed out after $t s ($counts)"
    elif [ -z "$total" ] && [ $rc != 0 ]; then
        record cuda_tests failed "trazo_tests stopped with exit $rc in $(grep '^\[ RUN      \]' "$f" | tail -n 1 | sed 's/^\[ RUN      \] //' || true) (cuda_tests.log)"
    elif [ "${total:-0}" = 0 ]; then record cuda_tests failed "no test matched '$filter' (exit $rc)"
    elif [ "$failed" != 0 ] || [ $rc != 0 ]; then record cuda_tests failed "$counts: $names"
    elif [ $cuda_ok = 1 ] && [ "$skipped" = "$total" ]; then
        record cuda_tests failed "all $total skipped although a CUDA render works (cuda_tests.log)"
    elif [ $cuda_ok = 1 ] && [ "$nodev" != 0 ]; then
        record cuda_tests failed "$counts; $nodev skip messages say 'no CUDA device' although a CUDA render works"
    else record cuda_tests ran "$counts"; fi
fi

# --- bvh_bench: its GPU line ----------------------------------------------------------------------------------
if step bvh_bench gpu carry; then
    f=$OUT/bvh_bench.txt
    rc=0
    limited "$(cap 90)" "$f" "$B/bvh_bench" --no-build --repeat 3 --threads "$(nproc)" || rc=$?
    gpuline=$(grep -E '^GPU|^== |^  (primary|shadow|random): ' "$f" | sed 's/^ *//' | tr '\n' ' ' | cut -c1-700 || true)
    if [ $rc != 0 ]; then record bvh_bench failed "exit $rc: $gpuline"
    elif grep -q '^GPU: not measured' "$f"; then record bvh_bench failed "no GPU line: $(grep -m1 '^GPU: not measured' "$f")"
    else record bvh_bench ran "$gpuline"; fi
fi

# --- scene_timings: every seed scene on CUDA, beside the CPU here and the thesis's GTX 560 ----------------------
if step scene_timings gpu carry; then
    size=${SIZE:-512}
    csv=bench/peers/thesis_results.csv   # the thesis's times (a copy of the seed's results.csv)
    md=$OUT/scene_timings.md
    tcsv=$art/scene_timings.csv
    threads=$(nproc)
    # Rows as thesis_table.sh takes them: scene file, variant, GTX 560 exec_s, for the rows at the file's own
    # settings (not "instead of"); then any scene the table lacks.
    rows=$work/rows.tsv
    if [ -f "$csv" ]; then awk -F, 'NR > 1 && $9 != "" && $11 !~ /instead of/ { print $9 "\t" $2 "\t" $7 }' "$csv" >"$rows"
    else : >"$rows"; fi
    for s in scenes/*.scene; do
        b=$(basename "$s")
        grep -q "^$b	" "$rows" || printf '%s\t%s\t\n' "$b" "(not in the thesis table)" >>"$rows"
    done
    echo "scene_file,variant,gtx560_s,cuda_render_s,cuda_passes,cuda_mrays_s,cuda_wall_s,cpu_render_s,cpu_mrays_s,speed_vs_gtx560,cuda_over_cpu,rel_error_cpu_vs_cuda" >"$tcsv"
    ran=0 bad=0 notrun=0
    step_end=$(( $(date +%s) + $(cap 150) ))
    while IFS=$'\t' read -r file variant gtx; do
        name=${file%.scene}
        left=$(( step_end - $(date +%s) ))
        if (( left < 10 )); then notrun=$(( notrun + 1 )); echo "$file,$variant,$gtx,not run (out of time),,,,,,,," >>"$tcsv"; continue; fi
        t=$(( left < 40 ? left : 40 ))
        t0=$(date +%s.%N)
        rc=0
        limited "$t" "$log" "$B/trazo" --render "scenes/$file" --backend cuda --width "$size" --height "$size" --seed 1 \
            --quiet -o "$work/${name}_cuda.pfm" --stats "$art/${name}_cuda.json" || rc=$?
        wall=$(seconds_since "$t0")
        if [ $rc != 0 ]; then
            bad=$(( bad + 1 ))
            echo "$file,$variant,$gtx,failed (exit $rc),,,,,,,," >>"$tcsv"
            continue
        fi
        left=$(( step_end - $(date +%s) ))
        t=$(( left < 40 ? left : 40 ))
        crc=1
        if (( t >= 5 )); then
            crc=0
            limited "$t" "$log" "$B/trazo" --render "scenes/$file" --backend cpu --threads "$threads" --width "$size" \
                --height "$size" --seed 1 --quiet -o "$work/${name}_cpu.pfm" --stats "$art/${name}_cpu.json" || crc=$?
        fi
        g=$art/${name}_cuda.json c=$art/${name}_cpu.json
        gs=$(jf "$g" render_s) cs=""
        err=""
        if [ $crc = 0 ]; then
            cs=$(jf "$c" render_s)
            err=$(ours "$B/image_error" "$work/${name}_cuda.pfm" "$work/${name}_cpu.pfm" 2>/dev/null | awk '{print $2}' || true)
        fi
        awk -v f="$file" -v v="$variant" -v g="$gtx" -v gs="$gs" -v p="$(jf "$g" spp)" -v m="$(jf "$g" mrays_per_s)" \
            -v w="$wall" -v cs="$cs" -v cm="$(jf "$c" mrays_per_s)" -v e="$err" 'BEGIN {
              sp = (g != "" && gs > 0) ? sprintf("%.4g", g / gs) : "";
              r = (cs != "" && gs > 0) ? sprintf("%.4g", cs / gs) : "";
              printf "%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s\n", f, v, g, gs, p, m, w, cs, (cs == "" ? "" : cm), sp, r, e }' >>"$tcsv"
        ran=$(( ran + 1 ))
        rm -f "$work/${name}_cuda.pfm" "$work/${name}_cpu.pfm"
    done <"$rows"
    {
        echo "Every seed scene at its own settings, ${size}², seed 1, one render each: CUDA ($(jf "$art/$(head -n 1 "$rows" | cut -f1 | sed 's/\.scene$//')_cuda.json" device))"
        echo "beside the CPU ($threads threads here) and the thesis's GTX 560 (bench/peers/thesis_results.csv). Times: the stats'"
        echo "render_s (render phase only, as the thesis's exec_s); wall: the whole CUDA process (context, read, build, upload)."
        echo "rel. error: image_error of the CUDA image against the CPU's (RMSE over the reference's mean)."
        echo "$(date -u +%Y-%m-%d), $(uname -n), binaries at ${REV:-?}."
        echo
        echo "| scene file | variant | GTX 560 s | CUDA s | passes | CUDA Mrays/s | CUDA wall s | CPU s | CPU Mrays/s | speed vs GTX 560 | CPU/CUDA time | rel. error CPU vs CUDA |"
        echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
        tail -n +2 "$tcsv" | awk -F, '
            function n(x) { return (x ~ /^[0-9.eE+-]+$/) ? sprintf("%.4g", x) : x }
            { printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", $1, $2, $3, n($4), $5, n($6), $7,
                     n($8), n($9), ($10 == "" ? "" : $10 "×"), ($11 == "" ? "" : $11 "×"), n($12) }'
    } >"$md"
    # At a glance: the summed render times, the slowest scene against the GTX 560, the largest CPU/CUDA error.
    glance=$(tail -n +2 "$tcsv" | awk -F, '$4 ~ /^[0-9.eE+-]+$/ {
            g += $4; if ($8 != "") { c += $8; nc++ }
            if ($10 != "" && (ms == "" || $10 + 0 < ms + 0)) { ms = $10; mf = $1 }
            if ($12 != "" && (me == "" || $12 + 0 > me + 0)) { me = $12; ef = $1 } }
        END { printf "CUDA %.3g s in all, CPU %.3g s (%d scenes); slowest against the GTX 560: %s %s×; largest CPU/CUDA rel. error %s (%s)",
                     g, c, nc, mf, ms, me, ef }')
    detail="$ran scenes timed on CUDA and CPU at ${size}²: $glance (scene_timings.md)"
    (( bad == 0 )) || detail+="; $bad CUDA renders failed"
    (( notrun == 0 )) || detail+="; $notrun not run (out of time)"
    if (( bad > 0 )); then record scene_timings failed "$detail"; else record scene_timings ran "$detail"; fi
fi

# --- memcheck: compute-sanitizer on small renders of five seed scenes ------------------------------------------
if step memcheck gpu carry; then
    sanitizer=$(command -v compute-sanitizer || true)
    for s in /usr/local/cuda/bin/compute-sanitizer /usr/local/cuda/compute-sanitizer/compute-sanitizer; do
        if [ -z "$sanitizer" ] && [ -x "$s" ]; then sanitizer=$s; fi
    done
    if [ -z "$sanitizer" ]; then
        record memcheck skipped "compute-sanitizer not found (PATH, /usr/local/cuda)"
    else
        f=$OUT/memcheck.log
        : >"$f"
        # Area light + CSG, mesh + reflection, textures + normal map, refraction, indirect light + refraction.
        res="" bad=0 slow=0
        step_end=$(( $(date +%s) + $(cap 170) ))
        for s in scene3_csg_area scene5_bunny_reflect scene8_textured_mesh scene7_refract extra1_refract_indirect; do
            left=$(( step_end - $(date +%s) ))
            if (( left < 15 )); then res+=" $s:not-run(time)"; continue; fi
            rc=0
            limited "$(( left < 60 ? left : 60 ))" "$f" "$sanitizer" --tool memcheck --leak-check full --error-exitcode 86 \
                --print-limit 20 "$B/trazo" --render "scenes/$s.scene" --backend cuda --width 64 --height 48 --spp 2 \
                --quiet -o "$work/mc_$s.pfm" || rc=$?
            case $rc in 0) res+=" $s:ok" ;; 86) res+=" $s:ERRORS"; bad=$(( bad + 1 )) ;; 124|137) res+=" $s:timeout"; slow=$(( slow + 1 )) ;;
                        *) res+=" $s:exit$rc"; bad=$(( bad + 1 )) ;; esac
        done
        errs=$(grep -h -o 'ERROR SUMMARY: .*' "$f" | sort | uniq -c | awk '{ $1 = $1 "×"; print }' | tr '\n' ';' || true)
        if grep -q 'Device not supported\|Unable to find injection\|error 999' "$f"; then
            record memcheck skipped "compute-sanitizer cannot attach here: $(grep -m1 -o 'Device not supported\|Unable to find injection[^.]*\|error 999' "$f")"
        elif (( bad > 0 )); then
            record memcheck failed "64x48, 2 passes:$res [$errs] $(grep -m3 -E '^========= +(Invalid|Out of|Program hit|Leaked)' "$f" | tr '\n' ' ' || true)"
        else record memcheck ran "64x48, 2 passes, no errors$( (( slow == 0 )) || echo ", $slow timed out under the sanitizer (no verdict)"):$res [$errs]"; fi
    fi
fi

# --- register_cap: the render kernels at 128 registers (16 warps an SM, some spills) against uncapped ---------
# trazo is built with __launch_bounds__ for two 256-thread blocks an SM; trazo_uncapped (TRAZO_CUDA_PASS_MIN_BLOCKS=1)
# lets ptxas take up to 255 registers (8 warps, no spills). Same scenes, passes and seed: the faster build says
# which budget scripts/kernel_resources.sh should hold.
if step register_cap gpu carry; then
    if [ ! -x "$B/trazo_uncapped" ]; then
        record register_cap skipped "no trazo_uncapped in the carry folder (rerun scripts/gpu_prepare.sh)"
    else
        md=$OUT/scene_timings.md
        {
            echo
            echo "## Register cap: 128 registers (16 warps an SM) against uncapped (8 warps), 512², 32 passes, seed 1"
            echo
            echo "| scene | variant bits | capped s | uncapped s | uncapped / capped |"
            echo "|---|---|---|---|---|"
        } >>"$md"
        res="" bad=0
        step_end=$(( $(date +%s) + $(cap 90) ))
        for s in scene1_area scene3_csg_area scene5_bunny_reflect scene7_refract scene9_indirect scene10_bunny_indirect_area extra1_refract_indirect; do
            times=()
            for bin in trazo trazo_uncapped; do
                left=$(( step_end - $(date +%s) ))
                if (( left < 5 )); then times+=(""); continue; fi
                rc=0
                limited "$(( left < 30 ? left : 30 ))" "$log" "$B/$bin" --render "scenes/$s.scene" --backend cuda --width 512 \
                    --height 512 --spp 32 --seed 1 --quiet -o "$work/rc_$s.pfm" --stats "$art/${s}_$bin.json" || rc=$?
                if [ $rc = 0 ]; then times+=("$(jf "$art/${s}_$bin.json" render_s)"); else times+=(""); bad=$(( bad + 1 )); fi
            done
            features=$(jf "$art/${s}_trazo.json" features)
            awk -v s="$s" -v f="$features" -v a="${times[0]}" -v b="${times[1]}" 'BEGIN {
                r = (a != "" && b != "" && a > 0) ? sprintf("%.3f", b / a) : "";
                printf "| %s | %s | %s | %s | %s |\n", s, f, a, b, r }' >>"$md"
            res+=" $s:${times[0]:-?}/${times[1]:-?}"
        done
        if (( bad > 0 )); then record register_cap failed "capped/uncapped render_s:$res ($bad renders failed)"
        else record register_cap ran "capped/uncapped render_s (s):$res (scene_timings.md)"; fi
    fi
fi

# --- summary -----------------------------------------------------------------------------------------------------
if [ -n "$(ls -A "$art")" ]; then tar -C "$work" -czf "$OUT/artifacts.tar.gz" artifacts; fi
{
    echo "# trazo gpu_check, $(date -u +%Y-%m-%dT%H:%M:%SZ), $(( $(date +%s) - start )) s"
    echo
    echo "Machine: $(uname -n); ${no_gpu:-GPU present}; carry: ${no_carry:-${carry#"$repo"/}/ at ${REV:-?}}${no_setup:+; $no_setup}."
    echo
    printf '%s\n' "${lines[@]}"
    echo
    echo "Files: $(cd "$OUT" && find . -maxdepth 1 -type f -printf '%f\n' | sort | tr '\n' ' ')"
} >"$summary"
echo
cat "$summary"
if [ -z "$no_gpu" ] && (( failures > 0 )); then exit 1; fi
exit 0
