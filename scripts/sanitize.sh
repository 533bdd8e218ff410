#!/usr/bin/env bash
# The CPU-only project built with AddressSanitizer + UndefinedBehaviorSanitizer (in build-sanitize/, or the
# folder given), and the whole test suite run under it: any report fails the test it came from. Nothing is
# suppressed; the two viewer tests alone run without leak detection (tests/CMakeLists.txt says why).
# Usage: scripts/sanitize.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-sanitize}
flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
# The benchmarks are not tests; the CUDA backend cannot be instrumented (and CI has no GPU). The camera-packet
# kernels are not flattened: instrumented, each of their three units took 21 minutes to compile flattened, 32 s
# not (the same code, inlined less; camera_tile_render.h). Line tables only (-g1): reports still name file and
# line, and a test unit compiles in 3/4 of the time.
release_debug="-O2 -g1 -DNDEBUG"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTRAZO_ENABLE_CUDA=OFF -DTRAZO_BUILD_BENCH=OFF \
  -DTRAZO_FLATTEN_PACKET_KERNELS=OFF \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="$release_debug" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$release_debug" \
  -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined"
cmake --build "$build"
export ASAN_OPTIONS=detect_leaks=1:halt_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir "$build" --output-on-failure -j2 --timeout 900
