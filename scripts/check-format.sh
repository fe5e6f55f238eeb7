#!/usr/bin/env bash
# Checks that every C/C++ file of ours is as clang-format (Debian 12: clang-format 14) would write
# it with the repository's .clang-format, and fails with the list of files that differ.
#
# Usage: scripts/check-format.sh [--lines] [--style FILE] [--list-files] [--root DIR] | --self-test
#   --lines        also prints, per differing file, the lines the formatter would remove and add,
#                  and the totals (how docs/architecture.md measured the candidate styles)
#   --style FILE   checks against FILE's style instead of .clang-format (a candidate style)
#   --list-files   prints the files checked, one a line, and checks nothing (scripts/format.sh)
#   --root DIR     checks the git tree at DIR instead of this repository (the self-test's)
#   --self-test    checks the check on a small tree written by hand (scripts/check-format-self-test.sh)
#
# The files: the .c, .h, .cpp, .hpp and .ino files git knows or would add (so ignored folders
# such as build*/ and tests/clients/node_modules/ are out), but for test inputs kept as written:
# the sketches and sources under a fixtures/ or fault_sketches/ folder and tests/cli/live/ (tests
# quote their line numbers, e.g. NullWrite.ino:11, and some are broken on purpose).
# The example sketches (examples/*.ino) are in: they are ours, and the first code a user reads.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)

lines=0
list_only=0
style_file=$repo/.clang-format
root=$repo
while [ $# -gt 0 ]; do
  case $1 in
    --lines) lines=1 ;;
    --list-files) list_only=1 ;;
    --style) style_file=$(realpath "${2:?check-format: --style needs a file}"); shift ;;
    --root) root=$(realpath "${2:?check-format: --root needs a folder}"); shift ;;
    --self-test) exec "$repo/scripts/check-format-self-test.sh" ;;
    *) echo "check-format: unknown option '$1' (--lines, --style FILE, --list-files, --self-test)" >&2; exit 2 ;;
  esac
  shift
done
cd "$root"

list_files() {
  git ls-files --cached --others --exclude-standard -- '*.c' '*.h' '*.cpp' '*.hpp' '*.ino' |
    grep -Ev '(^|/)(fixtures|fault_sketches|node_modules)/|^tests/cli/live/|^build[^/]*/' |
    LC_ALL=C sort -u
}
if [ $list_only -eq 1 ]; then
  list_files
  exit 0
fi

formatter=$(command -v clang-format-14 || command -v clang-format || true)
[ -n "$formatter" ] || { echo "check-format: needs clang-format (scripts/setup.sh)" >&2; exit 2; }
[ -f "$style_file" ] || { echo "check-format: no style file '$style_file'" >&2; exit 2; }

# Formats copies (a/ as the files are, b/ formatted), two batches of files per clang-format run,
# then prints "REMOVED ADDED PATH" for each file that differs.
# .ino files are read as C++: clang-format takes an unknown extension for C++.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
style_path=$style_file
style_name=${style_file#"$repo"/}
list_files | tar -c -T - | tar -x -C "$work" --one-top-level=a
cp -r "$work/a" "$work/b"
(cd "$work/b" && find . -type f -print0 | xargs -0 -P"$(nproc)" -n 50 "$formatter" -i --style="file:$style_path")
differing=$(cd "$work" && { diff -r a b || true; } | awk '
    /^diff -r / { if (file != "") print r + 0, a + 0, file; file = substr($3, 3); r = a = 0; next }
    /^Only in / { print "check-format: " $0 > "/dev/stderr"; exit 2 }
    /^</ { r++ } /^>/ { a++ }
    END { if (file != "") print r + 0, a + 0, file }' | sort -k3)
checked=$(list_files | wc -l)
if [ -z "$differing" ]; then
  echo "check-format: all $checked files formatted ($style_name, $("$formatter" --version))"
  exit 0
fi
count=$(echo "$differing" | wc -l)
if [ $lines -eq 1 ]; then
  echo "removed added file"
  echo "$differing"
  echo "$differing" | awk -v n="$checked" '{ r += $1; a += $2 } END {
    printf "check-format: %d of %d files differ; %d lines removed, %d added\n", NR, n, r, a }'
else
  echo "check-format: $count of $checked files differ from $style_name (fix: scripts/format.sh):"
  echo "$differing" | awk '{ print "  " $3 }'
fi
exit 1
