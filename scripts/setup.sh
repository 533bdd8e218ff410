#!/usr/bin/env bash
# Installs every Debian package Trazo needs, then configures it (Release, into build/) and builds what a first
# image needs: trazo with its viewer and the scenes' generated assets. `cmake --build build` builds the rest
# (the tests and benchmarks).
# Usage: scripts/setup.sh [extra cmake arguments]   (TRAZO_SKIP_APT=1 skips the package step)
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake ninja-build pkg-config
  libglfw3-dev libimgui-dev libfreeimage-dev python3-glad libtinyobjloader-dev
  libgtest-dev libbenchmark-dev libcli11-dev libembree-dev povray
  xvfb xauth xdotool x11-apps libgl1-mesa-dri mesa-utils
  slurm-wlm munge libxxhash-dev ccache)

if [ "${TRAZO_SKIP_APT:-0}" != 1 ]; then
  missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  # The bunny comes from the npm registry: node and npm are needed (Debian's, unless the machine has its own).
  command -v npm >/dev/null 2>&1 || missing+=(nodejs npm)
  if [ ${#missing[@]} -gt 0 ]; then
    sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
    echo "setup: installing ${missing[*]}" >&2
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
  fi
fi

# The Stanford bunny of scenes 2, 5 and 10 (npm package `bunny`, not committed).
scripts/make_bunny.sh

# nvcc is not on PATH in every shell; the toolkit's usual home is enough for CMake to find it.
cuda_args=()
if [ -x /usr/local/cuda/bin/nvcc ] && [ "${TRAZO_ENABLE_CUDA:-ON}" != OFF ]; then
  cuda_args+=(-DCMAKE_CUDA_COMPILER=/usr/local/cuda/bin/nvcc)
fi
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "${cuda_args[@]}" "$@"
cmake --build build --target trazo trazo_scene_assets
