#!/usr/bin/env bash
# Many boards: N ChainedKnobsBasic boards (Basic Modules, no cables) over 2 simulated seconds,
# for N = 1, 10, 100, 1000 (or the counts given), timed with `stepdance sim --quiet --no-vcd`.
# Usage: bench/many_boards.sh [STEPDANCE] [N…]   (docs/simulator.md, "Many boards")
set -euo pipefail
cd "$(dirname "$0")/.."
stepdance=${1:-build/stepdance}
shift || true
counts=("${@:-1 10 100 1000}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sketch=$(pwd)/examples/ChainedKnobsBasic/ChainedKnobsBasic.ino
# The sketch built once beforehand, so the figures are the runs' own.
printf 'duration_s = 0.01\n[[board]]\nname = "b0"\nsketch = "%s"\nmodule = "basic"\n' "$sketch" > "$work/warm.toml"
"$stepdance" sim --quiet --no-vcd --out "$work/out" "$work/warm.toml" >/dev/null
# The machine is shared: CPU seconds (user + system) are the steadier figure.
printf '%8s %10s %10s %16s %12s\n' boards wall_s cpu_s cpu_per_board_s max_rss_mb
for n in ${counts[*]}; do
  scenario="$work/boards-$n.toml"
  echo 'duration_s = 2' > "$scenario"
  for ((i = 0; i < n; ++i)); do
    printf '[[board]]\nname = "b%d"\nsketch = "%s"\nmodule = "basic"\n' "$i" "$sketch" >> "$scenario"
  done
  /usr/bin/time -f '%e %U %S %M' -o "$work/time" "$stepdance" sim --quiet --no-vcd --out "$work/out-$n" "$scenario" >/dev/null
  read -r wall user sys rss_kb < "$work/time"
  awk -v n="$n" -v wall="$wall" -v user="$user" -v sys="$sys" -v rss="$rss_kb" \
    'BEGIN { cpu = user + sys; printf "%8d %10.2f %10.2f %16.4f %12.0f\n", n, wall, cpu, cpu / n, rss / 1024 }'
done
