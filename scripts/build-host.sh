#!/usr/bin/env bash
# Configures and builds the host tree (library, tests, tools, benchmarks) in build/.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${STEPDANCE_BUILD_DIR:-build}
launcher=()
# ccache, where installed, makes rebuilds in other checkouts of the same tree cheap.
if command -v ccache >/dev/null 2>&1; then
  export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$(cd .. && pwd)}
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
# The servo firmware is switched on explicitly: scripts/main.sh configures a fresh tree without it.
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSTEPDANCE_TESTS=ON -DSTEPDANCE_BENCH=ON \
  -DSTEPDANCE_SERVO_FIRMWARE=ON \
  "${launcher[@]}" "$@" >/dev/null
cmake --build "$build_dir" -j"$(nproc)"
