#!/usr/bin/env bash
# Installs every Debian 12 package the build, the tests and the tools need (idempotent).
# --web adds emscripten, for the WebAssembly build and its tests (scripts/test.sh passes it;
# scripts/main.sh does not, so the main command installs no emscripten).
set -euo pipefail

packages=(
  cmake g++ make pkg-config git ccache
  libgtest-dev libgmock-dev googletest libbenchmark-dev valgrind
  gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib qemu-system-arm
  gcc-avr avr-libc binutils-avr simavr libsimavr-dev libelf-dev
  libcli11-dev libtomlplusplus-dev nlohmann-json3-dev libcairo2-dev sigrok-cli
  libunicorn-dev  # unicorn: the Cortex-M7 that runs firmware images in the simulator (sim/image)
  libre2-dev  # RE2: scenario reply patterns matched in time linear in the line
  clang  # libFuzzer targets (scripts/fuzz.sh)
  time  # /usr/bin/time: CPU seconds in bench/image_board_speed.sh
  universal-ctags  # function lengths for the structure check (scripts/check-function-length.sh)
  linuxcnc-uspace  # rs274, the independent G-code interpreter the conformance test compares with
  prusa-slicer  # slices the conformance test's 3D-printer sample (tests/interfaces/gcode/conformance/prusaslicer)
  python3 python3-serial  # pyserial: the live simulator's pseudo-terminal tests
  bcnc  # a real Grbl sender driving the live simulator (tests/cli/live/bcnc_sender_test.py)
  libseccomp-dev  # seccomp filters confining the sketch server's runs (docs/web.md)
  libboost-dev  # Boost.Beast and Asio (header-only): HTTP and WebSocket for `stepdance serve`
  chromium chromium-driver python3-selenium  # the web control page tested in headless Chromium
)
if [ "${1:-}" = "--web" ]; then
  packages+=(emscripten)  # the WebAssembly build (scripts/build-web.sh) and the web tests
fi

missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
