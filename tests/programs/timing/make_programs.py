#!/usr/bin/env python3
"""Writes the reference programs of tests/programs/timing/ (README.md says
how they were timed). Each starts at home in G21 G90 G94 G17 and ends with M2."""
import math
import os

HEAD = "G21 G90 G94 G17\nG0 X0 Y0 Z0\n"
TAIL = "M2\n"
progs = {}


def put(name, body):
    progs[name] = HEAD + body + TAIL


def square(mode, f=3000, side=100):
    return f"{mode}\nG1 X{side} F{f}\nG1 Y{side}\nG1 X0\nG1 Y0\n"


def curve(n, chord, radius, f, mode, digits=4):
    out = [f"{mode}\n"]
    step = 2 * math.asin(chord / (2 * radius))
    for i in range(1, n + 1):
        t = i * step
        out.append(f"G1 X{radius * math.sin(t):.{digits}f} Y{radius * (1 - math.cos(t)):.{digits}f}"
                   + (f" F{f}" if i == 1 else "") + "\n")
    return "".join(out)


def zigzag(mode, f=2400, n=8, dx=12.5, dy=20):
    out = [f"{mode}\n"]
    for i in range(1, n + 1):
        out.append(f"G1 X{i * dx:g} Y{dy if i % 2 else 0}" + (f" F{f}" if i == 1 else "") + "\n")
    return "".join(out)


def polygon(mode, sides, r, f):
    out = [f"{mode}\nG1 X{r} F{f}\n"]
    for i in range(1, sides + 1):
        t = 2 * math.pi * i / sides
        out.append(f"G1 X{r * math.cos(t):.4f} Y{r * math.sin(t):.4f}\n")
    return "".join(out)


def rounded_rect(mode, f=3000, w=60, h=30, r=8):
    return (f"{mode}\nG1 X{w - r} F{f}\nG3 X{w} Y{r} I0 J{r}\nG1 Y{h - r}\n"
            f"G3 X{w - r} Y{h} I-{r} J0\nG1 X{r}\nG3 X0 Y{h - r} I0 J-{r}\nG1 Y{r}\n"
            f"G3 X{r} Y0 I{r} J0\n")


put("a_line_rapid_g64", "G1 X100 F600\nG0 X0\n")
put("a_line_rapid_g61", "G61\nG1 X100 F600\nG0 X0\n")
put("b_square_g61_1", square("G61.1"))
put("b_square_g61", square("G61"))
put("b_square_g64", square("G64"))
put("b_square_g64_p0_1", square("G64 P0.1"))
put("c_circle_r20_f3000", "G2 X0 Y0 I20 J0 F3000\n")
put("c_circle_r20_g61", "G61\nG2 X0 Y0 I20 J0 F3000\n")
put("d_cam_1000x0_5_p0_01", curve(1000, 0.5, 500, 3000, "G64 P0.01"))
put("diagonal_g61", "G61\nG1 X100 Y100 F6000\nG0 X0 Y0\n")
put("rapids_g64", "G0 X50\nG0 Y30 Z-10\nG0 X-20 Y-40\nG0 X0 Y0 Z0\n")
put("feed_slow_f300", "G1 X10 F300\nG1 X10 Y10\nG1 X0 Y0\n")
put("feeds_several", "G61\nG1 X60 F1200\nG1 Y60 F2400\nG1 X0 F4800\nG1 Y0 F900\n")
put("zigzag_g64", zigzag("G64"))
put("zigzag_g64_p0_05", zigzag("G64 P0.05"))
put("zigzag_g61", zigzag("G61"))
put("zigzag_g61_1", zigzag("G61.1"))
put("helix_2turns", "G1 X10 F1200\nG3 X10 Y0 Z-6 I-10 J0 P2\nG0 Z0\n")
put("circle_r5_f1200", "G2 X0 Y0 I5 J0 F1200\n")
put("half_circle_r50_f3000", "G3 X100 Y0 I50 J0 F3000\n")
put("rounded_rect_g64", rounded_rect("G64"))
put("rounded_rect_g61", rounded_rect("G61"))
put("cam_600x0_5_plain_g64", curve(600, 0.5, 500, 3000, "G64"))
put("cam_300x1_r200_p0_02", curve(300, 1.0, 200, 2400, "G64 P0.02"))
put("cam_2000x0_05_p0_01", curve(2000, 0.05, 500, 1500, "G64 P0.01", 5))
put("drill_g81", "G0 Z5\nG98 G81 X10 Y10 Z-5 R1 F600\nX30\nY30\nX10\nG80\nG0 Z5\n")
put("peck_g83", "G0 Z5\nG98 G83 X15 Y5 Z-8 R1 Q2 F900\nX35\nG80\nG0 Z5\n")
put("octagon_g64_p0_5", polygon("G64 P0.5", 8, 40, 3000))
put("octagon_g64", polygon("G64", 8, 40, 3000))
put("polyline_2mm_g64", "".join(["G64\n"] + [f"G1 X{2 * i} Y{(i % 2) * 0.2:.1f}" + (" F1500" if i == 1 else "") + "\n" for i in range(1, 31)]))
put("diagonal_3d_g61", "G61\nG1 X40 Y30 Z-20 F2000\nG1 X0 Y0 Z0\n")
put("mixed_modes", "G61\nG1 X30 F2400\nG1 Y30\nG64\nG1 X0\nG1 Y0\n")
put("spiral_square_g64_p0_01", "G64 P0.01\n" + "".join(
    f"G1 X{s} F2400\nG1 Y{s}\nG1 X{-s + 5}\nG1 Y{-s + 5}\n" for s in (20, 15, 10)))
put("profile_ramp_g64", "G64\nG1 Z-2 F600\nG1 X40 Z-3 F1800\nG1 Y20\nG1 X0\nG1 Y0\nG0 Z5\n")
put("slot_arcs_g64_p0_02", "G64 P0.02\nG1 X40 F2000\nG3 X40 Y10 I0 J5\nG1 X0\nG3 X0 Y0 I0 J-5\n")

# Corners in the mode LinuxCNC starts in (no G61/G64 word) and in G64.
put("corner_10mm_f1200_startup", "G1 X10 F1200\nG1 X10 Y10\n")
put("corner_10mm_f300_startup", "G1 X10 F300\nG1 X10 Y10\n")
put("corner_40mm_f1200_startup", "G1 X40 F1200\nG1 X40 Y40\n")
put("corner_40mm_f1200_g64", "G64\nG1 X40 F1200\nG1 X40 Y40\n")
put("three_lines_f1200_startup", "G1 X10 F1200\nG1 X10 Y10\nG1 X0 Y10\n")
put("rapids_explicit_g64", "G64\nG0 X50\nG0 Y30 Z-10\nG0 X-20 Y-40\nG0 X0 Y0 Z0\n")

here = os.path.dirname(os.path.abspath(__file__))
for name, text in progs.items():
    with open(os.path.join(here, name + ".ngc"), "w") as f:
        f.write(text)
print(len(progs), "programs")
