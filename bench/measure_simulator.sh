#!/usr/bin/env bash
# Prints the simulator's performance figures for docs/simulator.md:
#   1. wall clock (best of N runs): Step-A-Sketch speed in simulated seconds per wall second with
#      the VCD off, per-frame cost of the simulation and of the bare engine (same block graph on
#      the manual backend) in the same process, and max RSS over 10 simulated minutes;
#   2. callgrind instruction counts (repeatable): instructions per simulated frame, all included
#      (scheduler, devices, machine, the sketch's engine), against Engine::run_frame on the bare
#      engine.
# Usage: bench/measure_simulator.sh [runs]   (builds nothing: run scripts/build-host.sh first)
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${STEPDANCE_BUILD_DIR:-build}
runs=${1:-5}
binary="$build_dir/stepdance_simulator_speed"
[ -x "$binary" ] || { echo "build first: scripts/build-host.sh (missing $binary)" >&2; exit 1; }

echo "== wall clock"
"$binary" "$runs"

echo "== callgrind instruction counts"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
engine_frames=200000
# 42 s of Step-A-Sketch at 25 000 frames per second.
simulated_frames=1050000
valgrind --tool=callgrind --callgrind-out-file="$out/sim.out" \
  --toggle-collect='stepdance::sim::Simulation::run_until(long)' "$binary" --simulate >/dev/null 2>"$out/sim.log"
valgrind --tool=callgrind --callgrind-out-file="$out/engine.out" \
  --toggle-collect='stepdance::Engine::run_frame()' "$binary" --engine "$engine_frames" >/dev/null 2>"$out/engine.log"
sim_total=$(sed -n 's/^summary: *\([0-9]*\).*/\1/p' "$out/sim.out")
engine_total=$(sed -n 's/^summary: *\([0-9]*\).*/\1/p' "$out/engine.out")
sim_per_frame=$((sim_total / simulated_frames))
engine_per_frame=$((engine_total / engine_frames))
echo "simulation: $sim_per_frame instructions per frame ($sim_total in Simulation::run_until, $simulated_frames frames)"
echo "bare engine: $engine_per_frame instructions per frame (Engine::run_frame, $engine_frames frames)"
awk -v s="$sim_per_frame" -v e="$engine_per_frame" \
  'BEGIN { printf "simulator overhead: %d instructions per frame = %.2fx the cost of the bare engine\n", s - e, (s - e) / e }'
