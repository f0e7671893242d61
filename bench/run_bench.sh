#!/usr/bin/env bash
# Whole-command timing of the issue's speed and memory targets (a benchmark,
# not a test: it reports, it never fails on a time).
#
#   bench/run_bench.sh [--blocks N] [--runs R] [--no-micro] [--no-draw] [--no-dialects]
#   BUILD_DIR=/tmp/build-bench bench/run_bench.sh
#   bench/run_bench.sh --usina PATH ...   # times that usina, builds nothing
#
# 1. builds usina Release in $BUILD_DIR (default build-release/, not build/);
# 2. generates a 3D surfacing program of N blocks (default 1,000,000, ~30 MB)
#    in /tmp with bench/gen_surfacing.py;
# 3. times `usina check`, `usina trace --format jsonl > /dev/null` and
#    `usina stats` (default profile, then small_vmc with an S-curve) on it:
#    wall time with hyperfine (mean of R runs after a warm-up) when it is
#    installed (apt-get install hyperfine), otherwise the best of R runs;
#    CPU time (the least user+sys of R runs) and peak memory (max RSS) from
#    the kernel's accounting of the finished runs (getrusage);
# 4. prints MB/s (10^6 bytes of G-code a second) by wall and by CPU time, and
#    peak MiB, against the targets (check >= 100 MB/s, trace >= 30 MB/s,
#    peak < 32 MB), and for stats the seconds against its target (< 3 s);
# 5. times `usina draw` to DXF, SVG, PNG and PDF (issue 3: < 5 s; issue 19:
#    peak < 32 MB whatever the picture)
#    on the surfacing program and on a spiral of as many blocks made by
#    bench/gen_spiral.py, in which no two moves merge (the worst case: one
#    drawing entity a block); --no-draw leaves this out;
# 6. times check, trace, stats and convert (to the dialect's own control,
#    written to standard output) in every dialect (rs274ngc, fanuc, grbl,
#    romi) on the same raster written for each (bench/gen_surfacing*.py):
#    CPU MB/s, peak MiB and the ratio to rs274ngc (issue 19: each within
#    1.5x), and Debian's LinuxCNC interpreter `rs274` on the rs274ngc
#    program when it is installed (its ratio to usina check); --no-dialects
#    leaves this out;
# 7. runs the Google Benchmark micro-benchmarks (parser, interpreter alone).
#
# Before step 3 it prints the floor: bench/number_floor maps the program and
# reads its every number with usina's decimal routine, nothing else (the
# least CPU time of R passes), so figures from two machines compare.
#
# --usina PATH times an executable already built (two builds compared under
# the same load, one after the other) and skips step 1 and the
# micro-benchmarks, which need the build.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build-release}"
blocks=1000000
runs=5
micro=1
draw=1
dialects=1
given=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --blocks) blocks="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    --no-micro) micro=0; shift ;;
    --no-draw) draw=0; shift ;;
    --no-dialects) dialects=0; shift ;;
    --usina) given="$2"; micro=0; shift 2 ;;
    -h | --help) sed -n "2,40p" "$0"; exit 0 ;;
    *) echo "run_bench.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done

# GCC 12 at -O3 reports a false -Wrestrict inside std::string (parser.cpp,
# o_word); it must not stop a benchmark build.
if [[ -n "$given" ]]; then
  [[ -x "$given" ]] || { echo "run_bench.sh: --usina $given is not an executable" >&2; exit 2; }
  usina="$(cd "$(dirname "$given")" && pwd)/$(basename "$given")"
else
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_FLAGS="${BENCH_CXXFLAGS:--Wno-error=restrict}" > /dev/null
  cmake --build "$build" --target usina usina_bench number_floor > /dev/null
  usina="$build/usina"
fi
# bench/number_floor of the usina timed (its build's bench/ folder), else
# of the Release build or the README's build/.
floor_exe=""
for f in "$(dirname "$usina")/bench/number_floor" "$build/bench/number_floor" "$root/build/bench/number_floor"; do
  if [[ -x "$f" ]]; then floor_exe="$f"; break; fi
done

program="/tmp/usina-bench-surfacing-$blocks.ngc"
if [[ ! -s "$program" || "$root/bench/gen_surfacing.py" -nt "$program" ]]; then
  python3 "$root/bench/gen_surfacing.py" "$blocks" "$program"
fi
bytes="$(stat -c %s "$program")"
echo "program: $program, $blocks blocks, $bytes bytes"
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')"
if [[ -n "$given" ]]; then
  echo "usina:   $usina (given)"
else
  echo "usina:   $usina ($(cd "$build" && grep -m1 CMAKE_BUILD_TYPE:STRING CMakeCache.txt | cut -d= -f2))"
fi
"$usina" check "$program" || { echo "run_bench.sh: usina check fails on the generated program" >&2; exit 1; }

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# Wall seconds per run of the command line "$1" (run through sh, output discarded):
# hyperfine's mean when installed, else the best of $runs runs (a
# microsecond clock: /usr/bin/time's 10 ms put a row at a target's edge on
# either side of it from run to run).
wall_seconds() {
  if command -v hyperfine > /dev/null; then
    hyperfine --style none --warmup 1 --runs "$runs" --export-json "$tmp/h.json" "$1" > /dev/null
    python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["results"][0]["mean"])' "$tmp/h.json"
  else
    python3 - "$runs" "$1" << 'PY'
import subprocess, sys, time
best = float("inf")
for _ in range(int(sys.argv[1])):
    start = time.perf_counter()
    subprocess.run(["sh", "-c", sys.argv[2]], stdout=subprocess.DEVNULL, check=False)
    best = min(best, time.perf_counter() - start)
print(best)
PY
  fi
}

# "cpu_seconds peak_mib" of the command line "$1": the least user+sys time and
# the largest max RSS of $runs runs, from the kernel's accounting of the
# finished children (getrusage, to the microsecond). CPU time is what the
# program itself costs, so it holds on a machine shared with other work.
cpu_and_peak() {
  python3 - "$runs" "$1" << 'PY'
import resource, subprocess, sys
best, peak = float("inf"), 0
for _ in range(int(sys.argv[1])):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(["sh", "-c", sys.argv[2]], stdout=subprocess.DEVNULL, check=False)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    used = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    best = min(best, used)
    peak = max(peak, after.ru_maxrss)  # KiB, the largest child so far
print(best, peak / 1024)
PY
}

report() {  # name, command line, target MB/s
  local wall cpu mib
  wall="$(wall_seconds "$2")"
  read -r cpu mib < <(cpu_and_peak "$2")
  python3 - "$1" "$bytes" "$wall" "$cpu" "$mib" "$3" << 'PY'
import sys
name, size, wall, cpu, mib, target = sys.argv[1], int(sys.argv[2]), *map(float, sys.argv[3:])
mb = size / 1e6
ok = lambda good: "ok" if good else "MISSED"
print(f"{name:6} wall {wall:6.3f} s = {mb / wall:6.1f} MB/s   cpu {cpu:6.3f} s = {mb / cpu:6.1f} MB/s"
      f"   (target >= {target:g} MB/s: wall {ok(mb / wall >= target)}, cpu {ok(mb / cpu >= target)})"
      f"   peak {mib:5.1f} MiB (target < 32: {ok(mib < 32)})")
PY
}

echo "load before timing: $(cut -d' ' -f1-3 /proc/loadavg) (wall figures need a quiet machine; cpu figures do not)"
echo "timing: wall $(command -v hyperfine > /dev/null && echo "= hyperfine mean of $runs runs" || echo "= best of $runs runs"); cpu = least user+sys of $runs runs"
if [[ -x "$floor_exe" ]]; then
  # The floor: the file mapped and its numbers read, nothing else.
  read -r _ _ _ floor_cpu floor_mbs < <("$floor_exe" "$program" "$runs")
  echo "floor  cpu $floor_cpu s = $floor_mbs MB/s: the file mapped and every number read with usina's decimal routine, nothing else (bench/number_floor)"
else
  echo "floor: bench/number_floor not built (cmake --build BUILD --target number_floor)"
fi
report check "'$usina' check '$program'" 100
report trace "'$usina' trace --format jsonl '$program' > /dev/null" 30

# usina stats: the whole command (interpreter, planner, checks, report)
# against the issue's target of 3 s for 1,000,000 blocks; once with the
# default profile (trapezoidal), once with an S-curve profile (small_vmc
# with jerk 20000 mm/s³ on every axis), the planner's costlier case.
jerk_profile="$tmp/small_vmc_jerk.toml"
sed 's/^jerk = 0.0.*$//; s/^accel = \(.*\)$/accel = \1\njerk = 20000.0/' \
  "$root/examples/machines/small_vmc.toml" > "$jerk_profile"
report_seconds() {  # name, command line, target seconds
  local wall cpu mib
  wall="$(wall_seconds "$2")"
  read -r cpu mib < <(cpu_and_peak "$2")
  python3 - "$1" "$wall" "$cpu" "$mib" "$3" << 'PY'
import sys
name, wall, cpu, mib, target = sys.argv[1], *map(float, sys.argv[2:])
ok = lambda good: "ok" if good else "MISSED"
print(f"{name:14} wall {wall:6.3f} s   cpu {cpu:6.3f} s   (target < {target:g} s: wall {ok(wall < target)}, "
      f"cpu {ok(cpu < target)})   peak {mib:5.1f} MiB")
PY
}
report_seconds "stats" "'$usina' stats '$program' > /dev/null 2>&1" 3
report_seconds "stats s-curve" "'$usina' stats --machine '$jerk_profile' '$program' > /dev/null 2>&1" 3
report_draw() {  # name, command line: seconds and MiB against the targets of issues 3 and 19
  local wall cpu mib
  wall="$(wall_seconds "$2")"
  read -r cpu mib < <(cpu_and_peak "$2")
  python3 - "$1" "$wall" "$cpu" "$mib" << 'PY'
import sys
name, wall, cpu, mib = sys.argv[1], *map(float, sys.argv[2:])
ok = lambda good: "ok" if good else "MISSED"
print(f"{name:22} wall {wall:6.3f} s   cpu {cpu:6.3f} s   (target < 5 s: wall {ok(wall < 5)}, "
      f"cpu {ok(cpu < 5)})   peak {mib:6.1f} MiB (target < 32: {ok(mib < 32)})")
PY
}

if [[ "$draw" -eq 1 ]]; then
  spiral="/tmp/usina-bench-spiral-$blocks.ngc"
  if [[ ! -s "$spiral" || "$root/bench/gen_spiral.py" -nt "$spiral" ]]; then
    python3 "$root/bench/gen_spiral.py" "$blocks" "$spiral"
  fi
  echo
  echo "usina draw, $blocks blocks: surfacing (rows merge into lines) and spiral (nothing merges)"
  for input in surfacing:"$program" spiral:"$spiral"; do
    for format in dxf svg png pdf; do
      report_draw "${input%%:*} -> $format" "'$usina' draw '${input#*:}' -o '$tmp/drawing.$format'"
    done
  done
fi

# The command line of a verb in a dialect (output and warnings discarded).
dialect_line() {  # dialect, program, verb (check|trace|stats|convert)
  case "$3" in
    check) echo "'$usina' check --dialect $1 '$2' > /dev/null 2>&1" ;;
    trace) echo "'$usina' trace --dialect $1 --format jsonl '$2' > /dev/null 2>&1" ;;
    stats) echo "'$usina' stats --dialect $1 '$2' > /dev/null 2>&1" ;;
    convert) echo "'$usina' convert --dialect $1 --post $1 '$2' > /dev/null 2>&1" ;;
  esac
}

# One row of the dialects' table: CPU MB/s, the ratio to rs274ngc, peak MiB.
dialect_row() {  # dialect, program, verb, rs274ngc's cpu seconds
  local line cpu mib size
  line="$(dialect_line "$1" "$2" "$3")"
  read -r cpu mib < <(cpu_and_peak "$line")
  size="$(stat -c %s "$2")"
  python3 - "$1" "$3" "$size" "$cpu" "$mib" "$4" << 'PY'
import sys
dialect, verb, size, cpu, mib, base = sys.argv[1], sys.argv[2], int(sys.argv[3]), *map(float, sys.argv[4:])
target = {"check": 250, "trace": 120, "stats": 100, "convert": 80}[verb]
ok = lambda good: "ok" if good else "MISSED"
print(f"{dialect:9} {verb:7} cpu {cpu:6.3f} s = {size / 1e6 / cpu:6.1f} MB/s (>= {target}: {ok(size / 1e6 / cpu >= target)})"
      f"   x{cpu / base:4.2f} of rs274ngc (<= 1.5: {ok(cpu / base <= 1.5)})   peak {mib:5.1f} MiB (< 32: {ok(mib < 32)})")
PY
}

if [[ "$dialects" -eq 1 ]]; then
  echo
  echo "every dialect, $blocks blocks of the same raster (cpu = least user+sys of $runs runs)"
  declare -A programs=([rs274ngc]="$program" [fanuc]="$program")
  for d in grbl romi; do
    programs[$d]="/tmp/usina-bench-surfacing-$blocks.$d"
    if [[ ! -s "${programs[$d]}" || "$root/bench/gen_surfacing_$d.py" -nt "${programs[$d]}" ]]; then
      python3 "$root/bench/gen_surfacing_$d.py" "$blocks" "${programs[$d]}"
    fi
  done
  for verb in check trace stats convert; do
    read -r base _ < <(cpu_and_peak "$(dialect_line rs274ngc "$program" "$verb")")
    for d in rs274ngc fanuc grbl romi; do
      dialect_row "$d" "${programs[$d]}" "$verb" "$base"
    done
  done
  table="$root/../shared/conformance/rs274ngc/tools/generic.tbl"
  if command -v rs274 > /dev/null && [[ -f "$table" ]]; then
    # rs274 as lcnc-trace.sh runs it: canon calls printed, to /dev/null.
    read -r lcnc _ < <(cpu_and_peak "rs274 -g -t '$table' '$program' < /dev/null > /dev/null 2>&1")
    read -r mine _ < <(cpu_and_peak "$(dialect_line rs274ngc "$program" check)")
    python3 -c 'import sys; l, u = map(float, sys.argv[1:]); print(f"rs274 (LinuxCNC) cpu {l:.3f} s; usina check {u:.3f} s: usina takes 1/{l / u:.0f} of its time")' "$lcnc" "$mine"
  else
    echo "rs274 or ../shared's tool table missing (apt-get install linuxcnc-uspace): no LinuxCNC ratio"
  fi
fi

if [[ "$micro" -eq 1 ]]; then
  echo
  "$build/bench/usina_bench" --benchmark_min_time=0.5
fi
