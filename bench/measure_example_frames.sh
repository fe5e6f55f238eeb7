#!/usr/bin/env bash
# Counts, with callgrind, the host instructions per frame of every board's engine while an example
# runs its own scenario in the simulator: the real sketch, driven the way its scenario drives it.
# Only Engine::run_frame is collected, minus its calls into the simulator's hal:: functions (the
# board's stand-in for the Teensy registers); callgrind dumps every STEPDANCE_WINDOW_BLOCKS basic
# blocks, so besides the mean over the run the script reports the busiest window's mean.
# The Cortex-M7 columns scale the busiest window's mean by STEPDANCE_M7_PER_HOST (M7 instructions
# per host instruction, -Os) and its worst frame by STEPDANCE_M7_WORST_PER_MEAN: both are the
# largest ratios measured under QEMU on the benchmark graphs (docs/high-speed.md, "Every
# example", says how). From them, the shortest period (10, 20, 25 or 40 µs) at which the worst
# frame takes at most 75 % of the frame at CPI 1.5, and the shortest at which the mean takes at
# most 10 % at CPI 1.0 (the frame-cost target).
# Usage: bench/measure_example_frames.sh [example-folder|scenario.toml ...]   (default: every
#        example with a scenario; run scripts/build-host.sh first)
# Output, one line per board: example, frames, host mean and busiest window (instructions per
# frame), the M7 estimates (busiest window's mean, worst frame), the two periods, blocks per frame.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${STEPDANCE_BUILD_DIR:-build}
binary="$build_dir/stepdance"
window_blocks=${STEPDANCE_WINDOW_BLOCKS:-2000000}
m7_per_host=${STEPDANCE_M7_PER_HOST:-1.2}
worst_per_mean=${STEPDANCE_M7_WORST_PER_MEAN:-1.4}
[ -x "$binary" ] || { echo "build first: scripts/build-host.sh (missing $binary)" >&2; exit 1; }
if [ $# -eq 0 ]; then
  set -- $(for scenario in examples/*/scenario.toml; do dirname "$scenario"; done)
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The M7 estimates and the shortest periods of one board, from its host figures.
m7_columns() {
  awk -v busiest="$1" -v ratio="$m7_per_host" -v worst_ratio="$worst_per_mean" 'BEGIN {
    mean = busiest * ratio; worst = mean * worst_ratio
    split("10 20 25 40", periods, " ")
    fits = "-"; target = "-"
    for (i = 4; i >= 1; --i) {
      budget = periods[i] * 600  # cycles at 600 MHz
      if (worst * 1.5 <= 0.75 * budget) fits = periods[i]
      if (mean <= 0.10 * budget) target = periods[i]
    }
    printf "%6d %6d %5s %5s", mean, worst, fits, target
  }'
}

printf '%-22s %8s %5s %7s %6s %6s %5s %5s  %s\n' example frames mean busiest m7 m7max fits 10% "blocks per frame"
for example in "$@"; do
  name=$(basename "${example%/scenario.toml}")
  # A first run compiles the sketches (outside the measurement) and must pass its own checks.
  "$binary" sim "$example" --quiet --no-vcd --out "$work/out" >"$work/first.log" 2>&1 ||
    { cat "$work/first.log"; echo "measure: $example failed its own run" >&2; exit 1; }
  rm -rf "$work/dumps"
  mkdir -p "$work/dumps"
  valgrind --tool=callgrind --callgrind-out-file="$work/dumps/callgrind.out" \
    --dump-every-bb="$window_blocks" --toggle-collect='stepdance::Engine::run_frame()' \
    "$binary" sim "$example" --quiet --no-vcd --out "$work/out" >"$work/valgrind.log" 2>&1 ||
    { tail -n 20 "$work/valgrind.log"; echo "measure: $example failed under callgrind" >&2; exit 1; }
  awk -f bench/callgrind_frames.awk "$work"/dumps/callgrind.out* |
    sed -n 's/^[^ ]* frames=\([0-9]*\) mean=\([0-9]*\) busiest=\([0-9]*\) windows=[0-9]* blocks=\(.*\)$/\1 \2 \3 \4/p' |
    while read -r frames mean busiest blocks; do
      printf '%-22s %8d %5d %7d %s  %s\n' "$name" "$frames" "$mean" "$busiest" "$(m7_columns "$busiest")" "$blocks"
    done
done
