#!/usr/bin/env bash
# Developer check, not run in CI: compiles and links the library and every example against the
# real Teensyduino core (Teensy 4.0 and 4.1), with our -Werror flags and the core's headers as
# system headers, linked as the Arduino IDE links them (the core as an archive, only the libraries
# the sources include); counts the heap and exception symbols in every image (all must be 0, and
# two allocating probe sketches must be caught) and prints each image's size as Teensyduino's
# teensy_size does.
#
# Usage: scripts/check-teensyduino.sh TEENSY_AVR_DIR
#   TEENSY_AVR_DIR is Teensyduino's hardware/teensy/avr folder, e.g.
#   ~/.arduino15/packages/teensy/hardware/avr/1.59.0 (Arduino IDE 2 with Teensyduino 1.59), which
#   holds cores/teensy4 and libraries/{SD,SdFat,SPI,Wire}. docs/hardware-backend.md ("Checking against
#   the real core") shows how to assemble the same tree from the public repositories.
# Output in build-teensyduino/ (or $STEPDANCE_TEENSY_BUILD_DIR). STEPDANCE_TEENSY_LTO=1 builds with
# link-time optimisation instead (build-teensyduino-lto/).
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -eq 1 ] || { sed -n '2,15p' "$0" >&2; exit 2; }
avr=$(realpath "$1")
[ -f "$avr/cores/teensy4/imxrt.h" ] || { echo "check-teensyduino: $avr/cores/teensy4/imxrt.h not found" >&2; exit 1; }
STEPDANCE_TEENSYDUINO=$avr exec scripts/build-teensy.sh
