#!/usr/bin/env bash
# The README's test command: installs what is needed, builds, fuzzes the
# parser and interpreter for a short fixed time, runs every test.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --with-linuxcnc
bash scripts/build.sh
# The optimiser's warnings differ between -O3 and -O2 (GCC 12's false
# -Wrestrict fires only at -O3): the program (every library and the usina
# binary) must compile under -Werror at both; the tests run on Release.
cmake -S . -B build-relwithdebinfo -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build-relwithdebinfo --parallel "$(nproc)" --target usina
bash scripts/fuzz.sh 30
cd build
ctest --output-on-failure --parallel "$(nproc)"
