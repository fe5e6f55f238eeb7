#!/usr/bin/env bash
# Builds the portable core's unit tests for the Cortex-M7 and runs them on QEMU's mps2-an500 with
# semihosting; exits non-zero on a failed test, a crash or a timeout. Extra arguments go to CMake
# (e.g. -DSTEPDANCE_QEMU_EXTRA_TESTS=/tmp/fail_test.cpp to check that a failing test fails the run).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${STEPDANCE_QEMU_BUILD_DIR:-build-qemu-m7}
time_limit=${STEPDANCE_QEMU_TIMEOUT:-600}

cmake -S targets/qemu-m7 -B "$build_dir" -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/cortex-m7.cmake" \
  -DCMAKE_BUILD_TYPE=MinSizeRel "$@" >/dev/null
cmake --build "$build_dir" -j"$(nproc)" --target stepdance_target_tests >/dev/null

image="$build_dir/stepdance_target_tests.elf"
log="$build_dir/stepdance_target_tests.log"
status=0
timeout "$time_limit" qemu-system-arm -M mps2-an500 -cpu cortex-m7 -nographic -monitor none \
  -semihosting-config enable=on,target=native -kernel "$image" </dev/null >"$log" 2>&1 || status=$?

if [ $status -eq 0 ] && grep -q '^\[  PASSED  \]' "$log" && ! grep -q '^\[  FAILED  \]' "$log"; then
  grep -E '^\[(==========|  PASSED  )\]' "$log" | sed 's/^/qemu-m7: /'
  exit 0
fi

cat "$log"
if [ $status -eq 124 ]; then
  echo "qemu-m7: FAILED: no result within ${time_limit} s (full log: $log)"
else
  echo "qemu-m7: FAILED: exit status $status (full log: $log)"
fi
[ $status -ne 0 ] || status=1
exit $status
