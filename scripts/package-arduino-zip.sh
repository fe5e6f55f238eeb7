#!/usr/bin/env bash
# Packs Stepdance.zip for the Arduino IDE's "Add .ZIP Library": library files only, in Stepdance/.
#
# Usage: scripts/package-arduino-zip.sh [OUTPUT.zip]      (default: build-teensy/Stepdance.zip)
# Contents: library.properties, library.json, LICENSE, README.md, and the files git tracks in src/
# and examples/ (without the simulator's scenario files, and without anything a run wrote there).
# Needs git and cmake.
set -euo pipefail
cd "$(dirname "$0")/.."

zip_path=$(realpath -m "${1:-build-teensy/Stepdance.zip}")
for file in library.properties library.json LICENSE README.md src/stepdance.hpp; do
  [ -f "$file" ] || { echo "package: $file is missing" >&2; exit 1; }
done

stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir "$stage/Stepdance"
cp library.properties library.json LICENSE README.md "$stage/Stepdance/"
count=4
while IFS= read -r -d '' file; do
  mkdir -p "$stage/Stepdance/$(dirname "$file")"
  cp "$file" "$stage/Stepdance/$file"
  count=$((count + 1))
done < <(git ls-files -z src examples | grep -zv -e '\.toml$' -e '/\.' | LC_ALL=C sort -z)

mkdir -p "$(dirname "$zip_path")"
rm -f "$zip_path"
(cd "$stage" && cmake -E tar cf "$zip_path" --format=zip --mtime=2026-01-01 Stepdance)
echo "package: $zip_path ($count files)"
