#!/usr/bin/env bash
# Configures and builds usina into build/ (Release, -O3, Ninja); extra
# arguments go to cmake (e.g. -DCMAKE_BUILD_TYPE=RelWithDebInfo).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build build --parallel "$(nproc)"
# The web page (docs/web.md) into build/web, where `usina serve` finds it
# beside the binary; skipped with a message when web/node_modules is missing.
if [ -d web/node_modules ]; then
  node web/build.mjs --outdir build/web
else
  echo "build.sh: web/node_modules is missing (scripts/setup.sh runs npm ci): the page is not built" >&2
fi
