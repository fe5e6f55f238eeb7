#!/usr/bin/env bash
# Prints the WebAssembly build's figures for docs/web.md: the site's module sizes (raw and gzip
# -9), and Step-A-Sketch's simulation speed under node against the native build in the same run
# (best of N runs each, the VCD off, loading left out on both sides).
# Usage: bench/measure_web.sh [runs]   (builds nothing: run scripts/build-host.sh and
# scripts/build-web.sh first)
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${STEPDANCE_BUILD_DIR:-build}
site=${STEPDANCE_WEB_SITE_DIR:-build/web}
runs=${1:-5}
[ -x "$build_dir/stepdance" ] || { echo "build first: scripts/build-host.sh (missing $build_dir/stepdance)" >&2; exit 1; }
[ -f "$site/stepdance_web.wasm" ] || { echo "build first: scripts/build-web.sh (missing $site/stepdance_web.wasm)" >&2; exit 1; }

echo "== sizes (bytes: raw, gzip -9)"
size_row() { printf '%-40s %10d %10d\n' "$1" "$(stat -c %s "$2")" "$(gzip -9c "$2" | wc -c)"; }
size_row "host module stepdance_web.wasm" "$site/stepdance_web.wasm"
size_row "loader stepdance_web.js" "$site/stepdance_web.js"
size_row "board StepASketch.wasm" "$site/boards/StepASketch.wasm"
total_raw=0
total_gz=0
for board in "$site"/boards/*.wasm; do
  total_raw=$((total_raw + $(stat -c %s "$board")))
  total_gz=$((total_gz + $(gzip -9c "$board" | wc -c)))
done
printf '%-40s %10d %10d\n' "all $(ls "$site"/boards/*.wasm | wc -l) boards" "$total_raw" "$total_gz"

echo "== Step-A-Sketch, simulated seconds per wall second (best of $runs)"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
best_native=0
for _ in $(seq "$runs"); do
  line=$("$build_dir/stepdance" sim examples/StepASketch --no-vcd --out "$out/native" | grep '^simulated ')
  speed=$(echo "$line" | sed -n 's/^simulated \([0-9.]*\) s in \([0-9.]*\) s.*/\1 \/ \2/p')
  best_native=$(python3 -c "print(round(max($best_native, $speed)))")
done
best_wasm=$(node --no-experimental-fetch wasm/node/run_scenario.js "$site" examples/StepASketch --repeat "$runs" \
  --out "$out/wasm.json" 2>&1 | sed -n 's/.*(\([0-9.]*\)x real time.*/\1/p' | sort -n | tail -1)
echo "native: ${best_native}x real time"
echo "wasm under node $(node --version): ${best_wasm}x real time"
python3 -c "print(f'native / wasm: {$best_native / $best_wasm:.2f}')"
