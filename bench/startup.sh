#!/usr/bin/env bash
# Start-up of the usina command (issue 19: a small `usina check` under
# 10 ms), the figures of docs/performance.md, "Start-up". A benchmark, not a
# test: it reports, it never fails on a time.
#
#   bench/startup.sh [USINA]        (default build/usina; needs perf, valgrind optional)
#
# For `usina --version` and `usina check` of a 10-line program: CPU time
# (perf stat task-clock, mean of 30 runs; /bin/true beside them, the cost of
# any process on this machine), instructions (valgrind's callgrind, the same
# on a loaded machine), the shared libraries loaded (ldd) and the dynamic
# loader's relocations (LD_DEBUG=statistics).
set -euo pipefail
usina=${1:-build/usina}
[ -x "$usina" ] || { echo "startup.sh: $usina is not an executable (build it first)" >&2; exit 2; }
program=$(mktemp /tmp/usina-startup-XXXXXX.ngc)
trap 'rm -f "$program" "$program.cg"' EXIT
printf 'G21 G90\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10\nG1 Y10\nG1 X0\nG1 Y0\nG0 Z5\nM5\nM2\n' >"$program"

cpu_ms() {  # the mean task-clock of 30 runs, in ms
  perf stat -r 30 -x, -e task-clock "$@" 2>&1 >/dev/null | awk -F, '/task-clock/ { printf "%.1f", $1 }'
}
instructions() {  # what callgrind counts, loader included ("-" without valgrind)
  if command -v valgrind >/dev/null; then
    valgrind --tool=callgrind --callgrind-out-file="$program.cg" "$@" 2>&1 >/dev/null |
      awk '/refs:/ { gsub(",", "", $NF); printf "%.1fM", $NF / 1e6 }'
  else
    printf -- "-"
  fi
}

echo "usina: $usina ($(ldd "$usina" | wc -l) shared libraries, ldd)"
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-28s %10s %14s\n' "command" "CPU ms" "instructions"
printf '%-28s %10s %14s\n' "/bin/true" "$(cpu_ms /bin/true)" "$(instructions /bin/true)"
printf '%-28s %10s %14s\n' "usina --version" "$(cpu_ms "$usina" --version)" \
  "$(instructions "$usina" --version)"
printf '%-28s %10s %14s\n' "usina check (10 lines)" "$(cpu_ms "$usina" check "$program")" \
  "$(instructions "$usina" check "$program")"
LD_DEBUG=statistics "$usina" --version 2>&1 >/dev/null |
  awk '/number of relocations:|relative relocations:/ { $1 = ""; print "loader:" $0 }'
