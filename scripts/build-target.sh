#!/usr/bin/env bash
# Cross-compiles the portable core for the Teensy 4.x Cortex-M7; any warning fails the build.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${STEPDANCE_TARGET_BUILD_DIR:-build-cortex-m7}
cmake -S . -B "$build_dir" -DCMAKE_TOOLCHAIN_FILE=cmake/cortex-m7.cmake -DCMAKE_BUILD_TYPE=MinSizeRel \
  -DSTEPDANCE_TESTS=OFF -DSTEPDANCE_BENCH=OFF >/dev/null
cmake --build "$build_dir" -j"$(nproc)"
echo "target: portable core built for Cortex-M7 in $build_dir"
