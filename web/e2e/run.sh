#!/usr/bin/env bash
# ctest's web.e2e: the page in Debian's chromium against a real usina serve
# (web/e2e/run.mjs). Skipped (77) with the reason when Node.js, chromium or
# web/node_modules is missing; scripts/setup.sh installs all three.
#   run.sh USINA SEED [--screenshots DIR]
set -euo pipefail
if ! command -v node >/dev/null 2>&1; then
  echo "SKIPPED: node is not installed (scripts/setup.sh installs it)"
  exit 77
fi
usina=$1 seed=$2
shift 2
exec node "$(dirname "$0")/run.mjs" --usina "$usina" --seed "$seed" "$@"
