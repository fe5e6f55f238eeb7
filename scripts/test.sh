#!/usr/bin/env bash
# Sets up the machine, then builds and runs the whole test suite: host unit and integration
# tests (CTest), the core's portability check and the Cortex-M7 cross-compile.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/check-core-portability.sh
scripts/build-target.sh
scripts/build-host.sh
ctest --test-dir "${STEPDANCE_BUILD_DIR:-build}" --output-on-failure -j"$(nproc)"
