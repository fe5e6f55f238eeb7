#!/usr/bin/env bash
# Builds the libFuzzer targets in fuzz/ with clang (ASan + UBSan) and runs them on their corpora.
#   scripts/fuzz.sh                 short smoke run of every target (CI)
#   scripts/fuzz.sh gcode 10000000  one target for a number of executions (the documented long run)
# STEPDANCE_FUZZ_TIMEOUT_S (default 10) is libFuzzer's per-input wall-clock limit: raise it for a
# long run on a loaded machine, which stretches wall time, not the work.
# STEPDANCE_FUZZ_WORKERS (default 1) splits a run's executions between that many processes sharing
# one corpus, each with its own log (<target>-worker<N>.log) and random seed.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${STEPDANCE_FUZZ_DIR:-build-fuzz}
mkdir -p "$build"

# Portable-core folders (every .cpp in them) or files each target links besides its fuzz file.
# "core" stands for the whole portable core and the manual board (hosts whole blocks).
# The Grbl link without its block (GCodeInterface, its homing and its steps/mm check need the whole core).
gcode_link_sources="$(find src/stepdance/interfaces/gcode -name '*.cpp' ! -name 'gcode_interface.cpp' ! -name 'gcode_homing.cpp' ! -name 'gcode_steps_per_mm.cpp' | sort | tr '\n' ' ')"
gcode_link_sources+="src/stepdance/interfaces/link/line_reader.cpp src/stepdance/interfaces/link/reply_ring.cpp src/stepdance/core/text_writer.cpp"
declare -A target_sources=(
  [gcode]="$gcode_link_sources"
  [grbl]="$gcode_link_sources"
  [ebb]="core"
  [rpc]="core"
  [scenario]="sim/scenario sim/kinds sim/kinds/devices sim/kinds/machines sim/kinds/expectations sim/models servo/pulse/servo_pulse.c"
  [vcd]="cli/decode/vcd_reader.cpp cli/decode/vcd_tokenizer.cpp cli/decode/step_dir_pairs.cpp cli/decode/capture_decoder.cpp src/stepdance/protocol/pulse_decoder.cpp"
)
# Extra compiler flags: the scenario reader sees sim/ (it also links the device, machine and
# expectation kinds, whose rows hold their models' factories and their checks), the capture reader sim/ and cli/; toml++ is compiled in from its header
# (Debian's libtomlplusplus-dev) so the fuzzer also instruments the TOML parser.
declare -A target_flags=(
  [scenario]="-Isim -Iservo/pulse -DTOML_HEADER_ONLY=1"
  [vcd]="-Isim -Icli"
)
# Libraries a target links besides its objects: reply patterns are RE2 (Debian's libre2-dev).
declare -A target_libs=(
  [scenario]="$(pkg-config --libs re2)"
)
# Longest input per target (default 4096 bytes): the example scenarios are up to 6 KB.
declare -A target_max_len=([scenario]=8192)

# Sources of one target, one per line.
sources_of() {
  local name=$1
  for entry in ${target_sources[$name]}; do
    if [ "$entry" = core ]; then
      find src/stepdance -name '*.cpp' -not -path '*/platform/*' | sort
      printf '%s\n' src/stepdance/platform/manual/hal_manual.cpp src/stepdance/platform/manual/i2c_manual.cpp
    elif [ -d "$entry" ]; then
      # The WebAssembly build's versions of native sources (docs/architecture.md) are left out.
      printf '%s\n' "$entry"/*.cpp | grep -v -e '_ecmascript\.cpp$' -e '_wasm\.cpp$' -e '_none\.cpp$'
    else
      printf '%s\n' "$entry"
    fi
  done
  echo "fuzz/${name}_fuzz.cpp"
}

# Object of a source compiled with a target's extra flags; targets with the same flags share it.
object_of() {
  local flags_key
  flags_key=$(printf '%s' "$1" | md5sum | cut -c1-8)
  echo "$build/obj/$flags_key/${2//\//__}.o"
}

compile_object() {
  local flags=$1 source=$2 object=$3
  mkdir -p "$(dirname "$object")"
  local compiler=(clang++ -std=c++17)
  [[ $source == *.c ]] && compiler=(clang -std=c99)  # the servo's pulse arithmetic is C
  # shellcheck disable=SC2086 # the flags are words
  "${compiler[@]}" -O1 -g -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all \
    -Isrc -Isrc/stepdance/platform/manual -DSTEPDANCE_PLATFORM_MANUAL $flags -c "$source" -o "$object"
}
export -f compile_object

# Compiles every object the targets need once, on every core, then links each target.
build_targets() {
  local name source flags jobs=()
  declare -A seen=()
  for name in "$@"; do
    flags=${target_flags[$name]:-}
    while read -r source; do
      local object
      object=$(object_of "$flags" "$source")
      [ -n "${seen[$object]:-}" ] && continue
      seen[$object]=1
      jobs+=("$flags" "$source" "$object")
    done < <(sources_of "$name")
  done
  printf '%s\0' "${jobs[@]}" |
    xargs -0 -n 3 -P "$(nproc)" bash -c 'compile_object "$1" "$2" "$3"' _
  for name in "$@"; do
    local objects=()
    flags=${target_flags[$name]:-}
    while read -r source; do objects+=("$(object_of "$flags" "$source")"); done < <(sources_of "$name")
    # shellcheck disable=SC2086 # the libraries are words
    clang++ -fsanitize=fuzzer,address,undefined "${objects[@]}" ${target_libs[$name]:-} -o "$build/${name}_fuzz"
  done
}

# One libFuzzer process: a target, a number of executions, its log and its seed option.
run_worker() {
  local name=$1 runs=$2 log=$3 seed=$4
  local work="$build/${name}_corpus"
  "$build/${name}_fuzz" -runs="$runs" ${seed:+"$seed"} -max_len="${target_max_len[$name]:-4096}" -timeout="${STEPDANCE_FUZZ_TIMEOUT_S:-10}" -print_final_stats=1 \
    -artifact_prefix="$build/${name}-" "$work" "fuzz/corpus/$name" >"$log" 2>&1
}

run_target() {
  local name=$1 runs=$2 workers=${STEPDANCE_FUZZ_WORKERS:-1}
  mkdir -p "$build/${name}_corpus"
  # Inputs that once failed (fuzz/regressions/<target>/) must keep passing.
  if compgen -G "fuzz/regressions/$name/*" >/dev/null; then
    "$build/${name}_fuzz" fuzz/regressions/"$name"/* >"$build/${name}-regressions.log" 2>&1 ||
      { cat "$build/${name}-regressions.log"; echo "fuzz: $name regression inputs FAILED"; return 1; }
  fi
  # The checked-in seeds stay untouched; new inputs go to the build folder, shared by the workers
  # (libFuzzer reloads it), which split the executions between them.
  local logs=() pids=() worker
  for ((worker = 1; worker <= workers; ++worker)); do
    local log="$build/${name}.log"
    [ "$workers" -gt 1 ] && log="$build/${name}-worker${worker}.log"
    logs+=("$log")
    local seed=""  # a fixed walk for the smoke run, one per worker
    [ -n "$fixed_seed" ] && seed="-seed=$((${STEPDANCE_FUZZ_SEED:-1} + worker - 1))"
    run_worker "$name" $(((runs + workers - 1) / workers)) "$log" "$seed" &
    pids+=($!)
  done
  local failed=0
  for ((worker = 0; worker < workers; ++worker)); do
    local log=${logs[$worker]}
    if ! wait "${pids[$worker]}"; then
      grep -A 30 -E "ERROR|runtime error|deadly signal|timeout" "$log" | head -n 60
      echo "fuzz: $name FAILED (full log: $log; reproducer: $build/${name}-*)"
      failed=1
    else
      grep -E "^Done|stat::number_of_executed_units|stat::new_units_added|stat::peak_rss_mb" "$log"
    fi
  done
  return "$failed"
}

fixed_seed=""
if [ $# -ge 1 ]; then
  targets=("$1")
  runs=${2:-1000000}
else
  targets=("${!target_sources[@]}")
  runs=${STEPDANCE_FUZZ_SMOKE_RUNS:-20000}
  # The smoke run is a fixed walk (same seed, and a fresh clone starts from the checked-in seeds
  # alone), so CI's verdict repeats; long runs take a new random seed each time.
  fixed_seed=yes
fi
export build
build_targets "${targets[@]}"
for name in "${targets[@]}"; do
  echo "fuzz: $name, $runs executions"
  run_target "$name" "$runs"
done
