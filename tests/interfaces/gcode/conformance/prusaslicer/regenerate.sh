#!/usr/bin/env bash
# Makes prism.gcode, the slicer sample of the rs274 conformance test, from its sources: the STL
# written by prism_stl.py and the settings in prism.ini, sliced by Debian's PrusaSlicer 2.5.
# Usage: regenerate.sh [OUTPUT.gcode]   (default: prism.gcode beside this script)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
output=$(realpath -m "${1:-$here/prism.gcode}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$here/prism_stl.py" "$work/prism.stl"
prusa-slicer --load "$here/prism.ini" --export-gcode "$work/prism.stl" -o "$work/prism.gcode" >"$work/log" 2>&1 ||
  { cat "$work/log" >&2; exit 1; }
# The first line names the time of slicing; everything else depends only on the inputs.
sed '1s/ on [0-9-]* at [0-9:]* UTC$//' "$work/prism.gcode" >"$output"
