#!/usr/bin/env bash
# Sets up the machine, then builds and runs the whole test suite: the core's portability check,
# the function-length limits (60 lines in src/, sim/ and cli/; 40 in sim/scenario/), the comment
# density of src/ (at least 0.10, scripts/comment-density.sh), the C/C++ format
# (scripts/check-format.sh, .clang-format),
# the Cortex-M7 builds (core, Teensy backend, every example sketch, firmware image, Arduino zip),
# the core's unit tests on a Cortex-M7 under QEMU, the host tests (CTest: unit, example sketches,
# simulator, servo firmware under simavr), the host tests again under AddressSanitizer + UBSan,
# and a short smoke run of every libFuzzer target (the long runs are documented in docs/fuzzing.md).
set -euo pipefail
cd "$(dirname "$0")/.."
# Each stage prints the seconds since the start, so a slow stage shows in the log.
stage() {
  echo "== [${SECONDS} s] $*"
  "$@"
}
stage scripts/setup.sh --web
stage scripts/setup-npm-clients.sh
stage scripts/check-core-portability.sh
stage scripts/check-interfaces-structure.sh
stage scripts/check-function-length.sh 60 src sim cli
stage scripts/check-function-length.sh 40 sim/scenario
stage scripts/comment-density.sh --min 0.10 src
stage scripts/check-format.sh --self-test
stage scripts/check-format.sh
stage scripts/build-target.sh
stage scripts/build-teensy.sh
stage scripts/test-target-qemu.sh
stage scripts/build-host.sh
stage ctest --test-dir "${STEPDANCE_BUILD_DIR:-build}" --output-on-failure -j"$(nproc)" -LE image_full
echo "== again under AddressSanitizer and UBSan"
stage env STEPDANCE_BUILD_DIR=build-sanitize scripts/build-host.sh -DSTEPDANCE_SANITIZE=ON -DSTEPDANCE_BENCH=OFF
# Slow integration tests (live pseudo-terminals, browsers, npm clients) run once, above.
stage ctest --test-dir build-sanitize --output-on-failure -j"$(nproc)" -LE "integration|image_full"
echo "== fuzz smoke runs"
stage scripts/fuzz.sh
echo "== [${SECONDS} s] all tests passed"
