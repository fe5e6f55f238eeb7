#!/usr/bin/env bash
# Configures and builds the host tree (library, tests, tools, benchmarks) in build/.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${STEPDANCE_BUILD_DIR:-build}
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSTEPDANCE_TESTS=ON -DSTEPDANCE_BENCH=ON "$@" >/dev/null
cmake --build "$build_dir" -j"$(nproc)"
