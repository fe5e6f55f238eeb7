#!/usr/bin/env bash
# Sets up the machine, builds, and runs the main job: the engine demo printing a decoded frame trace.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build-host.sh >/dev/null
"${STEPDANCE_BUILD_DIR:-build}"/stepdance_demo "$@"
