#!/usr/bin/env bash
# The README's test command: installs what is needed, builds, runs every test.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --with-linuxcnc
bash scripts/build.sh
cd build
ctest --output-on-failure --parallel "$(nproc)"
cd ..
# The fuzzers of the parser and interpreter, a short fixed time each.
bash scripts/fuzz.sh 30
