#!/usr/bin/env bash
# Developer check (not in CI): builds the original Stepdance library's example sketches through
# our simulator's sketch builder and prints pass/fail for each, with the first compiler error.
#
# Usage: scripts/check-original-examples.sh EXAMPLES_DIR [--all]
#   EXAMPLES_DIR  a local copy of the original's lib/examples folder (github.com/imoyer/stepdance);
#                 nothing of it is copied into this repository.
#   --all         every sketch folder under EXAMPLES_DIR, not only the 33 that issue 9 lists.
# Needs a host build (scripts/build-host.sh): uses build/stepdance-sketch-build, or the one in
# $STEPDANCE_BUILD_DIR. Exit status 0 if every sketch checked compiled.
set -euo pipefail
cd "$(dirname "$0")/.."

examples=${1:?usage: $0 EXAMPLES_DIR [--all]}
builder=${STEPDANCE_BUILD_DIR:-build}/stepdance-sketch-build
[ -x "$builder" ] || { echo "check-original-examples: $builder is missing (run scripts/build-host.sh)" >&2; exit 2; }
[ -d "$examples" ] || { echo "check-original-examples: $examples is not a folder" >&2; exit 2; }

# The original's examples that compile against it and need only what issue 9 covers.
listed=(
  3D_printer_examples/polar_cartesian_3dprinter archived_examples/clay_3dprinter_texturizer_modularized
  axidraw_examples/harmonograph axidraw_examples/harmonograph_basic_module axidraw_examples/polar_to_cartesian
  axidraw_examples/stepasketch axidraw_examples/stepasketch_with_generator
  basic_module_examples/joystick_basic_module basic_module_examples/physical_ui_module button_toggle_three_state
  cmc_course/01_motion_streams_demo cmc_course/01_step_a_sketch cmc_course/01_step_a_sketch_finished
  cmc_course/02_intro_to_interpreters module_driver_template
  snippets/analog_input snippets/analog_input_callback snippets/button snippets/channel snippets/input_port
  snippets/output_port
  stepdance_paper_examples/clay_3dprinter_texturizer_modularized_v2 stepdance_paper_examples/pantograph
  stepdance_paper_examples/pantograph_basic_module stepdance_paper_examples/polar_cartesian_3dprinter_extrusion
  stepdance_paper_examples/stepasketch_with_inputs
  tests/all_input_test tests/analog_in_test tests/digital_in_test tests/encoder_test tests/limit_in_test
  tests/set_motor_currents wheelbot
)
if [ "${2:-}" = "--all" ]; then
  mapfile -t sketches < <(cd "$examples" && find . -name '*.ino' -printf '%h\n' | sed 's|^\./||' | LC_ALL=C sort -u)
else
  sketches=("${listed[@]}")
fi

passed=0
failed=0
log=$(mktemp)
trap 'rm -f "$log"' EXIT
for sketch in "${sketches[@]}"; do
  if "$builder" "$examples/$sketch" >"$log" 2>&1; then
    printf 'pass  %s\n' "$sketch"
    passed=$((passed + 1))
  else
    first_error=$(grep -m1 -E 'error|not found' "$log" | sed "s|$examples/||" || true)
    printf 'FAIL  %s\n      %s\n' "$sketch" "$first_error"
    failed=$((failed + 1))
  fi
done
echo "check-original-examples: $passed compiled, $failed failed, of ${#sketches[@]}"
[ "$failed" -eq 0 ]
