#!/usr/bin/env python3
"""Writes the 10,000-entity DXF sketch of bench/cam_bench.cpp to a file, for
timing the whole command (read, chain, generate, post):

    bench/gen_sketch_dxf.py /tmp/sketch.dxf [N]
    /usr/bin/time -v usina gen from-dxf /tmp/sketch.dxf --post rs274ngc -o /dev/null

LINEs (every third drawn backwards) and an ARC every seventh entity, a
zig-zag in rows of 100 entities: 100 open contours.
"""
import math
import sys


def drawing(n):
    out = ["0\nSECTION\n2\nENTITIES\n"]
    for i in range(n):
        x = float(i % 100)
        y = (i // 100) * 2.0 + (0.5 if i % 2 else 0.0)
        x2 = x + 1.0
        y2 = (i // 100) * 2.0 + (0.0 if i % 2 else 0.5)
        if i % 7 == 3:
            cx, cy = (x + x2) / 2, (y + y2) / 2
            r = math.hypot(x2 - x, y2 - y) / 2
            a1 = math.degrees(math.atan2(y - cy, x - cx))
            out.append(f"0\nARC\n8\nSKETCH\n10\n{cx}\n20\n{cy}\n30\n0\n40\n{r}\n50\n{a1}\n51\n{a1 + 180}\n")
        else:
            if i % 3 == 2:
                x, y, x2, y2 = x2, y2, x, y
            out.append(f"0\nLINE\n8\nSKETCH\n10\n{x}\n20\n{y}\n30\n0\n11\n{x2}\n21\n{y2}\n31\n0\n")
    out.append("0\nENDSEC\n0\nEOF\n")
    return "".join(out)


def main(argv):
    if len(argv) not in (2, 3):
        sys.stderr.write(__doc__)
        return 2
    n = int(argv[2]) if len(argv) == 3 else 10000
    with open(argv[1], "w") as f:
        f.write(drawing(n))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
