#!/usr/bin/env bash
# cmake --install of a build into a scratch prefix, then the installed usina
# run as a shop runs it: its helpers usina-serve and usina-raster.so beside
# it in bin/, found there (docs/performance.md, "Start-up").
#   check_install.sh BUILD_DIR PROGRAM
set -euo pipefail
build=$1
program=$2
prefix=$(mktemp -d /tmp/usina-install-XXXXXX)
trap 'rm -rf "$prefix"' EXIT
fail() { echo "check_install: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$prefix" >/dev/null
for f in usina usina-serve usina-raster.so; do
  [ -f "$prefix/bin/$f" ] || fail "cmake --install put no bin/$f in $prefix"
done
"$prefix/bin/usina" serve --help >"$prefix/serve-help" || fail "installed usina serve --help failed"
grep -q -- "--verify-audit" "$prefix/serve-help" || fail "usina serve --help lacks the server's flags"
"$prefix/bin/usina" draw "$program" --dialect romi -o "$prefix/part.png" 2>/dev/null ||
  fail "installed usina draw to PNG failed"
[ "$(head -c 4 "$prefix/part.png" | tail -c 3)" = "PNG" ] || fail "the installed draw wrote no PNG"
# The build's helpers are not what the installed usina runs: without its
# own, it fails and names the file beside it.
rm "$prefix/bin/usina-serve"
if "$prefix/bin/usina" serve --help >/dev/null 2>"$prefix/err"; then
  fail "usina serve ran with no usina-serve beside it"
fi
grep -q "$prefix/bin/usina-serve" "$prefix/err" || fail "the error does not name $prefix/bin/usina-serve"
echo "check_install: $prefix/bin holds usina and its helpers; they work from there"
