#!/usr/bin/env bash
# Counts Cortex-M7 instructions per loop pass under QEMU (mps2-an500, -icount shift=0: 1 ns of
# virtual time per instruction, a 25 MHz timer tick = 40 instructions), each pass timed on its own,
# and turns the worst pass into time at 600 MHz. Method: docs/benchmarks-target.md.
# Usage: bench/measure_target_loop.sh [ebb [passes] | arc]
#   ebb: one EBB command per pass (the recorded saxi plot, examples/AxiDrawWave/saxi-plot.ebb, over
#        and over): read, parsed, executed, answered, queued; the moves run between passes, unmeasured
#   arc: a 1,000-turn helical G2 line (soft limits on) validated and fed to the planner, a loop pass
#        every 1 ms of frames, until the arc has run; the worst pass is the figure
#   (STEPDANCE_QEMU_BUILD_TYPE=MinSizeRel|RelWithDebInfo|...)
set -euo pipefail
cd "$(dirname "$0")/.."
workload=${1:-ebb}
passes=${2:-1000}
build_type=${STEPDANCE_QEMU_BUILD_TYPE:-MinSizeRel}
build_dir=${STEPDANCE_QEMU_BENCH_DIR:-build-qemu-m7-bench-$build_type-loop-$workload}
cmake -S targets/qemu-m7 -B "$build_dir" -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/cortex-m7.cmake" \
  -DCMAKE_BUILD_TYPE="$build_type" -DSTEPDANCE_BENCH_PASSES="$passes" \
  -DSTEPDANCE_BENCH_LOOP_WORKLOAD="$workload" >/dev/null
cmake --build "$build_dir" -j"$(nproc)" --target bench_loop >/dev/null
image="$build_dir/bench_loop.elf"
status=0
output=$(timeout 3600 qemu-system-arm -M mps2-an500 -cpu cortex-m7 -nographic -monitor none \
  -semihosting-config enable=on,target=native -kernel "$image" -icount shift=0 </dev/null) || status=$?
known_ticks=$(sed -n 's/^known_loop iterations=[0-9]* timer_ticks=\([0-9]*\).*/\1/p' <<<"$output")
figures=$(sed -n 's/^passes //p' <<<"$output")
[ "$status" -eq 0 ] && [ -n "$known_ticks" ] && [ -n "$figures" ] ||
  { echo "$output"; echo "bench: the workload failed or printed no figures (exit $status)" >&2; exit 1; }
expected_known=2000001
if [ $((known_ticks * 40 - expected_known)) -gt 40 ] || [ $((expected_known - known_ticks * 40)) -gt 40 ]; then
  echo "$output"; echo "bench: the known loop does not check out (timer $((known_ticks * 40)))" >&2; exit 1
fi
echo "image: $image ($build_type, Cortex-M7 hard-float double, workload $workload)"
echo "known loop (2 000 001 instructions): icount timer $((known_ticks * 40)) (+-40)"
awk -v workload="$workload" '{
  for (i = 1; i <= NF; ++i) { split($i, kv, "="); v[kv[1]] = kv[2] }
  n = v["count"]; total = v["total_ticks"] * 40; worst = v["worst_ticks"] * 40
  printf "loop passes: %d, units (EBB commands / G-code lines answered ok): %d\n", n, v["units"]
  printf "instructions in all passes: %.0f (each pass +-40), mean %.0f per pass\n", total, total / n
  if (workload == "ebb") printf "instructions per EBB command: %.0f\n", total / v["units"]
  printf "worst pass: %d instructions (+-40), pass %d\n", worst, v["worst_pass"]
  for (cpi = 1.0; cpi <= 1.51; cpi += 0.5)
    printf "CPI %.1f: worst pass %.0f cycles = %.3f ms on the 600 MHz M7\n", cpi, worst * cpi, worst * cpi / 600e3
}' <<<"$figures"
