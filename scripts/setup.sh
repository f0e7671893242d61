#!/usr/bin/env bash
# Installs what usina needs to build and test, from Debian 12's packages.
# Run as root (or with sudo) on a fresh Debian 12 machine.
#   setup.sh                 what building needs
#   setup.sh --with-linuxcnc also LinuxCNC's rs274 (large), for the differential tests
set -euo pipefail
pkgs=(
  build-essential cmake ninja-build pkg-config git python3
  libfmt-dev libcli11-dev nlohmann-json3-dev libtomlplusplus-dev libexpected-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libdxflib-dev libcairo2-dev libpolyclipping-dev hershey-fonts-data
  poppler-utils
  clang-14 libclang-rt-14-dev clang-format
  libsqlite3-dev libpqxx-dev libssl-dev libsodium-dev postgresql
  libboost-dev libboost-system-dev socat
  libmosquitto-dev mosquitto openssl
  chromium
)
# Node.js and npm for the web page, from Debian when the machine has none
# (a machine with NodeSource's nodejs has npm in it: Debian's would clash).
command -v npm >/dev/null 2>&1 || pkgs+=(nodejs npm)
[ "${1:-}" = "--with-linuxcnc" ] && pkgs+=(linuxcnc-uspace)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo_cmd apt-get update -qq
  $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# The web page's build and browser test (docs/web.md): esbuild, three.js,
# TypeScript and Playwright (@playwright/test) at the versions of web/package-lock.json.
# Playwright drives Debian's chromium; it never downloads a browser.
(cd "$(dirname "$0")/../web" && npm ci --no-audit --no-fund)
