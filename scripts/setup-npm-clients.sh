#!/usr/bin/env bash
# Installs the npm test clients (tests/clients/package.json: saxi, the plotter driver the EBB
# tests drive, and axe-core, the accessibility checker the page tests run) project-locally,
# with the native serial binding built against Debian's node headers. Idempotent: does nothing
# when the locked versions are already installed.
set -euo pipefail
cd "$(dirname "$0")/../tests/clients"
command -v npm >/dev/null || { echo "setup-npm-clients: npm is missing (it ships with the machine's nodejs)" >&2; exit 1; }
stamp=node_modules/.stepdance-installed
if [ -f "$stamp" ] && [ "$stamp" -nt package-lock.json ]; then
  echo "setup-npm-clients: saxi and axe-core present"
  exit 0
fi
npm ci --no-audit --no-fund --nodedir=/usr
# npm may skip install scripts: build saxi's serial binding explicitly.
npm rebuild @serialport/bindings --nodedir=/usr
node -e "require('@serialport/bindings'); require('saxi/dist/server/ebb'); require('axe-core')"
touch "$stamp"
echo "setup-npm-clients: saxi and axe-core installed"
