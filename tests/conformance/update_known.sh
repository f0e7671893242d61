#!/usr/bin/env bash
# Rewrites known_differences.tsv from a run: program, first difference, why.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=$here/known_differences.tsv
{
  echo "# Programs of ../shared/conformance/rs274ngc whose trace differs from LinuxCNC's."
  echo "# program<TAB>first difference<TAB>why (from known_reasons.tsv). Regenerate: tests/conformance/update_known.sh"
  { python3 "$here/run_conformance.py" "$here/../../build/usina" "$here/../../../shared" --verbose || true; } |
    sed -nE 's/^(NEW )?FAIL ([^:]+): (.*)$/\2\t\3/p' | sort | python3 "$here/annotate_known.py"
} > "$out.tmp"
mv "$out.tmp" "$out"
wc -l "$out"
