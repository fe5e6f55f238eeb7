#!/usr/bin/env bash
# Sets up the machine, builds, and runs the main job: the Step-A-Sketch example sketch on the
# simulator. Two knobs and a pen button draw a house on a simulated AxiDraw; the drawing goes to
# out/step-a-sketch/drawing.svg and drawing.png, and the replay page (the run under a time slider,
# one HTML file that opens offline) to out/step-a-sketch/replay.html. Extra arguments go to
# `stepdance sim`.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --main
build_dir=${STEPDANCE_BUILD_DIR:-build}
# A fresh tree is configured for the `stepdance` command alone (no tests, benchmarks or servo
# firmware: their packages are scripts/test.sh's); a tree configured before keeps its settings.
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  launcher=()
  if command -v ccache >/dev/null 2>&1; then
    export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$(cd .. && pwd)}
    launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  fi
  cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSTEPDANCE_TESTS=OFF -DSTEPDANCE_BENCH=OFF \
    -DSTEPDANCE_SERVO_FIRMWARE=OFF "${launcher[@]}" >/dev/null
fi
cmake --build "$build_dir" --target stepdance -j"$(nproc)" >/dev/null
out_dir=out/step-a-sketch
"$build_dir"/stepdance sim examples/StepASketch --out "$out_dir" --html "$out_dir/replay.html" "$@"
echo "The drawing is in $out_dir/drawing.svg and $out_dir/drawing.png; the replay page is $out_dir/replay.html."
