#!/usr/bin/env bash
# Benchmark (not a test): how fast an image board runs, and what its frame interrupt costs.
#
# Runs EXAMPLE's scenario for SECONDS of simulated time twice: on the host-compiled sketch, and
# on the firmware image (the CI image of scripts/build-teensy.sh, or IMAGE), and prints for each
# the simulated seconds per wall second and per CPU second (user + system: the machine may be
# shared), then the image's figures from the summary: instructions retired, instructions and
# simulated time to setup(), and the frame interrupt's mean instructions (the tick and stage
# handlers), to set beside docs/benchmarks-target.md's QEMU figures.
#
# Usage: bench/image_board_speed.sh [EXAMPLE [SECONDS [IMAGE]]]
#        (default StepASketch, 5 s, build-teensy/teensy41-serial/<EXAMPLE>.elf)
# Needs build/stepdance (scripts/build-host.sh) and the image (scripts/build-teensy.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
example=${1:-StepASketch}
seconds=${2:-5}
image=${3:-build-teensy/teensy41-serial/$example.elf}
board=$(python3 -c "import tomllib,sys; print(tomllib.load(open('examples/$example/scenario.toml','rb'))['board'][0]['name'])")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# run NAME ARGS...: one run, timed by /usr/bin/time; prints "NAME: wall s, cpu s, ratios".
run() {
  local name=$1
  shift
  /usr/bin/time -f '%e %U %S' -o "$work/$name.time" build/stepdance sim "examples/$example" --quiet --no-vcd \
    --duration "$seconds" --out "$work/$name" "$@" >/dev/null 2>&1 || true
  read -r wall user system <"$work/$name.time"
  python3 -c "
wall, cpu, s = $wall, $user + $system, $seconds
print(f'$name: {s} simulated s in {wall:.1f} s wall, {cpu:.1f} s CPU: {s / wall:.3f}x real time per wall s, {s / cpu:.3f}x per CPU s')"
}

run host
run image --image "$board=$image"
python3 - "$work/image/summary.json" "$board" <<'PY'
import json, sys
firmware = json.load(open(sys.argv[1]))["firmware"][sys.argv[2]]
print(f"image: {firmware['instructions']:.0f} instructions at {firmware['core_clock_hz'] / 1e6:.0f} MHz")
print(f"image: setup() after {firmware['instructions_to_setup']:.0f} instructions, {firmware['time_to_setup_s']:.6f} s")
print(f"image: frame interrupt {firmware['frame_interrupt_instructions_mean']:.1f} instructions per frame "
      f"(tick + stages, {firmware['frame_interrupts']:.0f} frames)")
PY
