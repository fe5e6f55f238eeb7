#!/usr/bin/env bash
# Cross-compiles the library and every example for the Teensy 4.x against the Teensyduino stand-in,
# links the images, reports flash/RAM use, rejects heap/exception symbols and checks the library zip.
# Sketch folders are prepared as the Arduino IDE does (.ino files concatenated, prototypes
# generated, .c/.cpp beside them compiled) by the simulator's own preparation code, built here for
# the host. The compile-only sketch fixtures under tests/sim/assembly/fixtures are compiled too.
#
# Usage: scripts/build-teensy.sh      (output in build-teensy/, or $STEPDANCE_TEENSY_BUILD_DIR)
# The images link against our stand-in for Teensyduino's core (targets/teensy/stand-in): it starts
# the chip as a Teensy does (docs/hardware-backend.md, "The CI stand-in core boots") so the simulator
# can run the images; they prove the code compiles and links and give its size. Untested on a board.
#
# Developer check against the real core (not in CI; scripts/check-teensyduino.sh wraps it):
#   STEPDANCE_TEENSYDUINO=DIR scripts/build-teensy.sh
# DIR is a Teensyduino tree laid out as hardware/teensy/avr: cores/teensy4 and libraries/{SD,SdFat,SPI,
# Wire}. The core and those libraries are then compiled with Teensyduino's own flags (their warnings
# silenced, as in the IDE), our library and the examples with ours (-Werror); the images link with
# the core's linker scripts and sizes are printed as Teensyduino's teensy_size prints them.
#
# Images link as the Arduino IDE links them: the sketch's and the libraries' objects, then the core
# as an archive (core.a), whose members join only when something needs them. A library links when
# our sources, the sketch or a linked library include one of its headers (the IDE's library
# discovery, read from the compiler's dependency files; the stand-in models SD and SdFat as
# libraries). Every image is then checked for heap and exception symbols, against either core, and
# two probe sketches that do allocate must fail that check.
#
# Third-party headers (the stand-in or the real core and its libraries) are system headers
# (-isystem): their warnings cannot fail our -Werror build.
#
# STEPDANCE_TEENSY_LTO=1 builds everything as the "Faster with LTO" entry of Teensyduino's boards.txt
# would (it is commented out for the Teensy 4.x): -O2 -flto -fno-fat-lto-objects, linked with
# -fuse-linker-plugin; output in build-teensy-lto/ or build-teensyduino-lto/. Not in CI; what LTO
# is worth is in docs/benchmarks-target.md.
set -euo pipefail
cd "$(dirname "$0")/.."

case ${STEPDANCE_TEENSY_LTO:-0} in
  0) lto_suffix="" lto_compile=() lto_link=() ;;
  1) lto_suffix=-lto lto_compile=(-flto -fno-fat-lto-objects) lto_link=(-flto -fno-fat-lto-objects -fuse-linker-plugin) ;;
  *) echo "build-teensy: FAILED: STEPDANCE_TEENSY_LTO must be 0 or 1" >&2; exit 1 ;;
esac
out=${STEPDANCE_TEENSY_BUILD_DIR:-build-teensy$lto_suffix}
stand_in=targets/teensy/stand-in
ld_dir=targets/teensy/ld
teensyduino=${STEPDANCE_TEENSYDUINO:-}
core_dir=
library_dirs=()
third_party_includes=(-isystem "$stand_in")
if [ -n "$teensyduino" ]; then
  core_dir=$teensyduino/cores/teensy4
  [ -f "$core_dir/imxrt.h" ] || { echo "build-teensy: FAILED: $core_dir/imxrt.h not found" >&2; exit 1; }
  out=${STEPDANCE_TEENSY_BUILD_DIR:-build-teensyduino$lto_suffix}
  third_party_includes=(-isystem "$core_dir")
  for lib in SD SdFat SPI Wire; do
    lib_dir=$teensyduino/libraries/$lib
    [ -d "$lib_dir" ] || { echo "build-teensy: FAILED: $lib_dir not found" >&2; exit 1; }
    [ -d "$lib_dir/src" ] && lib_dir=$lib_dir/src
    library_dirs+=("$lib_dir")
    third_party_includes+=(-isystem "$lib_dir")
  done
fi

fail() {
  echo "build-teensy: FAILED: $*" >&2
  exit 1
}

for tool in c++ arm-none-eabi-g++ arm-none-eabi-gcc arm-none-eabi-size arm-none-eabi-objcopy arm-none-eabi-objdump \
  arm-none-eabi-nm arm-none-eabi-gcc-nm arm-none-eabi-gcc-ar c++filt cmake; do
  command -v "$tool" >/dev/null || fail "$tool is missing (run scripts/setup.sh)"
done

mcu=(-mcpu=cortex-m7 -mfpu=fpv5-d16 -mfloat-abi=hard -mthumb)
# What Teensyduino passes for a Teensy 4.x at 600 MHz, "Faster" optimisation, plus our warnings.
common=("${mcu[@]}" -O2 "${lto_compile[@]}" -g -ffunction-sections -fdata-sections -Wall -Wextra -Werror -Wundef -Wshadow
  -D__IMXRT1062__ -DF_CPU=600000000 -DARDUINO=10819 -DTEENSYDUINO=159 -DLAYOUT_US_ENGLISH -Isrc
  "${third_party_includes[@]}")
cxx_flags=(-std=gnu++17 -fno-exceptions -fno-rtti)
c_flags=(-std=gnu11)
# Dependency files name every header, system ones included (-MD, not -MMD): the third-party headers
# come in through -isystem, and the .d files are how a changed header recompiles its users and how
# the link finds the libraries an image includes (libraries_linked).
dep_flags=(-MD -MP)

# Heap, exception and personality symbols: none may be referenced or linked.
forbidden='^(malloc|free|calloc|realloc|_malloc_r|_free_r|_calloc_r|_realloc_r|_sbrk|_sbrk_r|__cxa_allocate_exception|__cxa_throw|__gxx_personality_v0|_Znw[a-zA-Z0-9_]*|_Zna[a-zA-Z0-9_]*|_Zdl[a-zA-Z0-9_]*|_Zda[a-zA-Z0-9_]*)$'

# ---- Incremental compilation ------------------------------------------------------------------

# True if $1 exists and is newer than every file its dependency list names.
up_to_date() {
  local object=$1 deps=${1%.o}.d file
  [[ -f $object && -f $deps ]] || return 1
  for file in $(sed -e '/^[^ ].*:$/d' -e 's/^[^ ]*://' -e 's/\\$//' "$deps"); do
    [[ -e $file && ! $file -nt $object ]] || return 1
  done
}

compiled=0
# compile SOURCE OBJECT EXTRA_FLAGS...: C or C++ by extension (sketches arrive prepared, as .ino.cpp).
compile() {
  local source=$1 object=$2
  shift 2
  up_to_date "$object" && return 0
  mkdir -p "$(dirname "$object")"
  case $source in
    *.c) arm-none-eabi-gcc "${common[@]}" "${c_flags[@]}" "$@" "${dep_flags[@]}" -c "$source" -o "$object" ;;
    *) arm-none-eabi-g++ "${common[@]}" "${cxx_flags[@]}" "$@" "${dep_flags[@]}" -c "$source" -o "$object" ;;
  esac || fail "compiling $source ($*)"
  compiled=$((compiled + 1))
}

# third_party_compile SOURCE OBJECT EXTRA_FLAGS...: Teensyduino's core or library source, with the
# flags of Teensyduino's platform.txt and warnings off (they are not ours to fix).
third_party_compile() {
  local source=$1 object=$2
  shift 2
  up_to_date "$object" && return 0
  mkdir -p "$(dirname "$object")"
  local flags=("${mcu[@]}" -O2 "${lto_compile[@]}" -g -ffunction-sections -fdata-sections -w -D__IMXRT1062__ -DF_CPU=600000000
    -DARDUINO=10819 -DTEENSYDUINO=159 -DLAYOUT_US_ENGLISH "${third_party_includes[@]}" "$@" "${dep_flags[@]}")
  case $source in
    *.c) arm-none-eabi-gcc "${flags[@]}" "${c_flags[@]}" -c "$source" -o "$object" ;;
    *.S) arm-none-eabi-gcc "${flags[@]}" -x assembler-with-cpp -c "$source" -o "$object" ;;
    *) arm-none-eabi-g++ "${flags[@]}" -std=gnu++17 -fno-exceptions -fpermissive -fno-rtti -fno-threadsafe-statics \
      -felide-constructors -c "$source" -o "$object" ;;
  esac || fail "compiling $source ($*)"
  compiled=$((compiled + 1))
}

# ---- The IDE's sketch preparation, as a host tool -------------------------------------------------

prep="$out/tools/stepdance-sketch-prep"
prep_sources=(tools/sketch/sketch_prep_main.cpp sim/board/loader/sketch_prototypes.cpp
  sim/board/loader/sketch_sources.cpp)
prep_stale=0
[ -x "$prep" ] || prep_stale=1
for source in "${prep_sources[@]}" sim/board/loader/*.hpp; do [ "$source" -nt "$prep" ] && prep_stale=1; done
if [ $prep_stale -eq 1 ]; then
  mkdir -p "$out/tools"
  c++ -std=gnu++17 -O1 -Isim "${prep_sources[@]}" -o "$prep" || fail "building the sketch preparation tool"
fi

# prepare_sketch FOLDER OUTPUT.cpp: writes the IDE's translation unit (rewritten only when it
# changes, so unchanged sketches are not recompiled) and prints the folder's other C/C++ sources,
# relative to the repository.
prepare_sketch() {
  local folder=$1 output=$2 sources
  mkdir -p "$(dirname "$output")"
  sources=$("$prep" "$folder" "$output.new") || fail "preparing $folder"
  if cmp -s "$output.new" "$output"; then rm "$output.new"; else mv "$output.new" "$output"; fi
  [ -z "$sources" ] || realpath --relative-to=. $sources
}

# ---- What to build ----------------------------------------------------------------------------

mapfile -t library_sources < <(find src -type f \( -name '*.cpp' -o -name '*.c' \) | LC_ALL=C sort)
declare -A stand_in_libraries=()
if [ -z "$teensyduino" ]; then
  mapfile -t stand_in_sources < <(find "$stand_in" -type f -name '*.cpp' | LC_ALL=C sort)
  third_party_sources=()
  stand_in_libraries=([SD.cpp]=SD [SdFat.cpp]=SdFat)  # models of libraries/SD and libraries/SdFat
else
  stand_in_sources=()
  mapfile -t third_party_sources < <( (find "$core_dir" -maxdepth 1 -type f \( -name '*.c' -o -name '*.cpp' -o -name '*.S' \)
    find "${library_dirs[@]}" -type f \( -name '*.c' -o -name '*.cpp' \) -not -path '*/examples/*') | LC_ALL=C sort)
fi
mapfile -t example_dirs < <(find examples -mindepth 1 -maxdepth 1 -type d | LC_ALL=C sort)
[ ${#example_dirs[@]} -gt 0 ] || fail "no example folders under examples/"

# The Arduino IDE lists a sketch under File > Examples only as examples/<Name>/<Name>.ino.
for dir in "${example_dirs[@]}"; do
  name=$(basename "$dir")
  [ -f "$dir/$name.ino" ] || fail "$dir has no $name.ino: the IDE needs examples/<Name>/<Name>.ino"
done

# board id -> Teensyduino board macro and linker script
declare -A board_macro=([teensy41]=ARDUINO_TEENSY41 [teensy40]=ARDUINO_TEENSY40)
declare -A board_script=([teensy41]=imxrt1062_t41.ld [teensy40]=imxrt1062_t40.ld)
declare -A core_script=([teensy41]=imxrt1062_t41.ld [teensy40]=imxrt1062.ld)

# Every example builds for the Teensy 4.1; Basic Module sketches also for the Teensy 4.0.
# Sketches that print to SerialUSB1 need Tools > USB Type > Dual Serial, as in the IDE.
declare -a builds=()
for dir in "${example_dirs[@]}"; do
  name=$(basename "$dir")
  usb=serial
  grep -q 'SerialUSB1' "$dir"/*.ino && usb=dualserial
  builds+=("$name teensy41 $usb")
  if grep -Eq '^[[:space:]]*#[[:space:]]*define[[:space:]]+module_basic\b' "$dir/$name.ino"; then
    builds+=("$name teensy40 $usb")
  fi
done

# ---- Build each configuration (board + USB type) once, then its examples ------------------------

declare -A usb_macro=([serial]=USB_SERIAL [dualserial]=USB_DUAL_SERIAL)
declare -A config_objects=()      # board-usb -> our library objects
declare -A config_core=()         # board-usb -> the core archive
declare -A config_libraries=()    # board-usb -> names of the Teensyduino libraries compiled
declare -A library_objects_of=()  # board-usb:library -> that library's objects
declare -a images=()
declare -a all_objects=()
declare -a unlinked_hal=()

build_configuration() {
  local board=$1 usb=$2 dir="$out/$1-$2" source object
  local flags=("-D${board_macro[$board]}" "-D${usb_macro[$usb]}")
  # Start afresh when the flags or the compiler change.
  local stamp
  stamp="$(printf '%s ' "${common[@]}" "${cxx_flags[@]}" "${flags[@]}" "${dep_flags[@]}"; arm-none-eabi-g++ --version | head -1)"
  if [ "$(cat "$dir/flags" 2>/dev/null)" != "$stamp" ]; then
    rm -rf "$dir"
    mkdir -p "$dir"
    printf '%s' "$stamp" >"$dir/flags"
  fi
  local objects=() core_objects=() library library_names=()
  for source in "${library_sources[@]}"; do
    object="$dir/obj/${source%.*}.o"
    compile "$source" "$object" "${flags[@]}"
    objects+=("$object")
  done
  all_objects+=("${objects[@]}")  # ours: checked for heap symbols below
  config_objects[$board-$usb]="${objects[*]}"
  for source in "${stand_in_sources[@]}"; do
    object="$dir/obj/${source%.*}.o"
    compile "$source" "$object" "${flags[@]}"
    library=${stand_in_libraries[$(basename "$source")]:-}
    if [ -n "$library" ]; then add_library_object "$board-$usb" "$library" "$object"; else core_objects+=("$object"); fi
  done
  for source in "${third_party_sources[@]}"; do
    object="$dir/third-party/${source#"$teensyduino"/}.o"
    third_party_compile "$source" "$object" "${flags[@]}"
    case ${source#"$teensyduino"/} in
      libraries/*) library=${source#"$teensyduino"/libraries/}; add_library_object "$board-$usb" "${library%%/*}" "$object" ;;
      *) core_objects+=("$object") ;;
    esac
  done
  archive_core "$dir/core.a" "${core_objects[@]}"
  config_core[$board-$usb]=$dir/core.a
}

# add_library_object CONFIGURATION LIBRARY OBJECT: records one object of a Teensyduino library.
add_library_object() {
  local key=$1:$2
  [ -n "${library_objects_of[$key]+set}" ] || config_libraries[$1]+=" $2"
  library_objects_of[$key]+=" $3"
}

# archive_core ARCHIVE OBJECTS...: the core as Arduino links it (recipe.ar.pattern), rebuilt when
# an object is newer.
archive_core() {
  local archive=$1 object
  shift
  if [ -f "$archive" ]; then
    for object in "$@"; do [ "$object" -nt "$archive" ] && rm -f "$archive" && break; done
  fi
  [ -f "$archive" ] || arm-none-eabi-gcc-ar rcs "$archive" "$@" || fail "archiving the core into $archive"
}

# libraries_named: reads dependency (.d) text and prints the Teensyduino libraries whose headers it
# names: libraries/<name>/... of the real tree, or the stand-in's models (SD.h, SdFat.h).
libraries_named() {
  tr ' \\' '\n\n' | if [ -n "$teensyduino" ]; then
    grep -F "$teensyduino/libraries/" | sed 's|.*/libraries/||; s|/.*||'
  else
    sed -n "s#^$stand_in/\\(SD\\|SdFat\\)\\.h\$#\\1#p"
  fi | LC_ALL=C sort -u
}

# libraries_linked CONFIGURATION OBJECTS...: the Teensyduino libraries an image links, as the IDE
# discovers them: those whose headers these objects include (their .d files), then those the
# libraries' own sources include, until nothing new turns up.
libraries_linked() {
  local key=$1 library object found
  shift
  local pending=("$@") linked=" "
  while [ ${#pending[@]} -gt 0 ]; do
    found=$(for object in "${pending[@]}"; do cat "${object%.o}.d" 2>/dev/null; done | libraries_named)
    pending=()
    for library in $found; do
      [[ $linked == *" $library "* ]] && continue
      [ -n "${library_objects_of[$key:$library]+set}" ] || fail "a source includes library $library, which was not compiled"
      linked+="$library "
      read -r -a objects_of_library <<<"${library_objects_of[$key:$library]}"
      pending+=("${objects_of_library[@]}")
    done
  done
  echo $linked
}

# image_inputs CONFIGURATION OBJECTS...: prints the link inputs of an image made of OBJECTS (the
# sketch's and ours): those, the objects of the libraries it links, and the core archive last.
image_inputs() {
  local key=$1 library
  shift
  printf '%s\n' "$@"
  for library in $(libraries_linked "$key" "$@"); do
    printf '%s\n' ${library_objects_of[$key:$library]}
  done
  echo "${config_core[$key]}"
}

backend_present() {
  # The Teensy backend defines the stepdance::hal functions; until it lands they stay undefined.
  local objects=("$@")
  arm-none-eabi-gcc-nm --defined-only "${objects[@]}" | grep ' T _ZN9stepdance3hal' >/dev/null
}

# link_elf ELF BOARD FLAGS_AND_OBJECTS...: links an image as Teensyduino does (unused sections
# dropped), with a map file beside it.
link_elf() {
  local elf=$1 board=$2
  shift 2
  if [ -n "$teensyduino" ]; then  # Teensyduino's own link line (platform.txt)
    arm-none-eabi-gcc "${mcu[@]}" -O2 "${lto_link[@]}" -Wl,--gc-sections,--relax -Wl,--no-warn-rwx-segments \
      "-T$core_dir/${core_script[$board]}" "-Wl,-Map=${elf%.elf}.map" -o "$elf" "$@" -lm -lstdc++
  else
    arm-none-eabi-g++ "${mcu[@]}" -O2 "${lto_link[@]}" -nostartfiles --specs=nano.specs -Wl,--gc-sections \
      -Wl,--no-warn-rwx-segments "-L$ld_dir" "-T${board_script[$board]}" "-Wl,-Map=${elf%.elf}.map" \
      -o "$elf" "$@" -lm
  fi
}

# link_example NAME BOARD USB [FOLDER [ELF]]: the sketch in FOLDER (examples/NAME) linked into ELF
# ($out/BOARD-USB/NAME.elf); only examples join the image list the checks below go through.
link_example() {
  local name=$1 board=$2 usb=$3 dir="$out/$2-$3" folder=${4:-examples/$1}
  local flags=("-D${board_macro[$board]}" "-D${usb_macro[$usb]}")
  local sketch_object="$dir/$folder/$name.ino.o" extra_sources=() source
  mapfile -t extra_sources < <(prepare_sketch "$folder" "$dir/$folder/$name.ino.cpp")
  compile "$dir/$folder/$name.ino.cpp" "$sketch_object" "${flags[@]}" -iquote "$folder"
  local objects=("$sketch_object")
  for source in "${extra_sources[@]}"; do
    compile "$source" "$dir/${source%.*}.o" "${flags[@]}"
    objects+=("$dir/${source%.*}.o")
  done
  local library_objects
  read -r -a library_objects <<<"${config_objects[$board-$usb]}"
  local link_flags=()
  if ! backend_present "${library_objects[@]}"; then
    link_flags=(-Wl,--unresolved-symbols=ignore-all)
  fi
  local elf=${5:-$dir/$name.elf} inputs
  mapfile -t inputs < <(image_inputs "$board-$usb" "${objects[@]}" "${library_objects[@]}")
  link_elf "$elf" "$board" "${link_flags[@]}" "${inputs[@]}" || fail "linking $name for $board"
  if [ ${#link_flags[@]} -gt 0 ]; then
    local missing
    missing=$(arm-none-eabi-nm -u "$elf" | awk '{print $2}' | grep -v '^_ZN9stepdance3hal' || true)
    [ -z "$missing" ] || fail "$name ($board) leaves symbols undefined: $missing"
    unlinked_hal+=("$name/$board")
  fi
  [ -n "${4:-}" ] && return 0
  images+=("$elf")
  all_objects+=("${objects[@]}")
}

for build in "${builds[@]}"; do
  read -r name board usb <<<"$build"
  [ -n "${config_objects[$board-$usb]+set}" ] || build_configuration "$board" "$usb"
  link_example "$name" "$board" "$usb"
done
# The image boards' fault fixtures (tests/sim/image/fault_sketches): one sketch per fault kind the
# simulator must report, for the Teensy 4.1, in $out/teensy41-serial/faults/.
for dir in tests/sim/image/fault_sketches/*/; do
  name=$(basename "$dir")
  [ -f "$dir/$name.ino" ] || continue
  mkdir -p "$out/teensy41-serial/faults"
  link_example "$name" teensy41 serial "${dir%/}" "$out/teensy41-serial/faults/$name.elf"
done
# The library builds for both boards even when no example needs the Teensy 4.0.
[ -n "${config_objects[teensy40-serial]+set}" ] || build_configuration teensy40 serial

# ---- Compile-only sketch fixtures (tests/sim/assembly/fixtures): the IDE-style folder and the ----
# original library's names. A fixture marked "// waits-for: NAME..." may fail only because those
# names do not exist yet (the host test, original_api_fixtures_test.cpp, applies the same rule).
waiting_only() {
  local log=$1 line name explained any=1
  shift
  while IFS= read -r line; do
    explained=1
    [[ $line == *"was not declared in this scope"* ]] && explained=0
    for name in "$@"; do
      if [[ $name == *::* ]]; then  # quoted ‘x’ in a UTF-8 locale, 'x' in the C locale
        [[ $line == *"has no member named "[\'‘]"${name#*::}"[\'’]* ]] && explained=0 && any=0
      else
        [[ $line == *[\'‘]"$name"[\'’]" does not name a type"* ]] && explained=0 && any=0
      fi
    done
    [ $explained -eq 0 ] || return 1
  done < <(grep ' error: ' "$log")
  return $any
}

fixtures_built=0
declare -a fixtures_waiting=()
mapfile -t fixture_dirs < <(find tests/sim/assembly/fixtures/IdeSketch tests/sim/assembly/fixtures/original_api -name '*.ino' -printf '%h\n' | LC_ALL=C sort -u)
for folder in "${fixture_dirs[@]}"; do
  name=$(basename "$folder")
  [ -f "$folder/$name.ino" ] || continue
  object_dir="$out/teensy41-serial/fixtures/$name"
  mapfile -t extra_sources < <(prepare_sketch "$folder" "$object_dir/$name.ino.cpp")
  read -r -a waited <<<"$(sed -n '1s|^// waits-for:||p' "$folder/$name.ino")"
  log="$object_dir/compile.log"
  if ! (for source in "$object_dir/$name.ino.cpp" "${extra_sources[@]}"; do
      object="$object_dir/$(basename "${source%.*}").o"
      up_to_date "$object" && continue
      case $source in
        *.c) arm-none-eabi-gcc "${common[@]}" "${c_flags[@]}" -DARDUINO_TEENSY41 -DUSB_SERIAL -MMD -MP -c "$source" -o "$object" ;;
        *) arm-none-eabi-g++ "${common[@]}" "${cxx_flags[@]}" -DARDUINO_TEENSY41 -DUSB_SERIAL -iquote "$folder" -MMD -MP \
          -c "$source" -o "$object" ;;
      esac || exit 1
    done) >"$log" 2>&1; then
    if [ ${#waited[@]} -gt 0 ] && waiting_only "$log" "${waited[@]}"; then
      fixtures_waiting+=("$name")
      continue
    fi
    cat "$log" >&2
    fail "sketch fixture $folder does not compile for the Teensy 4.1"
  fi
  fixtures_built=$((fixtures_built + 1))
done
echo "build-teensy: ${#library_sources[@]} library sources; ${#builds[@]} example images linked;" \
  "$fixtures_built sketch fixtures compiled${fixtures_waiting[*]:+ (waiting for blocks: ${fixtures_waiting[*]})}" \
  "($compiled files compiled this run):"
arm-none-eabi-size "${images[@]}" | sed 's/^/  /'
if [ ${#unlinked_hal[@]} -gt 0 ]; then
  echo "build-teensy: NOTE: no Teensy backend in src/stepdance/platform/teensy yet: ${unlinked_hal[*]}" \
    "link with the stepdance::hal functions left undefined (every other symbol must resolve)"
fi

# ---- Forbidden symbols: in any object's references and in any image ---------------------------

# heap_symbols ELF: the heap and exception symbols in an image, one per line. SdFat's placement
# operator new (_ZnwjPm, FsNew.h: it builds the FAT or exFAT object in a buffer the caller owns)
# allocates nothing and is not one of them.
heap_symbols() {
  arm-none-eabi-nm "$1" | awk '{print $NF}' | grep -E "$forbidden" | grep -vx '_ZnwjPm' || true
}

status=0
for object in "${all_objects[@]}"; do
  hits=$(arm-none-eabi-gcc-nm -u "$object" | awk '{print $2}' | grep -E "$forbidden" || true)  # reads LTO objects too
  if [ -n "$hits" ]; then
    echo "build-teensy: FORBIDDEN: $object references" $hits >&2
    status=1
  fi
done
echo "build-teensy: heap/exception symbols per image (malloc, free, _sbrk, operator new/delete, __cxa_throw, ...):"
for elf in "${images[@]}"; do
  hits=$(heap_symbols "$elf")
  count=$(printf '%s' "$hits" | grep -c . || true)
  printf '  %-24s %s  %d%s\n' "$(basename "${elf%.elf}")" "$(basename "$(dirname "$elf")")" "$count" \
    "$([ "$count" -eq 0 ] || echo ": $(echo $hits)")"
  [ "$count" -eq 0 ] || status=1
done
[ $status -eq 0 ] || fail "heap or exception symbols found (see above)"
echo "build-teensy: no malloc/free, operator new/delete or exception symbols in any object or image"

# The check must fail where the heap comes in: a sketch that writes a file through Teensyduino's SD
# library (it allocates every File), and one that mounts the card through SdFat's SdFs (its card
# objects' deleting destructors name the core's operator delete).
probe_dir="$out/teensy41-serial/heap-probe"
read -r -a probe_library <<<"${config_objects[teensy41-serial]}"
probes=(sd_library_probe sdfs_probe)
if [ ${#lto_compile[@]} -gt 0 ]; then
  # With LTO the stand-in's _sbrk is optimised away before newlib's _sbrk_r, linked after it, asks
  # for it, so a probe that allocates does not link at all. The images are checked all the same.
  echo "build-teensy: heap probes not linked with LTO (an allocating sketch does not link against the stand-in)"
  probes=()
fi
for probe in "${probes[@]}"; do
  compile "targets/teensy/heap-probe/$probe.cpp" "$probe_dir/$probe.o" -DARDUINO_TEENSY41 -DUSB_SERIAL
  mapfile -t probe_inputs < <(image_inputs teensy41-serial "$probe_dir/$probe.o" "${probe_library[@]}")
  link_elf "$probe_dir/$probe.elf" teensy41 "${probe_inputs[@]}" || fail "linking the heap probe $probe"
  hits=$(heap_symbols "$probe_dir/$probe.elf")
  [ -n "$hits" ] || fail "the no-heap check does not see the heap in targets/teensy/heap-probe/$probe.cpp"
  echo "build-teensy: the no-heap check catches the heap probe $probe:" $hits
done

# Storage links only into sketches that record or play back (the backend's card type marks it; its
# vtable and destructors keep their names with link-time optimisation too).
sd_linked() { arm-none-eabi-nm "$1" | grep '13SdCardBuiltin' >/dev/null; }
! sd_linked "$out/teensy41-serial/StepASketch.elf" || fail "StepASketch links SD card storage it never uses"
sd_linked "$out/teensy41-serial/AxiDrawRecorder.elf" || fail "AxiDrawRecorder does not link SD card storage"
echo "build-teensy: SD card storage links only into sketches that use it (AxiDrawRecorder yes, StepASketch no)"

# ---- The Step-A-Sketch firmware: hex and size report -----------------------------------------

section_size() { awk -v s="$2" '$1 == s {print $2; found=1} END {if (!found) print 0}' <<<"$1"; }

# ---- Against the real core: sizes as Teensyduino's teensy_size prints them ---------------------

# teensy_size ELF BOARD: the three lines the IDE shows after a build (same sections, same sums).
teensy_size() {
  local elf=$1 board=$2 sections
  sections=$(arm-none-eabi-size -A -d "$elf")
  local headers code progmem itcm exidx data bss dma csf
  headers=$(section_size "$sections" .text.headers) code=$(section_size "$sections" .text.code)
  progmem=$(section_size "$sections" .text.progmem) itcm=$(section_size "$sections" .text.itcm)
  exidx=$(section_size "$sections" .ARM.exidx) data=$(section_size "$sections" .data)
  bss=$(section_size "$sections" .bss) dma=$(section_size "$sections" .bss.dma) csf=$(section_size "$sections" .text.csf)
  local flash_size=8126464 model="Teensy 4.1"
  [ "$board" = teensy40 ] && flash_size=2031616 model="Teensy 4.0"
  local ram1_code=$((itcm + exidx))
  local ram1_total=$(((ram1_code + 32767) / 32768 * 32768))
  echo "Memory Usage on $model:"
  echo "  FLASH: code:$((code + itcm + exidx)), data:$((progmem + data)), headers:$((headers + csf))" \
    "  free for files:$((flash_size - headers - code - progmem - itcm - exidx - data - csf))"
  echo "   RAM1: variables:$((data + bss)), code:$ram1_code, padding:$((ram1_total - ram1_code))" \
    "  free for local variables:$((524288 - ram1_total - data - bss))"
  echo "   RAM2: variables:$dma  free for malloc/new:$((524288 - dma))"
}

if [ -n "$teensyduino" ]; then
  for build in "${builds[@]}"; do
    read -r name board usb <<<"$build"
    echo
    echo "$name ($board, $usb) against $core_dir:"
    teensy_size "$out/$board-$usb/$name.elf" "$board" | sed 's/^/  /'
  done
  echo "build-teensy: OK against the real Teensyduino core ($teensyduino)"
  exit 0
fi

# ---- The stand-in's boot layout: what the boot ROM and the start-up rely on, in every image -----
# Expected values from the reference manual (IMXRT1060RM rev 3): the FlexSPI NOR configuration
# block's tag "FCFB" and version at 0x60000000 (Table 9-15), the IVT header (tag 0xD1, length 32,
# version 0x41) at 0x60001000 (§9.7.1.1) pointing at the entry, the boot data and itself, the boot
# data's start and length (§9.7.1.2); the FlexRAM bank roles of IOMUXC_GPR17 (§11.4: 11 ITCM for
# the banks the code needs, 10 DTCM for the rest), the stack top at the end of those DTCM banks,
# the 32-byte stack guard above .bss, and the vector table alignment VTOR needs (ARMv7-M §B3.2.5).

# word_at BIN OFFSET: the little-endian 32-bit word at OFFSET of a flash image, as 0x%08x.
word_at() { printf '0x%08x' "0x$(od -An -tx4 -j "$2" -N 4 "$1" | tr -d ' ')"; }
# symbol_of ELF NAME: a symbol's value as 0x%08x.
symbol_of() { printf '0x%08x' "0x$(arm-none-eabi-nm "$1" | awk -v s="$2" '$3 == s {print $1; exit}')"; }
hex() { printf '0x%08x' "$1"; }

check_boot_layout() {
  local elf=$1 board=$2 bin=${1%.elf}.bin problems=()
  arm-none-eabi-objcopy -O binary -R .bss -R .bss.dma "$elf" "$bin"
  local flash_bytes=$((8 * 1024 * 1024))
  [ "$board" = teensy40 ] && flash_bytes=$((2 * 1024 * 1024))
  expect() { [ "$2" = "$3" ] || problems+=("$1 is $2, expected $3"); }
  expect "FlexSPI tag" "$(word_at "$bin" 0)" 0x42464346
  expect "FlexSPI version" "$(word_at "$bin" 4)" 0x56010000
  expect "FlexSPI sflashA1Size" "$(word_at "$bin" 0x50)" "$(hex $flash_bytes)"
  # Read sequence (LUT instructions: opcode 15:10, pads 9:8, operand 7:0): CMD_SDR 1 pad 0xEB,
  # RADDR_SDR 4 pads 24 bits; DUMMY_SDR 4 pads 6 cycles, READ_SDR 4 pads. Then pageSize, sectorSize.
  expect "FlexSPI LUT read word 0" "$(word_at "$bin" 0x80)" 0x0a1804eb
  expect "FlexSPI LUT read word 1" "$(word_at "$bin" 0x84)" 0x26043206
  expect "serial NOR pageSize" "$(word_at "$bin" 0x1c0)" 0x00000100
  expect "serial NOR sectorSize" "$(word_at "$bin" 0x1c4)" 0x00001000
  expect "IVT header" "$(word_at "$bin" 0x1000)" 0x412000d1
  expect "IVT entry" "$(word_at "$bin" 0x1004)" "$(hex $(($(symbol_of "$elf" stand_in_reset_handler) | 1)))"
  expect "IVT boot data" "$(word_at "$bin" 0x1010)" "$(symbol_of "$elf" stand_in_boot_data)"
  expect "IVT self" "$(word_at "$bin" 0x1014)" 0x60001000
  local boot_data=$(($(symbol_of "$elf" stand_in_boot_data) - 0x60000000))
  expect "boot data start" "$(word_at "$bin" $boot_data)" 0x60000000
  expect "boot data length" "$(word_at "$bin" $((boot_data + 4)))" "$(hex "$(stat -c %s "$bin")")"
  local itcm banks
  itcm=$(section_size "$(arm-none-eabi-size -A -d "$elf")" .text.itcm)
  banks=$(((itcm + 32767) / 32768))
  expect "_flexram_bank_config" "$(symbol_of "$elf" _flexram_bank_config)" "$(hex $((0xAAAAAAAA | ((1 << (2 * banks)) - 1))))"
  expect "_stack_top" "$(symbol_of "$elf" _stack_top)" "$(hex $((0x20000000 + (16 - banks) * 32768)))"
  local guard bss_end
  guard=$(($(symbol_of "$elf" _stack_guard))) bss_end=$(($(symbol_of "$elf" _bss_end)))
  [ $((guard % 32)) -eq 0 ] && [ "$guard" -ge "$bss_end" ] && [ $((guard - bss_end)) -lt 32 ] ||
    problems+=("_stack_guard $(hex $guard) is not the first 32-byte boundary at or after _bss_end $(hex $bss_end)")
  [ $((guard + 32)) -le $(($(symbol_of "$elf" _stack_top))) ] || problems+=("no room for the stack guard")
  [ $(($(symbol_of "$elf" stand_in_vectors_ram) % 1024)) -eq 0 ] || problems+=("the RAM vector table is not 1 KB aligned")
  rm -f "$bin"
  [ ${#problems[@]} -eq 0 ] || fail "$(basename "$elf") ($board): boot layout: ${problems[*]}"
}

for build in "${builds[@]}"; do
  read -r name board usb <<<"$build"
  check_boot_layout "$out/$board-$usb/$name.elf" "$board"
done
echo "build-teensy: boot layout (FlexSPI block, IVT, boot data, FlexRAM banks, stack guard) valid in all ${#builds[@]} images"

# ---- The Step-A-Sketch firmware: hex and size report -----------------------------------------

report_size() {
  local elf=$1 flash_total=$2 sections
  sections=$(arm-none-eabi-size -A -d "$elf")
  local headers flash_code itcm data bss dma
  headers=$(section_size "$sections" .headers)
  itcm=$(section_size "$sections" .text.itcm)
  flash_code=$(($(section_size "$sections" .text.flash) + $(section_size "$sections" .init_array) +
    $(section_size "$sections" .ARM.exidx) + itcm))
  data=$(section_size "$sections" .data)
  bss=$(section_size "$sections" .bss)
  dma=$(section_size "$sections" .bss.dma)
  local banks=$(((itcm + 32767) / 32768))
  local flash_used=$((headers + flash_code + data))
  local ram1_used=$((banks * 32768 + data + bss))
  printf '| Memory | Use | Bytes |\n|---|---|---:|\n'
  printf '| Flash | code (ITCM image + flash-resident start-up) | %d |\n' "$flash_code"
  printf '| Flash | initial values of DTCM data and constants | %d |\n' "$data"
  printf '| Flash | boot headers | %d |\n' "$headers"
  printf '| Flash | **total**, of %d KB | **%d** (%d.%d%%) |\n' $((flash_total / 1024)) "$flash_used" \
    $((flash_used * 100 / flash_total)) $((flash_used * 1000 / flash_total % 10))
  printf '| RAM1 (FlexRAM) | code in ITCM (%d x 32 KB bank, %d bytes padding) | %d |\n' "$banks" \
    $((banks * 32768 - itcm)) "$itcm"
  printf '| RAM1 (FlexRAM) | variables and constants in DTCM (.data %d + .bss %d) | %d |\n' "$data" "$bss" \
    $((data + bss))
  printf '| RAM1 (FlexRAM) | **used**, of 512 KB; the rest is stack | **%d** (%d.%d%%) |\n' "$ram1_used" \
    $((ram1_used * 100 / 524288)) $((ram1_used * 1000 / 524288 % 10))
  printf '| RAM2 (OCRAM) | DMA buffers; the rest is free | %d |\n' "$dma"
}

step_a_sketch="$out/teensy41-serial/StepASketch.elf"
if [ -f "$step_a_sketch" ]; then
  arm-none-eabi-objcopy -O ihex -R .bss -R .bss.dma "$step_a_sketch" "${step_a_sketch%.elf}.hex"
  echo
  echo "Step-A-Sketch for Teensy 4.1 (${step_a_sketch%.elf}.hex; stand-in core, untested on a board):"
  arm-none-eabi-size "$step_a_sketch"
  report_size "$step_a_sketch" $((7936 * 1024))
  echo
else
  fail "examples/StepASketch did not produce $step_a_sketch"
fi

# ---- Packaging: library manifests and the Arduino zip ---------------------------------------

scripts/package-arduino-zip.sh "$out/Stepdance.zip" >/dev/null
cmake -DZIP="$out/Stepdance.zip" -DOUT="$out" -P targets/teensy/check_package.cmake ||
  fail "library package check"
echo "build-teensy: OK"
