#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz/ with clang (ASan + UBSan) into
# build-fuzz/, replays every regression case of tests/fuzz/regressions/,
# checks that each target's work grows linearly with long inputs (a long
# block, a long comment, deep nesting, a big file: tests/fuzz/long_seeds.py
# and scaling.py), then runs each fuzzer for SECONDS (default 20) from the
# seed corpus and those long seeds, inputs up to 1 MiB. Exits 1 when a
# regression case fails, a target's work grows faster than its input, or the
# fuzzers find a crash, a hang (> 25 s), a leak or undefined behaviour; new
# crashers are written to tests/fuzz/crashers/.
#
#   scripts/fuzz.sh [SECONDS]
#   scripts/fuzz.sh --build-only               # build build-fuzz/fuzz_* and stop
#   CXX_FUZZ=clang++-15 scripts/fuzz.sh 60     # another clang
#   FUZZ_JOBS=1 scripts/fuzz.sh                # run the fuzzers one after the other
#   FUZZ_TARGETS="dxf fanuc" scripts/fuzz.sh   # only these targets (all are built)
#   FUZZ_OUT=/tmp/f FUZZ_EXTRA_FLAGS=-fsanitize-recover=undefined scripts/fuzz.sh --build-only
#                                              # a variant that goes on after known UB
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
build_only=0
if [[ "${1:-}" == "--build-only" ]]; then
  build_only=1
  shift
fi
seconds="${1:-20}"
cxx="${CXX_FUZZ:-clang++-14}"
jobs="${FUZZ_JOBS:-$(nproc)}"
out="${FUZZ_OUT:-$root/build-fuzz}"
fuzz="$root/tests/fuzz"
targets=(parser interpreter romi fanuc grbl dxf remote_request)
targets+=(apt cl)
targets+=(job_toml)
targets+=(config)
targets+=(forms)
# The dialect targets are one source, fuzz_dialect.cpp, built once per dialect
# with -DUSINA_FUZZ_DIALECT="<name>"; the others have a source of their own.
dialects=" romi fanuc grbl "
# The targets that read drawings link the cam module and its libraries
# instead of the gcode module.
cam_targets=" dxf "
# The targets of what a control punches link the dnc module's tape and
# request files (no event loop, no Boost).
dnc_targets=" remote_request "
# The targets of APT part programs link the apt module (core and canon under it).
apt_targets=" apt cl "
# The target of the job's TOML files links the job module's readers (toml++).
job_targets=" job_toml "
# The target of the configuration files and option values links their readers
# (sim, dnc and sim/stock files; toml++) and the gcode module (the tool table,
# the var file, and the dialects a [[machine]] may name).
config_targets=" config "
# The target of the web page's forms links their readers, the generators
# (cam) and the posts.
forms_targets=" forms "

command -v "$cxx" >/dev/null || { echo "fuzz.sh: $cxx not found (apt-get install clang-14 libclang-rt-14-dev)" >&2; exit 2; }
command -v ninja >/dev/null || { echo "fuzz.sh: ninja not found (apt-get install ninja-build)" >&2; exit 2; }
cam_flags="$(pkg-config --cflags dxflib polyclipping)" && cam_libs="$(pkg-config --libs dxflib polyclipping)" ||
  { echo "fuzz.sh: dxflib or polyclipping not found (apt-get install libdxflib-dev libpolyclipping-dev)" >&2; exit 2; }

# The library sources, excluding what src/CMakeLists.txt excludes from the
# gcode module (work in progress), so the fuzzers build whenever the project does.
exclude="$(sed -n 's/.*list(FILTER gcode_src EXCLUDE REGEX "\([^"]*\)").*/\1/p' "$root/src/CMakeLists.txt")"
mapfile -t base_sources < <(cd "$root" && ls src/core/*.cpp src/canon/*.cpp | sort)
mapfile -t gcode_sources < <(cd "$root" &&
  find src/gcode -name '*.cpp' | { if [[ -n "$exclude" ]]; then grep -Ev "$exclude"; else cat; fi; } | sort)
mapfile -t cam_sources < <(cd "$root" && ls src/cam/*.cpp | sort)
dnc_sources=(src/dnc/tape_code.cpp src/dnc/tape_reader.cpp src/dnc/remote_request.cpp)
mapfile -t apt_sources < <(cd "$root" && ls src/apt/*.cpp | sort)
job_sources=(src/job/toml_reader.cpp src/job/job_file.cpp src/job/tools.cpp src/job/materials.cpp
  src/sim/profile_keys.cpp)
config_sources=(src/sim/machine_profile.cpp src/sim/stock/tool_shape.cpp src/sim/stock/tool_reach.cpp
  src/sim/stock/height_map.cpp
  src/dnc/server_config.cpp src/dnc/machine_config.cpp src/dnc/link_config.cpp
  src/dnc/data_config.cpp src/dnc/link_port.cpp src/dnc/shift_calendar.cpp
  src/dnc/config_report.cpp src/dnc/tool_life_config.cpp)
mapfile -t post_sources < <(cd "$root" && ls src/post/*.cpp | sort)
mapfile -t forms_sources < <(cd "$root" && ls src/dnc/form_*.cpp | sort)

# A generated ninja file: parallel, incremental, header dependencies tracked.
mkdir -p "$out"
objects() { for s in "$@"; do printf 'obj/%s.o ' "${s%.cpp}"; done; }
{
  echo "cxx = $cxx"
  echo "cflags = -std=c++20 -g -O1 -fno-omit-frame-pointer -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined ${FUZZ_EXTRA_FLAGS:-} -I$root/src $cam_flags"
  echo "lflags = -fsanitize=fuzzer,address,undefined"
  echo "rule cxx"
  echo "  command = \$cxx \$cflags \$defines -MMD -MF \$out.d -c \$in -o \$out"
  echo "  depfile = \$out.d"
  echo "  deps = gcc"
  echo "  description = CXX \$in"
  echo "rule link"
  echo "  command = \$cxx \$lflags \$in -o \$out -lfmt \$libs"
  echo "  description = LINK \$out"
  for s in "${base_sources[@]}" "${gcode_sources[@]}" "${cam_sources[@]}" "${dnc_sources[@]}"; do
    echo "build obj/${s%.cpp}.o: cxx $root/$s"
  done
  for s in "${apt_sources[@]}" "${job_sources[@]}" "${config_sources[@]}" "${post_sources[@]}" \
    "${forms_sources[@]}"; do
    echo "build obj/${s%.cpp}.o: cxx $root/$s"
    if [[ "$s" == src/job/* || "$s" == src/sim/machine_profile.cpp || "$s" == src/dnc/* ]]; then
      echo "  defines = -DTOML_HEADER_ONLY=0 -DTOML_SHARED_LIB=1"
    fi
  done
  for t in "${targets[@]}"; do
    if [[ "$dialects" == *" $t "* ]]; then
      echo "build obj/tests/fuzz/fuzz_$t.o: cxx $fuzz/fuzz_dialect.cpp"
      echo "  defines = -DUSINA_FUZZ_DIALECT=\\\"$t\\\""
    else
      echo "build obj/tests/fuzz/fuzz_$t.o: cxx $fuzz/fuzz_$t.cpp"
      if [[ "$config_targets" == *" $t "* ]]; then echo "  defines = -DTOML_HEADER_ONLY=0 -DTOML_SHARED_LIB=1"; fi
    fi
    if [[ "$dnc_targets" == *" $t "* ]]; then
      echo "build fuzz_$t: link obj/tests/fuzz/fuzz_$t.o $(objects "${base_sources[@]}" "${dnc_sources[@]}")"
    elif [[ "$cam_targets" == *" $t "* ]]; then
      echo "build fuzz_$t: link obj/tests/fuzz/fuzz_$t.o $(objects "${base_sources[@]}" "${cam_sources[@]}")"
      echo "  libs = $cam_libs"
    elif [[ "$job_targets" == *" $t "* ]]; then
      echo "build fuzz_$t: link obj/tests/fuzz/fuzz_$t.o $(objects "${base_sources[@]}" "${cam_sources[@]}" "${job_sources[@]}")"
      echo "  libs = $cam_libs -ltomlplusplus"
    elif [[ "$config_targets" == *" $t "* ]]; then
      echo "build fuzz_$t: link obj/tests/fuzz/fuzz_$t.o $(objects "${base_sources[@]}" "${gcode_sources[@]}" "${config_sources[@]}" src/sim/profile_keys.cpp)"
      echo "  libs = -ltomlplusplus"
    elif [[ "$forms_targets" == *" $t "* ]]; then
      echo "build fuzz_$t: link obj/tests/fuzz/fuzz_$t.o $(objects "${base_sources[@]}" "${cam_sources[@]}" "${post_sources[@]}" "${forms_sources[@]}")"
      echo "  libs = $cam_libs"
    elif [[ "$apt_targets" == *" $t "* ]]; then
      echo "build fuzz_$t: link obj/tests/fuzz/fuzz_$t.o $(objects "${base_sources[@]}" "${apt_sources[@]}")"
    else
      echo "build fuzz_$t: link obj/tests/fuzz/fuzz_$t.o $(objects "${base_sources[@]}" "${gcode_sources[@]}")"
    fi
  done
} > "$out/build.ninja.new"
# Rewrite only on change, so ninja's incremental state survives.
cmp -s "$out/build.ninja.new" "$out/build.ninja" 2>/dev/null || mv "$out/build.ninja.new" "$out/build.ninja"
rm -f "$out/build.ninja.new"
ninja -C "$out" -j "$jobs"
[[ "$build_only" -eq 1 ]] && exit 0
if [[ -n "${FUZZ_TARGETS:-}" ]]; then
  read -r -a targets <<< "$FUZZ_TARGETS"
fi

failed=0

# 1. Every crasher ever found is replayed: a bug found is a test first.
for t in "${targets[@]}"; do
  shopt -s nullglob
  cases=("$fuzz/regressions/$t"/*)
  shopt -u nullglob
  for c in "${cases[@]}"; do
    [[ -f "$c" && "$c" != *.md ]] || continue
    if "$out/fuzz_$t" -timeout=5 -rss_limit_mb=2048 "$c" > "$out/replay.log" 2>&1; then
      echo "regression ok   $t ${c#"$root/"}"
    else
      echo "regression FAIL $t ${c#"$root/"}"
      grep -E 'ERROR|SUMMARY|runtime error|#[0-9]+ 0x' "$out/replay.log" | head -15 | sed 's/^/    /'
      failed=1
    fi
  done
done

# 2. Long inputs: each family of long_seeds.py at full size and at a quarter;
# the full one may take at most about four times the quarter's CPU time.
# One target at a time even with FUZZ_JOBS > 1: these are measurements, and
# runs side by side on two cores inflated a linear family's CPU time by 2.5x
# (CI, 2026-12-03: dxf hatch 0.44 s alone, 1.22 s beside eleven others).
python3 "$fuzz/long_seeds.py" "$out/long"
for t in "${targets[@]}"; do
  python3 "$fuzz/scaling.py" "$out/fuzz_$t" "$out/long/scaling/$t" || failed=1
done

# 3. Each fuzzer for $seconds (in parallel unless FUZZ_JOBS=1): new inputs go to
# build-fuzz/corpus/<target>; the checked-in seeds and the long ones are only
# read. Inputs grow to 1 MiB; the hang limit is 25 s (the longest seeds take
# about 2 s of CPU under ASan: room for a loaded machine, and super-linear
# work at that size takes minutes).
mkdir -p "$fuzz/crashers"
unset pid rc
declare -A pid rc
for t in "${targets[@]}"; do
  mkdir -p "$out/corpus/$t"
  "$out/fuzz_$t" -max_len=1048576 -timeout=25 -rss_limit_mb=2048 -max_total_time="$seconds" \
    -dict="$([[ -f "$fuzz/$t.dict" ]] && echo "$fuzz/$t.dict" || echo "$fuzz/gcode.dict")" -artifact_prefix="$fuzz/crashers/$t-" -print_final_stats=1 \
    "$out/corpus/$t" "$([[ -d "$fuzz/corpus_$t" ]] && echo "$fuzz/corpus_$t" || echo "$fuzz/corpus")" "$out/long/fuzz/$t" \
    > "$out/fuzz_$t.log" 2>&1 &
  pid[$t]=$!
  if [[ "$jobs" -le 1 ]]; then
    rc[$t]=0
    wait "${pid[$t]}" || rc[$t]=$?
  fi
done
for t in "${targets[@]}"; do
  if [[ -z "${rc[$t]:-}" ]]; then
    rc[$t]=0
    wait "${pid[$t]}" || rc[$t]=$?
  fi
  if [[ "${rc[$t]}" -eq 0 ]]; then
    runs="$(sed -n 's/^stat::number_of_executed_units: *//p' "$out/fuzz_$t.log")"
    echo "fuzz ok   $t: ${runs:-?} runs in ${seconds}s, nothing found"
  else
    echo "fuzz FAIL $t (log: build-fuzz/fuzz_$t.log)"
    grep -E 'ERROR|SUMMARY|runtime error|Test unit written|#[0-9]+ 0x' "$out/fuzz_$t.log" |
      head -25 | sed 's/^/    /'
    failed=1
  fi
done
exit "$failed"
