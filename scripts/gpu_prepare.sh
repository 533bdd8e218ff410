#!/usr/bin/env bash
# gpu_prepare.sh — run HERE (no GPU needed): builds what scripts/gpu_check.sh runs on a lent GPU machine and
# puts it in one git-ignored folder that the device tool carries beside the tree.
#
#   scripts/gpu_prepare.sh [--build DIR] [--carry DIR] [--limit-mib N]
#
# Why a carry folder: the GPU machine has nvcc and CMake but no apt, no internet and none of our Debian
# libraries (FreeImage, GTest, GLFW ...), so the binaries are built here and travel with the shared
# libraries they need that are not part of every Linux system.
#
# What it does:
#   1. configures and builds a CUDA-enabled sm_90 (H100/H200) Release build in build-gpu/ (its own dir: the
#      CPU build in build/ is left alone): 90-real, machine code only, no PTX, and --compress-mode=size, since
#      each of trazo, trazo_tests and bvh_bench embeds all 17 kernel variants (22 MB each as sm_90 + PTX with
#      the default compression, 20 MB as 90-real, 2.5 MB with size compression, which needs a CUDA 13 driver,
#      580 or later: the lent H100/H200 have 580.159); Embree off (bvh_bench's GPU line does not need it, and
#      libembree3 alone is ~44 MB), with DT_RPATH $ORIGIN/../lib so the carried binaries find the carried
#      libraries without LD_LIBRARY_PATH (DT_RPATH, not RUNPATH: it also serves the libraries' own deps);
#   2. builds tests/gpu/egl_interop_probe.cpp against build-gpu's libtrazo_cuda.a (not part of the normal
#      build: it needs CUDA and tests only the viewer's CUDA-GL interop through headless EGL);
#   3. assembles gpu-carry/: bin/ (trazo trazo_tests bvh_bench image_error egl_interop_probe, and
#      trazo_uncapped: trazo built again with TRAZO_CUDA_PASS_MIN_BLOCKS=1 in build-gpu-uncapped/), lib/ (every
#      library ldd resolves outside glibc, libstdc++/libgcc_s and the GL loaders), lib-cxx/ (libstdc++ and
#      libgcc_s, used there only if the system's are older than what the binaries need), lib-gl/ (the glvnd
#      loaders libEGL/libOpenGL/libGLdispatch, used only if the machine has none), assets/ (the
#      git-ignored scene assets: they do not travel with the tree), manifest.env (paths compiled into the
#      binaries, revision, glibc needed), tests.txt (the gtest list);
#   4. where gpu-carry/ is over --limit-mib (default 48) MiB, packs it as gpu-carry.tar.xz beside it (trazo is
#      ~11 MB: 7.7 MB of CPU code, the tile renderers compiled for three ISAs, and 1.9 MB of kernels; xz takes
#      the folder from 66 to 24 MiB), fails if even that is over, and prints the device-tool call (which
#      unpacks the archive there first when there is one).
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$repo/build-gpu
carry=$repo/gpu-carry
limit_mib=48
while [ $# -gt 0 ]; do
    case $1 in
        --build) build=$2; shift 2 ;;
        --carry) carry=$2; shift 2 ;;
        --limit-mib) limit_mib=$2; shift 2 ;;
        -h|--help) sed -n '2,31p' "$0"; exit 0 ;;
        *) echo "gpu_prepare: unknown option $1" >&2; exit 2 ;;
    esac
done
log() { printf 'gpu_prepare: %s\n' "$*" >&2; }
die() { log "$*"; exit 1; }

# The carry folder must stay out of git (it is binaries) but inside the repository (the tool carries only
# paths under the repository root).
case $carry in /*) ;; *) carry=$PWD/$carry ;; esac
case $build in /*) ;; *) build=$PWD/$build ;; esac
case $carry in "$repo"/?*) ;; *) die "the carry folder must be inside $repo (the device tool carries repo paths only)" ;; esac
carry_rel=${carry#"$repo"/}
git -C "$repo" check-ignore -q "$carry_rel/x" || die "$carry_rel/ is not git-ignored (add /$carry_rel/ to .gitignore)"
git -C "$repo" check-ignore -q "$carry_rel.tar.xz" || die "$carry_rel.tar.xz is not git-ignored (add /$carry_rel.tar.xz to .gitignore)"
[ "$(cd "$repo" && realpath -m "$build")" != "$repo/build" ] || die "refusing to use build/ (the CPU build others use)"

nvcc=${NVCC:-$(command -v nvcc || echo /usr/local/cuda/bin/nvcc)}
if [ ! -x "$nvcc" ]; then die "no nvcc (set NVCC or install the CUDA toolkit in /usr/local/cuda)"; fi
cuda_root=$(cd "$(dirname "$nvcc")/.." && pwd)
command -v ninja >/dev/null || die "ninja not found"

# --- 1. the sm_90 build ---------------------------------------------------------------------------------
t0=$(date +%s)
log "configuring $build (CUDA sm_90, Release, no Embree)"
# shellcheck disable=SC2016  # $ORIGIN is for the dynamic linker, not the shell
cmake -S "$repo" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DTRAZO_ENABLE_CUDA=ON \
    -DCMAKE_CUDA_COMPILER="$nvcc" -DCMAKE_CUDA_ARCHITECTURES=90-real -DCMAKE_CUDA_FLAGS=--compress-mode=size \
    -DCMAKE_DISABLE_FIND_PACKAGE_embree=ON \
    '-DCMAKE_BUILD_RPATH=$ORIGIN/../lib' -DCMAKE_EXE_LINKER_FLAGS=-Wl,--disable-new-dtags >"$build.configure.log" 2>&1 \
    || { cat "$build.configure.log" >&2; die "cmake configure failed"; }
grep -q "Trazo: CUDA backend ON" "$build.configure.log" || die "the configure did not enable the CUDA backend (see $build.configure.log)"
rm -f "$build.configure.log"
targets=(trazo trazo_tests bvh_bench image_error)
log "building ${targets[*]} (the CUDA objects take about a minute on 2 cores)"
cmake --build "$build" -j "$(nproc)" --target "${targets[@]}"
declare -A path=([trazo]=app/trazo [trazo_tests]=tests/trazo_tests [bvh_bench]=bench/bvh/bvh_bench
                 [image_error]=bench/peers/image_error)
for name in "${targets[@]}"; do [ -x "$build/${path[$name]}" ] || die "missing $build/${path[$name]}"; done
log "build done in $(( $(date +%s) - t0 )) s"

# --- 1b. trazo with the render kernels' register cap lifted (register_cap times the two) -----------------
uncapped=$build-uncapped
log "configuring $uncapped (the same, TRAZO_CUDA_PASS_MIN_BLOCKS=1)"
# shellcheck disable=SC2016
cmake -S "$repo" -B "$uncapped" -G Ninja -DCMAKE_BUILD_TYPE=Release -DTRAZO_ENABLE_CUDA=ON \
    -DCMAKE_CUDA_COMPILER="$nvcc" -DCMAKE_CUDA_ARCHITECTURES=90-real -DCMAKE_CUDA_FLAGS=--compress-mode=size \
    -DCMAKE_DISABLE_FIND_PACKAGE_embree=ON -DTRAZO_CUDA_PASS_MIN_BLOCKS=1 \
    '-DCMAKE_BUILD_RPATH=$ORIGIN/../lib' -DCMAKE_EXE_LINKER_FLAGS=-Wl,--disable-new-dtags >"$uncapped.configure.log" 2>&1 \
    || { cat "$uncapped.configure.log" >&2; die "cmake configure of $uncapped failed"; }
rm -f "$uncapped.configure.log"
cmake --build "$uncapped" -j "$(nproc)" --target trazo
[ -x "$uncapped/app/trazo" ] || die "missing $uncapped/app/trazo"

# --- 2. the EGL interop probe (links only cuda_gl_display.cu.o out of libtrazo_cuda.a) --------------------
probe=$build/tests/gpu/egl_interop_probe
mkdir -p "$(dirname "$probe")"
if [ ! -x "$probe" ] || [ "$repo/tests/gpu/egl_interop_probe.cpp" -nt "$probe" ] \
   || [ "$build/renderer/libtrazo_cuda.a" -nt "$probe" ]; then
    log "building egl_interop_probe"
    # shellcheck disable=SC2016
    g++ -O2 -std=c++20 -Wall -Wextra -I"$repo/renderer" -I"$cuda_root/include" \
        "$repo/tests/gpu/egl_interop_probe.cpp" "$build/renderer/libtrazo_cuda.a" \
        "$cuda_root/lib64/libcudart_static.a" -ldl -lpthread -lrt \
        -Wl,--disable-new-dtags,-rpath,'$ORIGIN/../lib' -o "$probe"
fi

# --- 3. the carry folder ---------------------------------------------------------------------------------
rm -rf "$carry"
mkdir -p "$carry/bin" "$carry/lib" "$carry/lib-cxx" "$carry/lib-gl" "$carry/assets"
for name in "${targets[@]}"; do cp "$build/${path[$name]}" "$carry/bin/$name"; done
cp "$probe" "$carry/bin/egl_interop_probe"
cp "$uncapped/app/trazo" "$carry/bin/trazo_uncapped"
for b in "$carry"/bin/*; do
    # shellcheck disable=SC2016
    readelf -d "$b" | grep -q 'RPATH.*\$ORIGIN/\.\./lib' || die "$(basename "$b") has no DT_RPATH \$ORIGIN/../lib"
done

# Libraries: glibc's own and the NVIDIA driver's are the machine's (a carried glibc would not match its
# loader; the driver must match the kernel module); libstdc++/libgcc_s are usually there and newer, so they
# go aside as a fallback; the GL loaders (glvnd) go aside because a machine that has them must use its own
# (they pick the vendor driver).
declare -A seen=()
for b in "$carry"/bin/*; do
    while read -r soname file; do
        [ -n "${seen[$soname]:-}" ] && continue
        seen[$soname]=1
        case $soname in
            linux-vdso*|ld-linux*|libc.so.*|libm.so.*|libdl.so.*|libpthread.so.*|librt.so.*|libresolv.so.*|libutil.so.*|libanl.so.*|libmvec.so.*) continue ;;
            libcuda.so*|libnvidia*|libEGL_nvidia*|libGLX_nvidia*) continue ;;
            libstdc++.so.*|libgcc_s.so.*) dest=lib-cxx ;;
            libEGL.so.*|libOpenGL.so.*|libGLdispatch.so.*|libGLX.so.*|libGL.so.*) dest=lib-gl ;;
            *) dest=lib ;;
        esac
        cp -L "$file" "$carry/$dest/$soname"
    done < <(ldd "$b" | awk '/=>/ && $3 ~ /^\// {print $1, $3}')
done
# The probe dlopens the glvnd loaders (ldd does not list them).
for so in libEGL.so.1 libOpenGL.so.0 libGLdispatch.so.0; do
    file=$(ldconfig -p | awk -v s="$so" '$1 == s && /x86-64/ {print $NF; exit}')
    if [ -n "$file" ]; then cp -L "$file" "$carry/lib-gl/$so"; else log "WARNING: no $so here to carry"; fi
done
missing=$(for b in "$carry"/bin/*; do ldd "$b" | grep 'not found' || true; done | sort -u)
[ -z "$missing" ] || die "unresolved libraries: $missing"

# Scene assets: generated or downloaded, git-ignored, so they do not travel with the tree.
while IFS= read -r f; do
    cp "$repo/$f" "$carry/assets/"
done < <(git -C "$repo" ls-files --others --ignored --exclude-standard scenes/assets)
for f in bunny.obj head.obj head_diffuse.png head_normal.png; do
    [ -f "$carry/assets/$f" ] || log "WARNING: scenes/assets/$f missing here (scenes that use it will fail there)"
done

# The newest glibc symbol version anything carried needs: gpu_check.sh compares it with the machine's.
glibc_needed=$(for f in "$carry"/bin/* "$carry"/lib/*; do objdump -T "$f" 2>/dev/null; done \
    | grep -o 'GLIBC_[0-9][0-9.]*' | sort -u -V | tail -n 1)
glibcxx_needed=$(for f in "$carry"/bin/* "$carry"/lib/*; do objdump -T "$f" 2>/dev/null; done \
    | grep -o 'GLIBCXX_[0-9][0-9.]*' | sort -u -V | tail -n 1)
"$carry/bin/trazo_tests" --gtest_list_tests >"$carry/tests.txt" 2>/dev/null || log "WARNING: could not list the tests"
src_baked=$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$build/CMakeCache.txt")
rev=$(git -C "$repo" rev-parse --short=12 HEAD 2>/dev/null || echo unknown)
dirty=$(git -C "$repo" status --porcelain --untracked-files=no 2>/dev/null | wc -l)
cat >"$carry/manifest.env" <<EOF
# written by scripts/gpu_prepare.sh on $(uname -n), $(date -u +%Y-%m-%dT%H:%M:%SZ); sourced by scripts/gpu_check.sh
# The tests and bvh_bench have these paths compiled in (TRAZO_SOURCE_DIR, TRAZO_BINARY).
SRC_BAKED='$src_baked'
BIN_BAKED='$build/app/trazo'
REV='$rev'
DIRTY_FILES='$dirty'
CUDA_ARCHS='$(sed -n 's/^CMAKE_CUDA_ARCHITECTURES:[A-Z]*=//p' "$build/CMakeCache.txt")'
NVCC_VERSION='$("$nvcc" --version | tail -n 1)'
GLIBC_NEEDED='${glibc_needed#GLIBC_}'
GLIBCXX_NEEDED='${glibcxx_needed#GLIBCXX_}'
BUILT_ON='$(sed -n 's/^PRETTY_NAME=//p' /etc/os-release | tr -d '"'), $(ldd --version | head -n 1)'
EOF

# --- 4. size and the call to make -------------------------------------------------------------------------
bytes=$(du -sb "$carry" | cut -f1)
mib() { awk -v b="$1" 'BEGIN {printf "%.1f MiB", b / 1048576}'; }
tree=$( (cd "$repo" && { git ls-files -z; git ls-files -z --others --exclude-standard; } | du -cb --files0-from=- 2>/dev/null | tail -n 1 | cut -f1) || echo 0)
log "contents:"
(cd "$carry" && du -sh bin lib lib-cxx lib-gl assets) | sed 's/^/    /' >&2
echo "gpu_prepare: $carry_rel/ is $(mib "$bytes") (limit $limit_mib MiB); with the tree ($(mib "${tree:-0}")) $(mib $(( bytes + ${tree:-0} ))) of the tool's 64 MiB"
echo "gpu_prepare: binaries at $rev ($dirty modified tracked files), need glibc ${glibc_needed#GLIBC_}, libstdc++ ${glibcxx_needed#GLIBCXX_}"
packed=$carry.tar.xz
rm -f "$packed"
carried=$carry_rel unpack=""
if (( bytes > limit_mib * 1048576 )); then
    log "packing $carry_rel/ into $carry_rel.tar.xz (xz -6, all cores)"
    tar -C "$(dirname "$carry")" -cf - "$(basename "$carry")" | xz -6 -T0 >"$packed"
    bytes=$(stat -c %s "$packed")
    echo "gpu_prepare: $carry_rel.tar.xz is $(mib "$bytes") (limit $limit_mib MiB)"
    (( bytes <= limit_mib * 1048576 )) || die "TOO BIG: even $carry_rel.tar.xz is over $limit_mib MiB"
    # python3's tarfile where the machine has no xz program (the lent machines' image holds python3).
    carried=$carry_rel.tar.xz
    unpack="(tar -xJf $carry_rel.tar.xz || python3 -c \\\"import tarfile; tarfile.open('$carry_rel.tar.xz').extractall()\\\") && "
fi
cat <<EOF
gpu_prepare: ready. The device-tool call for a GPU session (scripts/gpu_check.sh must be in the tree, committed or untracked):
  run(command: "${unpack}bash scripts/gpu_check.sh", carry: ["$carried"], timeout_s: 540)
  then read \$OUT's summary.md first (the files come back under files_at).
EOF
