#!/usr/bin/env bash
# Traces every program of this folder with `usina trace --dialect fanuc`;
# each must run to its end without an error (exit status 0).
#   check_programs.sh USINA
set -uo pipefail
usina=$(realpath "$1")
here=$(cd "$(dirname "$0")" && pwd)
status=0
for prog in "$here"/*.nc; do
  if "$usina" trace --dialect fanuc "$prog" > /dev/null 2> /tmp/fanuc_prog_err.$$; then
    echo "ok   $(basename "$prog")"
  else
    echo "FAIL $(basename "$prog"): $(grep -m1 error /tmp/fanuc_prog_err.$$)"; status=1
  fi
done
rm -f /tmp/fanuc_prog_err.$$
exit $status
