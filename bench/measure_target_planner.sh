#!/usr/bin/env bash
# Counts Cortex-M7 instructions per planned segment (full 128-block look-ahead queue) under QEMU
# (mps2-an500, -icount shift=0: 1 ns of virtual time per instruction, a 25 MHz timer tick = 40
# instructions) and turns them into segments per second at 600 MHz. Method: docs/benchmarks-target.md.
# Usage: bench/measure_target_planner.sh [segments] [planner|gcode]
#   gcode: each "segment" is one G-code line received, parsed, executed, acknowledged and planned
#   (STEPDANCE_QEMU_BUILD_TYPE=MinSizeRel|Release|...)
set -euo pipefail
cd "$(dirname "$0")/.."
segments=${1:-5000}
workload=${2:-planner}
build_type=${STEPDANCE_QEMU_BUILD_TYPE:-MinSizeRel}
build_dir=${STEPDANCE_QEMU_BENCH_DIR:-build-qemu-m7-bench-$build_type-$workload}
cmake -S targets/qemu-m7 -B "$build_dir" -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/cortex-m7.cmake" \
  -DCMAKE_BUILD_TYPE="$build_type" -DSTEPDANCE_BENCH_SEGMENTS="$segments" \
  -DSTEPDANCE_BENCH_PLANNER_WORKLOAD="$workload" >/dev/null
cmake --build "$build_dir" -j"$(nproc)" --target bench_planner >/dev/null
image="$build_dir/bench_planner.elf"
output=$(timeout 600 qemu-system-arm -M mps2-an500 -cpu cortex-m7 -nographic -monitor none \
  -semihosting-config enable=on,target=native -kernel "$image" -icount shift=0 </dev/null)
known_ticks=$(sed -n 's/^known_loop iterations=[0-9]* timer_ticks=\([0-9]*\).*/\1/p' <<<"$output")
segment_ticks=$(sed -n 's/^segments count=[0-9]* timer_ticks=\([0-9]*\).*/\1/p' <<<"$output")
[ -n "$known_ticks" ] && [ -n "$segment_ticks" ] || { echo "$output"; echo "bench: no timer figures" >&2; exit 1; }
expected_known=2000001
if [ $((known_ticks * 40 - expected_known)) -gt 40 ] || [ $((expected_known - known_ticks * 40)) -gt 40 ]; then
  echo "$output"; echo "bench: the known loop does not check out (timer $((known_ticks * 40)))" >&2; exit 1
fi
echo "image: $image ($build_type, Cortex-M7 hard-float double, workload $workload)"
echo "known loop (2 000 001 instructions): icount timer $((known_ticks * 40)) (+-40)"
awk -v ticks="$segment_ticks" -v n="$segments" 'BEGIN {
  per = ticks * 40 / n
  printf "segments planned: %d, instructions per segment: %.0f (+-%.2f)\n", n, per, 40 / n
  for (cpi = 1.0; cpi <= 1.51; cpi += 0.5)
    printf "CPI %.1f: %.0f cycles per segment = %.0f segments/s on the 600 MHz M7 (all of the CPU)\n", cpi, per * cpi, 600e6 / (per * cpi)
}'
