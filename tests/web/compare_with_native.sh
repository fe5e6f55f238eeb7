#!/usr/bin/env bash
# Runs every example's scenario natively (`stepdance sim --result-json`) and in the WebAssembly
# build under node (wasm/node/run_scenario.js), and compares the two result documents byte for
# byte: step counts per motor, pen position, strokes, every [[expect]] outcome.
#
#   tests/web/compare_with_native.sh STEPDANCE SITE [EXAMPLE...]
#
# Prints one line per example and "N examples compared, M differences"; fails on any difference.
set -uo pipefail
stepdance=$1
site=$2
shift 2
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [ $# -eq 0 ]; then
  for scenario in "$root"/examples/*/scenario.toml; do set -- "$@" "$(basename "$(dirname "$scenario")")"; done
fi
compared=0
differences=0
for example in "$@"; do
  folder="$root/examples/$example"
  "$stepdance" sim "$folder" --quiet --no-vcd --out "$work/$example-native" --result-json "$work/$example.native.json" \
    >"$work/$example.native.log" 2>&1
  node --no-experimental-fetch "$root/wasm/node/run_scenario.js" "$site" "$folder" --out "$work/$example.wasm.json" \
    >"$work/$example.wasm.log" 2>&1
  compared=$((compared + 1))
  if [ ! -s "$work/$example.native.json" ] || [ ! -s "$work/$example.wasm.json" ]; then
    echo "FAILED  $example: no result (native log, then wasm log:)"
    cat "$work/$example.native.log" "$work/$example.wasm.log"
    differences=$((differences + 1))
  elif ! diff -u "$work/$example.native.json" "$work/$example.wasm.json" >"$work/$example.diff"; then
    echo "FAILED  $example: the WebAssembly run differs from the native one:"
    head -60 "$work/$example.diff"
    differences=$((differences + 1))
  else
    echo "same    $example"
  fi
done
echo "$compared examples compared, $differences differences"
[ "$differences" -eq 0 ]
