#!/usr/bin/env bash
# Builds the WebAssembly site (docs/web.md) with Debian's emscripten: the simulator library as the
# host module, each example's board as a side module, the JavaScript API and the examples'
# files, into build/web/ (STEPDANCE_WEB_SITE_DIR), compiled in build-web/ (STEPDANCE_WEB_BUILD_DIR).
# scripts/setup.sh installs emscripten.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${STEPDANCE_WEB_BUILD_DIR:-build-web}
site_dir=$(mkdir -p "${STEPDANCE_WEB_SITE_DIR:-build/web}" && cd "${STEPDANCE_WEB_SITE_DIR:-build/web}" && pwd)
if ! command -v emcmake >/dev/null 2>&1; then
  echo "build-web: emscripten is not installed (scripts/setup.sh installs it)" >&2
  exit 1
fi
# This machine's node is not Debian's: emcc finds Debian's acorn only through NODE_PATH.
export NODE_PATH=${NODE_PATH:-/usr/share/nodejs}

# The IDE's sketch preparation, as a host tool (as scripts/build-teensy.sh builds it).
case $build_dir in /*) ;; *) build_dir="$PWD/$build_dir" ;; esac
prep="$build_dir/tools/stepdance-sketch-prep"
prep_sources=(tools/sketch/sketch_prep_main.cpp sim/board/loader/sketch_prototypes.cpp
  sim/board/loader/sketch_sources.cpp)
prep_stale=0
[ -x "$prep" ] || prep_stale=1
for source in "${prep_sources[@]}" sim/board/loader/*.hpp; do [ "$source" -nt "$prep" ] && prep_stale=1; done
if [ $prep_stale -eq 1 ]; then
  mkdir -p "$(dirname "$prep")"
  c++ -std=gnu++17 -O1 -Isim "${prep_sources[@]}" -o "$prep"
fi

launcher=()
if command -v ccache >/dev/null 2>&1; then
  export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$(cd .. && pwd)}
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
emcmake cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DSTEPDANCE_TESTS=OFF -DSTEPDANCE_BENCH=OFF \
  -DSTEPDANCE_SERVO_FIRMWARE=OFF -DSTEPDANCE_SKETCH_PREP="$prep" -DSTEPDANCE_WEB_SITE_DIR="$site_dir" \
  "${launcher[@]}" "$@" >/dev/null
cmake --build "$build_dir" -j"$(nproc)"
echo "build-web: the site is in $site_dir"
