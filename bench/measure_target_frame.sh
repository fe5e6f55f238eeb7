#!/usr/bin/env bash
# Counts Cortex-M7 instructions per frame of a benchmark graph under QEMU (mps2-an500) and turns
# them into an estimated share of the frame at 600 MHz (40 us, or STEPDANCE_BENCH_FRAME_PERIOD_US:
# 10, 20, 25 or 40). Method: docs/benchmarks-target.md; periods: docs/high-speed.md.
# Usage: bench/measure_target_frame.sh [frames] [step_a_sketch|step_a_sketch_tbi|gcode_step_a_sketch|harmonograph|clay_texturizer|axidraw_wave|pantograph]
#        (STEPDANCE_QEMU_BUILD_TYPE=MinSizeRel|RelWithDebInfo|...; STEPDANCE_QEMU_LTO=1 compiles the core
#        and the manual backend with -flto -fno-fat-lto-objects, as Teensyduino's LTO settings do)
set -euo pipefail
cd "$(dirname "$0")/.."
frames=${1:-20000}
workload=${2:-step_a_sketch}
build_type=${STEPDANCE_QEMU_BUILD_TYPE:-MinSizeRel}
period_us=${STEPDANCE_BENCH_FRAME_PERIOD_US:-40}
period_suffix=$([ "$period_us" = 40 ] && echo "" || echo "-${period_us}us")
lto=${STEPDANCE_QEMU_LTO:-0}
case $lto in 0) lto_option=OFF lto_suffix="" ;; 1) lto_option=ON lto_suffix=-lto ;;
  *) echo "bench: STEPDANCE_QEMU_LTO must be 0 or 1, got '$lto'" >&2; exit 2 ;; esac
build_dir=${STEPDANCE_QEMU_BENCH_DIR:-build-qemu-m7-bench-$build_type$lto_suffix-$workload$period_suffix}
budget_cycles=$((period_us * 600))         # the frame period at 600 MHz (24 000 at 40 us)
run_frame_symbol=_ZN9stepdance6Engine9run_frameEv

cmake -S targets/qemu-m7 -B "$build_dir" -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/cortex-m7.cmake" \
  -DCMAKE_BUILD_TYPE="$build_type" -DSTEPDANCE_BENCH_FRAMES="$frames" -DSTEPDANCE_BENCH_WORKLOAD="$workload" \
  -DSTEPDANCE_BENCH_FRAME_PERIOD_US="$period_us" -DSTEPDANCE_QEMU_LTO=$lto_option >/dev/null
cmake --build "$build_dir" -j"$(nproc)" --target bench_frame >/dev/null
image="$build_dir/bench_frame.elf"
qemu=(qemu-system-arm -M mps2-an500 -cpu cortex-m7 -nographic -monitor none
      -semihosting-config enable=on,target=native -kernel "$image")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# ---- Method 1: -icount shift=0 (1 ns of virtual time per instruction) and the 25 MHz CMSDK timer --
timeout 600 "${qemu[@]}" -icount shift=0 </dev/null >"$work/icount.txt"
known_ticks=$(sed -n 's/^known_loop iterations=[0-9]* timer_ticks=\([0-9]*\).*/\1/p' "$work/icount.txt")
frame_ticks=$(sed -n 's/^frames count=[0-9]* timer_ticks=\([0-9]*\).*/\1/p' "$work/icount.txt")
[ -n "$known_ticks" ] && [ -n "$frame_ticks" ] || { cat "$work/icount.txt"; echo "bench: no timer figures" >&2; exit 1; }

# ---- Method 2: single-instruction translation blocks, every executed block logged with its symbol --
# The log streams through a FIFO into awk, which counts instructions per frame inside
# Engine::run_frame (entered at its symbol, left at the first instruction back in the harness)
# and classifies each by the mnemonic objdump gives for its address.
arm-none-eabi-objdump -d "$image" | awk -F'\t' '$1 ~ /^ *[0-9a-f]+:$/ && NF >= 3 {
  address = $1; gsub(/[ :]/, "", address); split($3, word, /[ .]/); print address, word[1] }' >"$work/mnemonics"
mkfifo "$work/trace"
awk -v run_frame="$run_frame_symbol" -v per_frame="$work/per_frame" '
  FILENAME != "-" { mnemonic[$1] = $2; next }
  !/^Trace / { next }
  {
    symbol = NF >= 5 ? $5 : ""
    split($4, fields, "/"); pc = fields[2]; sub(/^0+/, "", pc)
    if (symbol == "bench_region_begin") { ++region; in_region = 1; next }
    if (symbol == "bench_region_end") { in_region = 0; next }
    if (!in_region) next
    if (region == 1) { if (symbol == "bench_known_loop") ++known; next }
    ++region_total
    if (symbol == run_frame && !inside) { inside = 1; ++frames; current = 0 }
    else if (inside && (symbol == "main" || symbol ~ /run_busy_frame/)) {
      inside = 0; total += current; print current > per_frame
      if (current > worst) { worst = current; worst_index = frames - 1 }
      if (frames == 1 || current < best) best = current
    }
    if (!inside) next
    ++current
    ++by_symbol[symbol]
    if (symbol ~ /^_ZN9stepdance3hal/) ++hal
    m = mnemonic[pc]
    if (m ~ /^v(div|sqrt)/) ++fp_long
    else if (m ~ /^(vldr|vstr|vldm|vstm|vpush|vpop|vmov|vmrs|vmsr)/) ++fp_move
    else if (m ~ /^v/) ++fp_arith
    else if (m ~ /^(sdiv|udiv)/) ++int_div
    else if (m ~ /^(ldr|ldm|pop)/) ++loads
    else if (m ~ /^(str|stm|push)/) ++stores
    else if (m ~ /^(b|bl|blx|bx|cbz|cbnz|tbb|tbh)$/ || m ~ /^b(eq|ne|cs|cc|hs|lo|mi|pl|vs|vc|hi|ls|ge|lt|gt|le)$/) ++branches
    else ++other
  }
  END {
    printf "known_loop_instructions %d\nregion_instructions %d\nframes %d\n", known, region_total, frames
    printf "run_frame_instructions %d\nworst_frame %d\nworst_index %d\nbest_frame %d\n", total, worst, worst_index, best
    printf "mix_loads %d\nmix_stores %d\nmix_branches %d\nmix_fp_arith %d\nmix_fp_move %d\n", loads, stores, branches, fp_arith, fp_move
    printf "mix_fp_div_sqrt %d\nmix_int_div %d\nmix_other %d\nhal_instructions %d\n", fp_long, int_div, other, hal
    for (name in by_symbol) printf "symbol %d %s\n", by_symbol[name], name
  }' "$work/mnemonics" - <"$work/trace" >"$work/trace.txt" &
counter=$!
timeout 1800 "${qemu[@]}" -singlestep -d exec,nochain -D "$work/trace" </dev/null >"$work/singlestep.txt"
wait $counter
value() { sed -n "s/^$1 //p" "$work/trace.txt"; }

known=$(value known_loop_instructions)
expected_known=2000001                    # 1 000 000 x (subs + bne) + bx lr
counted_frames=$(value frames)
total=$(value run_frame_instructions)
region=$(value region_instructions)
icount_region=$((frame_ticks * 40))
if [ "$known" -ne $expected_known ] || [ $((known_ticks * 40 - expected_known)) -gt 40 ] ||
   [ $((expected_known - known_ticks * 40)) -gt 40 ] || [ "$counted_frames" -ne "$frames" ]; then
  cat "$work/icount.txt" "$work/trace.txt"
  echo "bench: the known loop or the frame count does not check out; the figures are not trustworthy" >&2
  exit 1
fi

per_frame=$(awk -v t="$total" -v f="$frames" 'BEGIN { printf "%.1f", t / f }')
echo "image: $image ($build_type$([ "$lto_option" = ON ] && echo ", LTO"), Cortex-M7 hard-float double)"
echo "known loop (2 000 001 instructions): single-step trace $known, icount timer $((known_ticks * 40)) (+-40)"
echo "frames measured: $frames"
echo "instructions in the measured region: single-step trace $region, icount timer $icount_region (+-40)"
echo "instructions in Engine::run_frame: $total"
percentile() { sort -n "$work/per_frame" | awk -v p="$1" '{ v[NR] = $1 } END { i = int(NR * p / 100); print v[i < 1 ? 1 : i] }'; }
echo "instructions per frame: mean $per_frame, min $(value best_frame), median $(percentile 50)," \
  "99th percentile $(percentile 99), max $(value worst_frame) (frame $(value worst_index))"
awk -v f="$frames" -v t="$total" '
  { value[$1] = $2 }
  END {
    printf "mix per frame: loads %.1f, stores %.1f, branches %.1f, FP arithmetic %.1f, FP moves %.1f,", \
      value["mix_loads"] / f, value["mix_stores"] / f, value["mix_branches"] / f, value["mix_fp_arith"] / f, value["mix_fp_move"] / f
    printf " FP divide/sqrt %.2f, integer divide %.2f, other %.1f\n", value["mix_fp_div_sqrt"] / f, value["mix_int_div"] / f, value["mix_other"] / f
  }' "$work/trace.txt"
echo "of which in the manual backend's HAL functions (stand-ins for the Teensy backend):" \
  "$(awk -v h="$(value hal_instructions)" -v f="$frames" 'BEGIN { printf "%.1f", h / f }') per frame"
echo "instructions per frame by function (own instructions, not callees):"
sed -n 's/^symbol //p' "$work/trace.txt" | sort -rn | head -12 |
  while read -r count name; do
    printf '  %7.1f  %s\n' "$(awk -v c="$count" -v f="$frames" 'BEGIN { print c / f }')" "$(echo "$name" | arm-none-eabi-c++filt)"
  done
# Cycle estimate (assumptions in docs/benchmarks-target.md): instructions x CPI at 1.0 (code and
# data in ITCM/DTCM, as on the Teensy 4) and 1.5 (conservative); the pessimistic line adds 30
# cycles per double-precision divide/square root and 50 cycles of exception entry, exit and
# lazy FP stacking.
awk -v t="$total" -v f="$frames" -v worst="$(value worst_frame)" -v long="$(value mix_fp_div_sqrt)" \
    -v budget=$budget_cycles 'BEGIN {
  mean = t / f; long_per_frame = long / f
  for (i = 1; i <= 3; ++i) {
    cpi = i == 1 ? 1.0 : 1.5
    extra = i == 3 ? long_per_frame * 30 + 50 : 0
    label = i == 3 ? "pessimistic (CPI 1.5 + divides + ISR entry)" : sprintf("CPI %.1f", cpi)
    printf "%s: mean %.0f cycles = %.1f%% of the %d-cycle frame; worst frame %.0f cycles = %.1f%%\n", label, \
      mean * cpi + extra, 100 * (mean * cpi + extra) / budget, budget, worst * cpi + extra, 100 * (worst * cpi + extra) / budget
  }
}'
