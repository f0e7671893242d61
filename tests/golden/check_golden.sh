#!/usr/bin/env bash
# Compares the trace of each program that has a golden file:
#   tests/golden/<name>.jsonl         ← tests/programs/rs274ngc/<name>.ngc
#   tests/golden/<dialect>/<name>.jsonl ← tests/programs/<dialect>/<name>.nc, --dialect <dialect>
# ('#' lines are the hand-check note).
#   check_golden.sh USINA            compare (exit 1 on a difference)
#   check_golden.sh USINA --update   rewrite the goldens (then check by hand!)
set -euo pipefail
usina=$(realpath "$1"); mode=${2:-check}
here=$(cd "$(dirname "$0")" && pwd)
status=0
check() {  # golden, program folder, program file, trace options...
  local golden=$1 dir=$2 prog=$3; shift 3
  local name; name=$(basename "$golden" .jsonl)
  local actual; actual=$(cd "$dir" && "$usina" trace "$@" "$prog" 2>/dev/null || true)
  if [ "$mode" = "--update" ]; then
    { grep '^#' "$golden" || true; printf '%s\n' "$actual"; } > "$golden.tmp" && mv "$golden.tmp" "$golden"
    return
  fi
  if ! diff <(grep -v '^#' "$golden") <(printf '%s\n' "$actual") > /tmp/golden.diff; then
    echo "FAIL $name: trace differs from $golden"; head -20 /tmp/golden.diff; status=1
  else
    echo "ok   $name"
  fi
}
for golden in "$here"/*.jsonl; do
  name=$(basename "$golden" .jsonl)
  check "$golden" "$here/../programs/rs274ngc" "$name.ngc"
done
for golden in "$here"/*/*.jsonl; do
  [ -e "$golden" ] || continue
  dialect=$(basename "$(dirname "$golden")")
  name=$(basename "$golden" .jsonl)
  check "$golden" "$here/../programs/$dialect" "$name.nc" --dialect "$dialect"
done
exit $status
