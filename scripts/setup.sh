#!/usr/bin/env bash
# Installs the Debian 12 packages a purpose needs (idempotent):
#
#   scripts/setup.sh --main   the main job (scripts/main.sh): a compiler, CMake and the libraries
#                             the `stepdance` command links; nothing for tests, targets or tools
#   scripts/setup.sh          everything the build, the tests and the tools need (the default)
#   scripts/setup.sh --web    everything, and emscripten for the WebAssembly build and its tests
#                             (scripts/test.sh passes it)
#
# --dry-run prints the packages the purpose needs, one a line, and installs nothing.
set -euo pipefail

# The main job: configure the host tree without tests, benchmarks or servo firmware, build
# `stepdance`, run Step-A-Sketch (its sketch compiled by g++ at run time, the PNG drawn by cairo).
main_packages=(
  cmake g++ make pkg-config
  libcli11-dev libtomlplusplus-dev nlohmann-json3-dev libcairo2-dev
  libunicorn-dev  # unicorn: the Cortex-M7 that runs firmware images in the simulator (sim/image)
  libre2-dev  # RE2: scenario reply patterns matched in time linear in the line
  libseccomp-dev  # seccomp filters confining the sketch server's runs (docs/web.md)
  libboost-dev  # Boost.Beast and Asio (header-only): HTTP and WebSocket for `stepdance serve`
)
# The tests, the targets and the tools, on top of the main job's.
test_packages=(
  git ccache
  libgtest-dev libgmock-dev googletest libbenchmark-dev valgrind
  gcc-arm-none-eabi libnewlib-arm-none-eabi libstdc++-arm-none-eabi-newlib qemu-system-arm
  gcc-avr avr-libc binutils-avr simavr libsimavr-dev libelf-dev
  sigrok-cli
  clang  # libFuzzer targets (scripts/fuzz.sh)
  libclang-rt-14-dev  # clang's libFuzzer and sanitizer runtimes: only a Recommends of clang, so a bare Debian lacks them
  time  # /usr/bin/time: CPU seconds in bench/image_board_speed.sh
  universal-ctags  # function lengths for the structure check (scripts/check-function-length.sh)
  clang-format  # clang-format 14: the C/C++ style check (scripts/check-format.sh, scripts/format.sh)
  linuxcnc-uspace  # rs274, the independent G-code interpreter the conformance test compares with
  prusa-slicer  # slices the conformance test's 3D-printer sample (tests/interfaces/gcode/conformance/prusaslicer)
  python3 python3-serial  # pyserial: the live simulator's pseudo-terminal tests
  bcnc  # a real Grbl sender driving the live simulator (tests/cli/live/bcnc_sender_test.py)
  chromium chromium-driver python3-selenium  # the web control page tested in headless Chromium
)
web_packages=(
  emscripten  # the WebAssembly build (scripts/build-web.sh) and the web tests
)

purpose=all
dry_run=0
for argument in "$@"; do
  case $argument in
    --main) purpose=main ;;
    --web) purpose=web ;;
    --dry-run) dry_run=1 ;;
    *) echo "setup: unknown option '$argument' (--main, --web, --dry-run)" >&2; exit 2 ;;
  esac
done
packages=("${main_packages[@]}")
if [ "$purpose" != main ]; then packages+=("${test_packages[@]}"); fi
if [ "$purpose" = web ]; then packages+=("${web_packages[@]}"); fi
if [ $dry_run -eq 1 ]; then
  printf '%s\n' "${packages[@]}"
  exit 0
fi

missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present ($purpose)"
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
