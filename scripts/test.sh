#!/usr/bin/env bash
# The README's test command: installs what is needed, builds, fuzzes the
# parser and interpreter for a short fixed time, runs every test.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --with-linuxcnc
bash scripts/build.sh
bash scripts/fuzz.sh 30
cd build
ctest --output-on-failure --parallel "$(nproc)"
