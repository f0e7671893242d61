#!/usr/bin/env bash
# Differential test against LinuxCNC's own interpreter (Debian's
# linuxcnc-uspace, through ../shared/conformance/lcnc-trace.sh): every
# program in tests/programs/rs274ngc/ must give the same motion as rs274.
# Skipped (exit 0, says so) when rs274 or the shared folder is missing.
#   run_differential.sh USINA SHARED_DIR
set -uo pipefail
usina=$(realpath "$1"); shared=$(realpath "$2" 2>/dev/null || echo "$2")
lcnc=$shared/conformance/lcnc-trace.sh
if ! command -v rs274 >/dev/null || [ ! -x "$lcnc" ] && [ ! -f "$lcnc" ]; then
  echo "differential: rs274 (apt-get install linuxcnc-uspace) or $lcnc missing: skipped"
  exit 0
fi
here=$(cd "$(dirname "$0")" && pwd)
# rs274 must work at all (a broken install is an environment problem, said so).
probe=$(mktemp -d); printf 'G0 X1\nM2\n' > "$probe/p.ngc"
out=$(bash "$lcnc" "$probe/p.ngc" 2>/dev/null || true)
if [[ "$out" != *traverse* ]]; then
  echo "differential: rs274 is installed but does not run here: skipped"; rm -rf "$probe"; exit 0
fi
rm -rf "$probe"
progs=$here/../programs/rs274ngc
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# rs274 keeps its tool table in $HOME/.tool.mmap: another rs274 of the same
# user running meanwhile would clobber it. A home of its own.
export HOME=$tmp
pass=0; fail=0
for p in "$progs"/*.ngc; do
  name=$(basename "$p" .ngc)
  (cd "$progs" && bash "$lcnc" "$name.ngc" > "$tmp/$name.lcnc" 2>/dev/null)
  # Debian's rs274 (2.9) pecks G73/G83 back 0.254 mm (usina's default is 2.10's 1 mm).
  (cd "$progs" && "$usina" trace --peck-clearance 0.254 --machine-units inch --tool-table "$shared/conformance/rs274ngc/tools/generic.tbl" "$name.ngc" > "$tmp/$name.usina" 2>/dev/null)
  if python3 "$shared/conformance/compare_traces.py" "$tmp/$name.lcnc" "$tmp/$name.usina" > "$tmp/$name.diff"; then
    pass=$((pass + 1))
  else
    fail=$((fail + 1)); echo "FAIL $name: $(head -3 "$tmp/$name.diff")"
  fi
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
