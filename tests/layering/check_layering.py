#!/usr/bin/env python3
"""The module layering of DESIGN.md ("Modules ... and what each may use"),
made mechanical: every `#include "<module>/..."` under src/<X>/ must name X
itself or a module X may use. Prints each offending file:line and exits 1.

    tests/layering/check_layering.py ROOT      (ROOT: the repository)

A folder under src/ that the table does not know is an error too, so a new
module cannot skip the check; so is an include that climbs out with "../".
"""
import pathlib
import re
import sys

# DESIGN.md, the modules table. dnc may use "all of the above" (every module
# but cli); cli, the executable, may use every module.
ALLOWED = {
    "core": set(),
    "canon": {"core"},
    "gcode": {"core", "canon"},
    "apt": {"core", "canon"},
    "cam": {"core", "canon"},
    "draw": {"core", "canon"},
    "sim": {"core", "canon"},
    "post": {"core", "canon"},
    # job (issue 16): the cam generators, driven by a job file, on a machine profile.
    # gcode: a LinuxCNC tool table (gcode/tool_table) read as the tool library.
    "job": {"core", "canon", "cam", "sim", "gcode"},
    "dnc": {"core", "canon", "gcode", "apt", "cam", "draw", "sim", "post"},
    "cli": {"core", "canon", "gcode", "apt", "cam", "draw", "sim", "post", "dnc", "job"},
}

SUFFIXES = {".hpp", ".cpp", ".h", ".cc", ".inl", ".ipp"}
INCLUDE = re.compile(r'^\s*#\s*include\s*(["<])([^">]+)[">]')


def check(root):
    src = root / "src"
    if not src.is_dir():
        return [f"{src}: no such folder"], 0
    modules = sorted(p.name for p in src.iterdir() if p.is_dir())
    problems = []
    count = 0
    for module in modules:
        if module not in ALLOWED:
            problems.append(f"src/{module}/: a module DESIGN.md's table does not list; "
                            f"add it to the table (and to {pathlib.Path(__file__).name})")
            continue
        for path in sorted((src / module).rglob("*")):
            if path.suffix not in SUFFIXES or not path.is_file():
                continue
            rel = path.relative_to(root)
            text = path.read_text(encoding="utf-8", errors="replace")
            for number, line in enumerate(text.splitlines(), 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                count += 1
                target = m.group(2)
                if m.group(1) == '"' and target.startswith("../"):
                    problems.append(f"{rel}:{number}: #include \"{target}\" climbs out of the "
                                    f"module; include \"<module>/<file>\" instead")
                    continue
                used = target.split("/", 1)[0]
                if "/" not in target or used == module:
                    continue
                if used not in ALLOWED and used not in modules:
                    continue  # a library's header, e.g. <fmt/format.h>
                if used not in ALLOWED[module]:
                    may = ", ".join(sorted(ALLOWED[module])) or "nothing but std"
                    problems.append(f"{rel}:{number}: {module} may not include {used} "
                                    f"(\"{target}\"); {module} may use: {may}")
    return problems, count


def main(argv):
    if len(argv) != 2:
        sys.stderr.write(__doc__)
        return 2
    problems, count = check(pathlib.Path(argv[1]).resolve())
    for p in problems:
        print(p)
    if problems:
        print(f"layering: {len(problems)} violation(s) of DESIGN.md's module table")
        return 1
    print(f"layering: ok ({count} includes checked)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
