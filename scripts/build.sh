#!/usr/bin/env bash
# Configures and builds usina into build/ (Release, -O3, Ninja); extra
# arguments go to cmake (e.g. -DCMAKE_BUILD_TYPE=RelWithDebInfo).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build build --parallel "$(nproc)"
