#!/usr/bin/env bash
# Fails if the portable core includes an Arduino, Teensy, POSIX or heavy standard-library header.
set -euo pipefail
cd "$(dirname "$0")/.."
allowed='^(stdint\.h|stddef\.h|stdbool\.h|string\.h|math\.h|cmath|atomic|limits|type_traits|utility|stepdance/.*)$'
status=0
while IFS= read -r -d '' file; do
  while IFS= read -r header; do
    if ! [[ "$header" =~ $allowed ]]; then
      echo "portability: $file includes <$header>, which the portable core must not use"
      status=1
    fi
  done < <(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"]\([^>"]*\)[>"].*/\1/p' "$file")
done < <(find src/stepdance -path src/stepdance/platform -prune -o \( -name '*.hpp' -o -name '*.cpp' \) -print0)
[ $status -eq 0 ] && echo "portability: core includes only allowed headers"
exit $status
