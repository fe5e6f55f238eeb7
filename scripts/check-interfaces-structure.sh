#!/usr/bin/env bash
# Checks the shape of the host protocols (docs/architecture.md, "Host protocols"): every source of
# src/stepdance/interfaces/ sits in a protocol's folder or in link/, the core includes nothing
# from interfaces/, and no function in interfaces/ reaches 40 lines.
set -euo pipefail
cd "$(dirname "$0")/.."
status=0
loose=$(find src/stepdance/interfaces -maxdepth 1 -type f | sort)
if [[ -n "$loose" ]]; then
  echo "interfaces: files outside a protocol folder or link/:"
  echo "$loose"
  status=1
fi
core_uses=$(grep -rn '#include "stepdance/interfaces/' src/stepdance/core || true)
if [[ -n "$core_uses" ]]; then
  echo "interfaces: the core includes a protocol:"
  echo "$core_uses"
  status=1
fi
scripts/check-function-length.sh 39 src/stepdance/interfaces || status=1
[[ $status -eq 0 ]] && echo "interfaces: every source in a protocol folder or link/, the core protocol-free"
exit $status
