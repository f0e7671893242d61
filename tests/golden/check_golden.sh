#!/usr/bin/env bash
# Compares the trace of each program in tests/programs/rs274ngc/ that has a
# golden file tests/golden/<name>.jsonl ('#' lines are the hand-check note).
#   check_golden.sh USINA            compare (exit 1 on a difference)
#   check_golden.sh USINA --update   rewrite the goldens (then check by hand!)
set -euo pipefail
usina=$(realpath "$1"); mode=${2:-check}
here=$(cd "$(dirname "$0")" && pwd)
status=0
for golden in "$here"/*.jsonl; do
  name=$(basename "$golden" .jsonl)
  prog="$here/../programs/rs274ngc/$name.ngc"
  actual=$(cd "$here/../programs/rs274ngc" && "$usina" trace "$name.ngc" 2>/dev/null || true)
  if [ "$mode" = "--update" ]; then
    { grep '^#' "$golden" || true; printf '%s\n' "$actual"; } > "$golden.tmp" && mv "$golden.tmp" "$golden"
    continue
  fi
  if ! diff <(grep -v '^#' "$golden") <(printf '%s\n' "$actual") > /tmp/golden.diff; then
    echo "FAIL $name: trace differs from tests/golden/$name.jsonl"; head -20 /tmp/golden.diff; status=1
  else
    echo "ok   $name"
  fi
done
exit $status
