#!/usr/bin/env python3
"""Long seeds for the fuzz targets, written by scripts/fuzz.sh.

The checked-in seeds are small programs; these reach what they cannot: a long
block, a long comment, deep nesting, a big file (issue 11: the fuzzers' inputs
stayed under 1.3 KB, so a DXF line of 1,024 characters and a quadratic fanuc
block were never met). Each family is written at its full size and at a quarter
of it, so scripts/fuzz.sh can tell linear work from super-linear work by the
ratio of the two times (tests/fuzz/scaling.py).

    long_seeds.py OUT_DIR

writes OUT_DIR/scaling/<target>/<family>.<full|quarter>.<ext> for scaling.py
and OUT_DIR/fuzz/<target>/<family>.<ext>, each under 64 KB, for the fuzzers
to start from. The output is deterministic; every file is within the
fuzzers' -max_len (1 MiB).
"""
import json
import os
import sys

MAX_LEN = 1 << 20


def repeat_to(unit, size):
    """`unit` repeated to about `size` bytes (whole units)."""
    return unit * max(1, size // len(unit))


# --- G-code: one text per family, from a size --------------------------------

def moves(n, line, start=""):
    """`start`, then numbered `line`s (a %-format of i % 97 and i % 89) to about n bytes."""
    out = [start]
    size = len(start)
    i = 0
    while size < n:
        out.append(line % (i % 97, i % 89))
        size += len(out[-1])
        i += 1
    return "".join(out)


def ngc_families(end="\n", comment=("(", ")"), start="G21 G90 G17", stop="M2", units=""):
    """Families for rs274ngc-like dialects; `end` ends a block."""
    open_c, close_c = comment
    return {
        # One block of 200 KB: words the parser reads one after the other.
        "block": lambda n: start + end + "G1 F100 " + repeat_to("X1 Y2 Z3 ", n) + end + stop + end,
        # A comment of 100 KB inside a block.
        "comment": lambda n: start + end + "G0 X1 " + open_c + repeat_to("comment ", n) + close_c
        + end + stop + end,
        # Brackets nested 10,000 deep (20 KB).
        "nesting": lambda n: start + end + "G1 F100 X" + "[" * (n // 2) + "1" + "]" * (n // 2)
        + end + stop + end,
        # A program of 1 MB: moves, one a block.
        "program": lambda n: moves(n, "G1 X%%d%s Y%%d%s F600%s" % (units, units, end),
                                   start + end) + stop + end,
    }


def romi_families():
    f = ngc_families(end="#\n", comment=(";", ""), start="G71", stop="M02", units=".")
    f["nesting"] = lambda n: "G71#\nG01 F100 X" + "(" * (n // 2) + "1" + ")" * (n // 2) + "#\nM02#\n"
    return f


def fanuc_families():
    f = ngc_families(start="%\nO1000\nG21 G90 G17", stop="M30\n%", units=".")
    return f


SIZES = {"block": 200_000, "comment": 100_000, "nesting": 20_000, "program": 1_000_000}

# --- DXF ----------------------------------------------------------------------


def pairs(groups):
    return "".join("%s\n%s\n" % g for g in groups)


def entities(body):
    return "0\nSECTION\n2\nENTITIES\n" + body + "0\nENDSEC\n0\nEOF\n"


def dxf_lines(n):
    unit = pairs([(0, "LINE"), (8, "CUT"), (10, 1), (20, 2), (11, 30), (21, 40)])
    return entities(repeat_to(unit, n))


def dxf_lwpolyline(n):
    count = n // 20
    body = pairs([(0, "LWPOLYLINE"), (8, "CUT"), (90, count), (70, 1)])
    body += "".join(pairs([(10, i % 500), (20, (i * 7) % 300)]) for i in range(count))
    return entities(body)


def dxf_splines(n):
    unit = pairs([(0, "SPLINE"), (8, "0"), (70, 8), (71, 3), (72, 8), (73, 4), (74, 0)]
                 + [(40, k) for k in (0, 0, 0, 0, 1, 1, 1, 1)]
                 + [(10, 0), (20, 0), (10, 10), (20, 20), (10, 30), (20, -20), (10, 40), (20, 0)])
    return entities(repeat_to(unit, n))


def dxf_hatch(n):
    edges = n // 40
    body = pairs([(0, "HATCH"), (8, "0"), (2, "X"), (70, 0), (91, 1), (92, 1), (93, edges)])
    body += "".join(pairs([(72, 1), (10, i), (20, 0), (11, i + 1), (21, 1)]) for i in range(edges))
    return entities(body + pairs([(0, "LINE"), (8, "0"), (10, 0), (20, 0), (11, 1), (21, 1)]))


DXF = {
    # One value line of 200 KB (dxflib's reader never finished a line of 1 KB).
    "value": lambda n: entities(pairs([(0, "LINE"), (8, "L" * n), (10, 0), (20, 0), (11, 1),
                                       (21, 1)])),
    # A comment of 100 KB, left out before dxflib.
    "comment": lambda n: pairs([(999, "c" * n)]) + dxf_lines(100),
    "lines": dxf_lines,
    "lwpolyline": dxf_lwpolyline,
    "splines": dxf_splines,
    "hatch": dxf_hatch,
}
DXF_SIZES = {"value": 200_000, "comment": 100_000, "lines": 1_000_000, "lwpolyline": 1_000_000,
             "splines": 1_000_000, "hatch": 1_000_000}

# --- remote requests: a punch's rows, the first byte picks code and block end --

REQUEST = {
    # A request whose comment holds 200 KB of KEY=VALUE pairs.
    "comment": lambda n: "\x00%\nO9999\n(" + repeat_to("PRG=A ", n) + ")\n%",
    # A punch of 1 MB: moves, one a block, with DC codes and a leader.
    "program": lambda n: moves(n, "G1 X%d Y%d F600\n", "\x00\x12" + "\x00" * 50 + "%\nO1\n")
    + "%\x14",
    # A label of 100 KB on the leader, before the first `%`.
    "label": lambda n: "\x00" + repeat_to("LABEL ", n) + "%\nO9999\n(PRG=1)\n%",
}
REQUEST_SIZES = {"comment": 200_000, "program": 1_000_000, "label": 100_000}


# --- APT part programs ----------------------------------------------------------


def apt_program(n):
    """Geometry, scalars and motion, one statement a line, to about n bytes."""
    out = ["PARTNO LONG\nCUTTER/0.5\nFROM/0,0,0\n"]
    size = len(out[0])
    i = 0
    while size < n:
        out.append("P%d=POINT/%d,%d,0\nL%d=LINE/P%d,ATANGL,%d\nA%d=SQRTF(%d)+%d*2\nGOTO/P%d\n"
                   % (i, i % 97, i % 89, i, i, i % 360, i, i, i % 7, i))
        size += len(out[-1])
        i += 1
    return "".join(out) + "FINI\n"


APT = {
    # One statement of 200 KB: an expression of many terms.
    "statement": lambda n: "A=" + repeat_to("1+2*3-", n) + "1\nFINI\n",
    # A comment of 100 KB after $$.
    "comment": lambda n: "$$" + "c" * n + "\nFROM/0,0,0\nFINI\n",
    # Parentheses nested 10,000 deep.
    "nesting": lambda n: "A=" + "(" * (n // 2) + "1" + ")" * (n // 2) + "\nFINI\n",
    # One statement continued over many lines with $.
    "continuation": lambda n: "GOTO/1" + repeat_to(",$\n1", n) + "\nFINI\n",
    # A program of 1 MB.
    "program": apt_program,
    # 1 MB of contouring: a startup, a line to a circle, the circle to a line.
    "contour": lambda n: "L1=LINE/0,0,0,10\nL2=LINE/0,5,10,5\nC=CIRCLE/-3,5,3\nCUTTER/2\n"
    + repeat_to("GOTO/-5,-5,0\nGO/TO,L1\nTLLFT,GOLFT/L1,TANTO,C\nGOFWD/C,PAST,L2\n", n) + "FINI\n",
    # 1 MB of patterns: large ones named again and again, GOTO/pattern with
    # long lists of ranges (their work must not be the product of the two).
    "patern": lambda n: "P=POINT/0,0\nV=VECTOR/1,0,0\nA=PATERN/LINEAR,P,V,100000\n"
    + repeat_to("B=PATERN/RANDOM,A,P\nX=POINT/A,99999\nGOTO/A,OMIT,1,THRU,99999,"
                "AVOID,1,2,THRU,100000,RETAIN,1,THRU,100000\n", n) + "FINI\n",
}
# --- CL files (the first byte picks the reader: 0 NX CLSF, 1 APT CL)


def clsf_program(n):
    """NX CLSF: GOTO, CIRCLE and its end, PAINT, FEDRAT, to about n bytes."""
    out = ["0TOOL PATH/LONG,TOOL,D10\nTLDATA/MILL,10,0,50,0,0\nRAPID\nGOTO/0,-10,0,0,0,1\n"]
    size = len(out[0])
    while size < n:
        out.append("PAINT/COLOR,31\nFEDRAT/MMPM,500\nCIRCLE/0,0,0,0,0,-1,10,0.06,0.5\n"
                   "GOTO/-10,0,0\nCIRCLE/0,0,0,0,0,-1,10\nGOTO/0,-10,0\n")
        size += len(out[-1])
    return "".join(out) + "END-OF-PATH\n"


CL = {
    # One statement of 200 KB (beyond the 64 KiB bound).
    "statement": lambda n: "1GOTO/1" + repeat_to(",1", n) + "\n",
    # A comment of 100 KB after $$.
    "comment": lambda n: "0$$" + "c" * n + "\nGOTO/0,0,0\n",
    # One statement continued over many lines with $.
    "continuation": lambda n: "1PPRINT/A" + repeat_to("$\nB", n) + "\nFINI\n",
    # A file of 1 MB.
    "program": clsf_program,
}
CL_SIZES = {"statement": 200_000, "comment": 100_000, "continuation": 200_000,
            "program": 1_000_000}

APT_SIZES = {"statement": 200_000, "comment": 100_000, "nesting": 20_000,
             "continuation": 200_000, "program": 1_000_000,
             "contour": 1_000_000, "patern": 1_000_000}

# --- usina job's TOML files (the first byte picks the reader: 0 job, 1 tools, 2 materials)

JOB_OPERATION = ('[[operation]]\ntype = "pocket"\nlayer = "POCKET"\ndepth = 4.0\n'
                 'step_down = 2.0\ntool = "auto"\n\n')
JOB_TOOL = ('[[tool]]\nnumber = 1\nname = "10 mm end mill"\ntype = "flat"\ndiameter = 10.0\n'
            'flutes = 3\ncutting_length = 22.0\noverall_length = 72.0\nmaterial = "carbide"\n\n')
JOB_TOML = {
    # A job of 1 MB: its header, then operations.
    "operations": lambda n: '0[job]\nname = "long"\ntools = "t.toml"\nmaterials = "m.toml"\n'
    'drawing = "d.dxf"\n[stock]\nshape = "box"\nsize = [100.0, 100.0, 10.0]\n'
    'material = "aluminium-wrought"\n\n' + repeat_to(JOB_OPERATION, n),
    # A tool library of 1 MB.
    "tools": lambda n: "1" + repeat_to(JOB_TOOL, n),
    # Arrays nested 10,000 deep (toml++ stops at its own limit).
    "nesting": lambda n: "0a = " + "[" * (n // 2) + "]" * (n // 2) + "\n",
    # A string of 200 KB in a materials file.
    "string": lambda n: '2x = "' + "a" * n + '"\n',
}
JOB_TOML_SIZES = {"operations": 1_000_000, "tools": 1_000_000, "nesting": 20_000,
                  "string": 200_000}

# --- configuration files and option values (the first byte picks the reader:
# 0 machine profile, 1 usina-serve.toml, 2 tool table, 3 var file, 4 --stock,
# 5 --tool-shape, 6 a link's port or mqtt.url)

PROFILE_AXES = "".join('[axes.%s]\nmin = -0.0\nmax = 1e6\nrapid = 1e6\nmax_feed = 1\naccel = 1e6\n'
                       'jerk = 0\n' % a for a in "xyzabc")
PROFILE_HEAD = '0[machine]\nname = "long"\nunits = "inch"\n' + PROFILE_AXES


def serve_machines(n, numbers=False):
    """usina-serve.toml with [[machine]] tables, each named apart, to about n bytes;
    with `numbers`, each table's numbers at the edges of a double (every one an error)."""
    out = ['1[server]\nsession_hours = 720\n[mqtt]\nurl = "mqtt://[::1]"\n']
    size = len(out[0])
    i = 0
    edges = ("nan", "inf", "-inf", "1e308", "-0.0", "-1e308")
    while size < n:
        if numbers:
            limits = "xon_timeout = %s\nreceive_idle = %s\nskid = %s\n" % (
                edges[i % 6], edges[(i + 1) % 6], edges[(i + 2) % 6])
        else:
            limits = "xon_timeout = 1.0\nreceive_idle = 3600\nskid = 65536\n"
        out.append('[[machine]]\nname = "m%d"\nport = "tcp://10.0.%d.%d:4001"\nbaud = 115200\n'
                   '%spart_count_pattern = "^PART ([0-9]+)"\n\n' % (i, i % 256, i % 251, limits))
        size += len(out[-1])
        i += 1
    return "".join(out)


def tool_lines(n):
    """A tool table listed in descending order of tool number (each line placed
    before all the others so far), to about n bytes."""
    count = n // 40
    return "2" + "".join("T%d P%d X+0.5 Z-1.5 D%d.25 ;ball\n" % (count - i, i, i % 50)
                         for i in range(count))


def var_lines(n):
    """A parameter file: every number 1..5601 in order, then again (each one a
    repeat), values at the edges of a double, to about n bytes."""
    values = ("0.000000", "-1.8e308", "nan", "-0", "inf", "4.9e-324", "+12.5")
    out = ["3"]
    size = 1
    i = 0
    while size < n:
        # 1e308 now and then: written back with six decimals it takes 10 ms
        # under ASan (309 digits), and 5,601 of them a minute.
        value = "1e308" if i % 500 == 0 else values[i % len(values)]
        out.append("%d\t%s\n" % (i % 5601 + 1, value))
        size += len(out[-1])
        i += 1
    return "".join(out)


CONFIG = {
    # A profile of 1 MB: its axes, then 100,000 keys it does not read.
    "keys": lambda n: PROFILE_HEAD + "[cost]\n" + "".join(
        "per_hour_%d = 1\n" % i for i in range(n // 18)),
    # A profile whose name is a string of 1 MB.
    "string": lambda n: '0[machine]\nname = "' + "a" * n + '"\n' + PROFILE_AXES,
    # Arrays nested 10,000 deep in a profile (toml++ stops at its own limit).
    "nesting": lambda n: "0[machine]\nname = " + "[" * (n // 2) + "]" * (n // 2) + "\n",
    # Inline tables nested 10,000 deep in usina-serve.toml.
    "inline": lambda n: "1server = " + "{a=" * (n // 3) + "1" + "}" * (n // 3) + "\n",
    # usina-serve.toml of 1 MB: [[machine]] tables, each with its data pattern.
    "machines": serve_machines,
    # The same with numbers at the edges of a double (nan, inf, 1e308, -0).
    "numbers": lambda n: serve_machines(n, numbers=True),
    # A data pattern of 200 KB (std::regex recursed once a character).
    "pattern": lambda n: '1[[machine]]\nname = "m"\nport = "/dev/ttyS0"\npart_count_pattern = "'
    + "(" * (n // 2) + "a" + ")" * (n // 2) + '"\n',
    # A tool table of 1 MB in descending order of tool number.
    "tools": tool_lines,
    # A parameter file of 1 MB.
    "vars": var_lines,
    # --stock with a side of 200 KB of digits.
    "stock": lambda n: "4box:" + "1" * n + "x2x3",
    # --tool-shape with 200 KB of words, and a comment of words no shape has.
    "shape": lambda n: "51=" + repeat_to("blob ", n) + "/6",
    # A port of 200 KB.
    "port": lambda n: "6tcp://" + "h" * n + ":4001",
}
CONFIG_SIZES = {"keys": 1_000_000, "string": 1_000_000, "nesting": 20_000, "inline": 30_000,
                "machines": 1_000_000, "numbers": 1_000_000, "pattern": 200_000, "tools": 1_000_000,
                "vars": 1_000_000, "stock": 200_000, "shape": 200_000, "port": 200_000}

# --- the web page's forms (the first byte picks the cycle by its value mod 7:
# "1" ellipse pocket ... "6" engraving, "0" the profile of a DXF)


def json_object_of_keys(n):
    keys, size, i = [], 2, 0
    while size < n:
        k = '"k%d":%d' % (i, i)
        keys.append(k)
        size += len(k) + 1
        i += 1
    return "{" + ",".join(keys) + "}"


FORMS = {
    # An engraving of 1 MB of text.
    "text": lambda n: '6{"text":"' + repeat_to("USINA ", n) + '","height":8,"tool_diameter":0.5}',
    # A body of 1 MB of unknown fields (each is an error naming the nearest field).
    "keys": lambda n: "2" + json_object_of_keys(n),
    # Arrays nested 10,000 deep as a field's value.
    "nesting": lambda n: '3{"radius":' + "[" * (n // 2) + "]" * (n // 2) + "}",
    # A profile of a 1 MB drawing of lines, in the body as the page sends it.
    "dxf": lambda n: '0{"dxf":' + json.dumps(dxf_lines(n)) + ',"depth":2}',
}
FORMS_SIZES = {"text": 1_000_000, "keys": 1_000_000, "nesting": 20_000, "dxf": 600_000}

TARGETS = {
    "parser": (ngc_families(), SIZES, "ngc"),
    "interpreter": (ngc_families(), SIZES, "ngc"),
    "romi": (romi_families(), SIZES, "nc"),
    "fanuc": (fanuc_families(), SIZES, "nc"),
    "grbl": (ngc_families(), SIZES, "gcode"),
    "dxf": (DXF, DXF_SIZES, "dxf"),
    "remote_request": (REQUEST, REQUEST_SIZES, "tape"),
    "apt": (APT, APT_SIZES, "apt"),
    "cl": (CL, CL_SIZES, "cls"),
    "job_toml": (JOB_TOML, JOB_TOML_SIZES, "toml"),
    "config": (CONFIG, CONFIG_SIZES, "txt"),
    "forms": (FORMS, FORMS_SIZES, "json"),
}


# The size of the seeds the fuzzers mutate: long enough to pass the limits
# of a line (1,024 in dxflib, 4,096 values in a block), to nest 10,000 deep
# and to hold thousands of blocks, short enough that a run of 30 s still makes
# thousands of inputs (1 MiB seeds made 100 a second).
FUZZ_SIZE = 64 * 1024


def write(path, text):
    assert len(text) <= MAX_LEN, (path, len(text))
    with open(path, "w", newline="") as f:
        f.write(text)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    for target, (families, sizes, ext) in TARGETS.items():
        scaling = os.path.join(out, "scaling", target)
        fuzzing = os.path.join(out, "fuzz", target)
        os.makedirs(scaling, exist_ok=True)
        os.makedirs(fuzzing, exist_ok=True)
        for family, make in families.items():
            for label, size in (("full", sizes[family]), ("quarter", sizes[family] // 4)):
                write(os.path.join(scaling, "%s.%s.%s" % (family, label, ext)), make(size))
            write(os.path.join(fuzzing, "%s.%s" % (family, ext)),
                  make(min(sizes[family], FUZZ_SIZE - 1024)))


if __name__ == "__main__":
    main()
