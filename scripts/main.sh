#!/usr/bin/env bash
# Sets up the machine, builds, and runs the main job: the Step-A-Sketch example sketch on the
# simulator. Two knobs and a pen button draw a house on a simulated AxiDraw; the drawing goes to
# out/step-a-sketch/drawing.svg and drawing.png, and the replay page (the run under a time slider,
# one HTML file that opens offline) to out/step-a-sketch/replay.html. Extra arguments go to
# `stepdance sim`.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build-host.sh >/dev/null
out_dir=out/step-a-sketch
"${STEPDANCE_BUILD_DIR:-build}"/stepdance sim examples/StepASketch --out "$out_dir" --html "$out_dir/replay.html" "$@"
echo "The drawing is in $out_dir/drawing.svg and $out_dir/drawing.png; the replay page is $out_dir/replay.html."
