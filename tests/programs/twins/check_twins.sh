#!/usr/bin/env bash
# Traces the twins of this folder with usina and compares each trace with
# the LinuxCNC trace <name>.lcnc.jsonl (README.md says how those were made).
#   check_twins.sh USINA SHARED rs274ngc   the <name>.ngc twins
#   check_twins.sh USINA SHARED fanuc      the <name>.fanuc.nc twins
#   check_twins.sh USINA SHARED grbl       the <name>.grbl.nc twins
# SHARED is ../shared (compare_traces.py lives in SHARED/conformance).
# Dialect options a twin needs are in options.tsv (name, dialect, options).
set -euo pipefail
usina=$(realpath "$1"); compare="$2/conformance/compare_traces.py"; dialect=$3
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
case $dialect in
  rs274ngc) suffix=.ngc ;;
  fanuc) suffix=.fanuc.nc ;;
  grbl) suffix=.grbl.nc ;;
  *) echo "check_twins.sh: unknown dialect $dialect" >&2; exit 2 ;;
esac
status=0; count=0
for prog in "$here"/*"$suffix"; do
  name=$(basename "$prog" "$suffix"); count=$((count + 1))
  opts=$(awk -F'\t' -v n="$name" -v d="$dialect" '$1 == n && $2 == d { print $3 }' "$here/options.tsv")
  # shellcheck disable=SC2086 # the options are words
  if ! "$usina" trace --dialect "$dialect" $opts "$prog" > "$tmp/actual.jsonl" 2> "$tmp/err"; then
    echo "FAIL $name$suffix: usina failed: $(head -3 "$tmp/err")"; status=1; continue
  fi
  if python3 "$compare" "$here/$name.lcnc.jsonl" "$tmp/actual.jsonl" > "$tmp/diff"; then
    echo "ok   $name$suffix"
  else
    echo "FAIL $name$suffix: $(head -5 "$tmp/diff")"; status=1
  fi
done
[ "$count" -gt 0 ] || { echo "no $suffix twins in $here"; exit 1; }
exit $status
