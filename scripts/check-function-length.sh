#!/usr/bin/env bash
# Lists every function longer than a limit in the given folders, longest first, and fails if any.
# Usage: scripts/check-function-length.sh [MAX_LINES] [FOLDER…]   (default: 39 src/stepdance/interfaces)
# "Under 40 lines" counts the lines from the signature to the closing brace, both included, as
# universal-ctags reports them (Debian: universal-ctags).
set -euo pipefail
cd "$(dirname "$0")/.."
max=${1:-39}
shift || true
folders=("${@:-src/stepdance/interfaces}")
command -v ctags >/dev/null || { echo "check-function-length: needs universal-ctags (scripts/setup.sh)" >&2; exit 2; }
long=$(find "${folders[@]}" -name '*.cpp' -o -name '*.hpp' | sort |
  xargs ctags --fields=+ne --c++-kinds=f --language-force=C++ -o - |
  awk -F'\t' -v max="$max" '{
      line = 0; end = 0
      for (i = 4; i <= NF; ++i) {
        if ($i ~ /^line:/) line = substr($i, 6)
        if ($i ~ /^end:/) end = substr($i, 5)
      }
      if (end > 0 && end - line + 1 > max) printf "%5d %s:%d %s\n", end - line + 1, $2, line, $1
    }' | sort -rn)
if [[ -n "$long" ]]; then
  echo "functions over $max lines:"
  echo "$long"
  exit 1
fi
echo "function length: none over $max lines in ${folders[*]}"
