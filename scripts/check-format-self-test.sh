#!/usr/bin/env bash
# Checks scripts/check-format.sh on a small git tree written here, whose answers were worked out by
# hand: a file in the style passes, a file out of it is listed with the lines it would lose and
# gain, and test inputs (fixtures/) and ignored folders (build/) are not checked at all.
# Usage: scripts/check-format-self-test.sh   (scripts/check-format.sh --self-test runs it)
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
tree=$(mktemp -d)
trap 'rm -rf "$tree"' EXIT
git -C "$tree" init -q
cp "$repo/.clang-format" "$tree/"
mkdir -p "$tree/src" "$tree/tests/fixtures" "$tree/build"
printf 'build/\n' >"$tree/.gitignore"
printf 'int twice(int x) { return 2 * x; }\n' >"$tree/src/good.cpp"
# Out of style on one line: two spaces, a space inside the parentheses, no space before the brace.
printf 'int  twice( int x ){ return 2 * x; }\n' >"$tree/src/bad.ino"
printf 'int  kept( ){ return 0; }\n' >"$tree/tests/fixtures/kept.cpp"
printf 'int  ignored( ){ return 0; }\n' >"$tree/build/ignored.cpp"

fail() { echo "check-format self-test: FAILED: $*" >&2; exit 1; }
status=0
got=$("$repo/scripts/check-format.sh" --root "$tree" --lines) || status=$?
[ $status -eq 1 ] || fail "an out-of-style file gave exit status $status, want 1"
want="removed added file
1 1 src/bad.ino
check-format: 1 of 2 files differ; 1 lines removed, 1 added"
[ "$got" = "$want" ] || fail "got
$got
want
$want"
printf 'int twice(int x) { return 2 * x; }\n' >"$tree/src/bad.ino"
got=$("$repo/scripts/check-format.sh" --root "$tree") || fail "a formatted tree failed: $got"
[[ $got == "check-format: all 2 files formatted"* ]] || fail "got '$got' for a formatted tree"
echo "check-format self-test: passed (an out-of-style .ino listed with 1 line each way, fixtures/ and build/ skipped)"
