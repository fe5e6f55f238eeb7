#!/usr/bin/env bash
# Measures candidate clang-format styles against the code as it is: for each, how many of the
# files scripts/check-format.sh checks it would change, and how many lines it would remove and
# add. The candidates that chose .clang-format (docs/architecture.md, "Formatting").
# Usage: scripts/measure-format-styles.sh        (about half a minute per candidate on 2 cores)
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# .clang-format without its ColumnLimit.
rest="AllowShortCaseLabelsOnASingleLine: true|IncludeBlocks: Preserve|DerivePointerAlignment: false|PointerAlignment: Left"
# name, then the options on top of BasedOnStyle: Google, separated by '|'.
candidates=(
  "google-80;"
  "google-100;ColumnLimit: 100"
  "google-110;ColumnLimit: 110"
  "google-120;ColumnLimit: 120"
  "google-130;ColumnLimit: 130"
  "120+case;ColumnLimit: 120|AllowShortCaseLabelsOnASingleLine: true"
  "120+case+preserve;ColumnLimit: 120|AllowShortCaseLabelsOnASingleLine: true|IncludeBlocks: Preserve"
  "120+case+nosort;ColumnLimit: 120|AllowShortCaseLabelsOnASingleLine: true|SortIncludes: Never"
  "chosen;ColumnLimit: 120|$rest"
  "chosen-110;ColumnLimit: 110|$rest"
  "chosen-130;ColumnLimit: 130|$rest"
  "chosen+noreflow;ColumnLimit: 120|$rest|ReflowComments: false"
  "chosen+ifelse;ColumnLimit: 120|$rest|AllowShortIfStatementsOnASingleLine: AllIfsAndElse"
  "chosen+blocks;ColumnLimit: 120|$rest|AllowShortBlocksOnASingleLine: Always"
  "chosen+noalign;ColumnLimit: 120|$rest|AlignTrailingComments: false"
)
for candidate in "${candidates[@]}"; do
  name=${candidate%%;*}
  { echo "BasedOnStyle: Google"; tr '|' '\n' <<<"${candidate#*;}"; } >"$work/$name.yaml"
  printf '%-20s ' "$name"
  scripts/check-format.sh --lines --style "$work/$name.yaml" | tail -1 || true
done
