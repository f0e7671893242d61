#!/usr/bin/env python3
"""Generates bench/gen_surfacing.py's program as Grbl 1.1 reads it.

    bench/gen_surfacing_grbl.py N OUT      (OUT may be '-' for standard output)

The same N blocks (same moves, arcs, feeds and '%' lines), with the one
block Grbl refuses changed: Grbl has no tool changer, so `T1 M6` (M6 is
error:20) becomes `T1`. Figures of `usina check --dialect grbl` on it compare
with `usina check` (rs274ngc) on gen_surfacing.py's program of the same N.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import gen_surfacing  # noqa: E402  (the path above finds it)

GRBL_LINES = {"T1 M6": "T1"}


def blocks(n):
    for line in gen_surfacing.blocks(n):
        yield GRBL_LINES.get(line, line)


def main(argv):
    if len(argv) != 3:
        sys.stderr.write(__doc__)
        return 2
    n = int(argv[1])
    out = sys.stdout if argv[2] == "-" else open(argv[2], "w", encoding="ascii", newline="\n")
    with out:
        buf = []
        for line in blocks(n):
            buf.append(line)
            if len(buf) >= 65536:
                out.write("\n".join(buf) + "\n")
                buf.clear()
        if buf:
            out.write("\n".join(buf) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
