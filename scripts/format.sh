#!/usr/bin/env bash
# Formats the C/C++ files of ours in place with clang-format (Debian 12: clang-format 14) and the
# repository's .clang-format: all of them (the files scripts/check-format.sh checks), or only the
# files named. Usage: scripts/format.sh [FILE…]
set -euo pipefail
cd "$(dirname "$0")/.."
formatter=$(command -v clang-format-14 || command -v clang-format || true)
[ -n "$formatter" ] || { echo "format: needs clang-format (scripts/setup.sh)" >&2; exit 2; }
if [ $# -gt 0 ]; then
  printf '%s\n' "$@"
else
  scripts/check-format.sh --list-files
fi | tr '\n' '\0' | xargs -0 -r -P"$(nproc)" -n 50 "$formatter" -i --style=file:.clang-format
echo "format: done ($("$formatter" --version))"
