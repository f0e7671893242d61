#!/usr/bin/env bash
# `usina simulate` on the 1,000,000-block surfacing program (issue 17's
# target: a 200 x 200 mm stock at 0.1 mm in under 10 s and under 1 GB), and
# its cost as a function of the resolution and of the program's length.
# A benchmark, not a test: it reports, it never fails on a time.
#
#   bench/simulate_bench.sh [USINA] [--blocks N] [--shape SHAPE] [--words W]
#
# USINA defaults to build-rel/usina (a Release build: see docs/simulate.md).
# The program comes from bench/gen_surfacing.py (in /tmp, made once); tool 1
# is a 6 mm SHAPE (default ball) given by --tool-shape, with the words W after
# it (e.g. --words ,holder:40,stickout:30: the holder's check). Wall time,
# user CPU and peak memory (max RSS) by /usr/bin/time -v.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
usina="$root/build-rel/usina"
blocks=1000000
shape=ball
words=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --blocks) blocks="$2"; shift 2 ;;
    --shape) shape="$2"; shift 2 ;;
    --words) words="$2"; shift 2 ;;
    -h | --help) sed -n "2,13p" "$0"; exit 0 ;;
    *) usina="$1"; shift ;;
  esac
done

program() {
  local n="$1" out="/tmp/usina-bench-surfacing-$1.ngc"
  if [[ ! -s "$out" || "$root/bench/gen_surfacing.py" -nt "$out" ]]; then
    python3 "$root/bench/gen_surfacing.py" "$n" "$out"
  fi
  echo "$out"
}

# One run: blocks, resolution -> "seconds MiB removed_mm3".
run() {
  local file report log
  file="$(program "$1")"
  report="$(mktemp /tmp/usina-bench-simulate-XXXXXX.json)"
  log="$(mktemp /tmp/usina-bench-simulate-XXXXXX.log)"
  /usr/bin/time -v "$usina" simulate "$file" --stock box:200x200x30 --resolution "$2" \
    --tool-shape "1=$shape/6$words" -o "$report" > /dev/null 2> "$log" || true
  local wall user rss removed
  wall="$(grep 'Elapsed (wall clock)' "$log" | awk '{print $NF}')"
  user="$(grep 'User time (seconds)' "$log" | awk '{print $NF}')"
  rss="$(grep 'Maximum resident set size' "$log" | awk '{printf "%.0f", $NF / 1024}')"
  removed="$(python3 -c 'import json,sys; print("%.1f" % json.load(open(sys.argv[1]))["removed_mm3"])' "$report")"
  rm -f "$report" "$log"
  printf '%9s blocks  %5s mm  %10s wall  %7s s user  %6s MiB  removed %s mm3\n' "$1" "$2" "$wall" \
    "$user" "$rss" "$removed"
}

echo "usina simulate, surfacing, 200 x 200 x 30 mm stock, tool 1 = $shape/6$words ($usina)"
echo "target: $blocks blocks at 0.1 mm in < 10 s and < 1 GB"
run "$blocks" 0.1
echo "cost against the resolution ($blocks blocks):"
for r in 0.4 0.2 0.05; do run "$blocks" "$r"; done
echo "cost against the program's length (0.1 mm):"
for n in 250000 500000; do run "$n" 0.1; done
