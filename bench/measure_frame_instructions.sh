#!/usr/bin/env bash
# Counts host instructions per frame of a benchmark graph with callgrind: only Engine::run_frame
# (and what it calls) is collected, then divided by the frame count.
# Usage: bench/measure_frame_instructions.sh [frames] [step_a_sketch|step_a_sketch_tbi|harmonograph|clay_texturizer|axidraw_wave|pantograph]
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${STEPDANCE_BUILD_DIR:-build}
frames=${1:-20000}
workload=${2:-step_a_sketch}
binary="$build_dir/stepdance_frame_instructions"
[ -x "$binary" ] || { echo "build first: scripts/build-host.sh" >&2; exit 1; }
out=$(mktemp -d)
valgrind --tool=callgrind --callgrind-out-file="$out/callgrind.out" \
  --toggle-collect='stepdance::Engine::run_frame()' "$binary" "$frames" "$workload" >/dev/null 2>"$out/log"
total=$(sed -n 's/^summary: *\([0-9]*\).*/\1/p' "$out/callgrind.out")
echo "workload: $workload"
echo "frames: $frames"
echo "instructions in Engine::run_frame: $total"
echo "instructions per frame: $((total / frames))"
rm -rf "$out"
