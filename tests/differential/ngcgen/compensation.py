"""Cutter radius compensation (G41/G42/G41.1/G42.1, G40) in the XY plane:
an entry move, a path of lines and arcs with convex and concave corners,
tangent joins and Z moves, and an exit. Lengths and radii are kept well
above the tool's radius so LinuxCNC can compute every corner."""
import math

from .expressions import word

# Tool diameters of shared/conformance/rs274ngc/tools/generic.tbl (inches).
TOOL_DIAMETERS = {1: 0.125, 2: 0.0625, 3: 0.201, 4: 0.005, 5: 0.25, 6: 0.375, 7: 0.5,
                  8: 0.1875, 9: 0.0625, 10: 0.125, 11: 0.25, 12: 0.375, 13: 0.5}


def choose_tool(b):
    """The words that turn compensation on, and the tool radius in program units."""
    side = b.pick([41, 42])
    r = b.rnd.random()
    if r < 0.6:
        t = b.pick(list(TOOL_DIAMETERS))
        return [b.g(side), f'D{t}'], b.mm(TOOL_DIAMETERS[t] * 25.4 / 2)
    if r < 0.85:
        d = b.rnd_units(b.length(1, 10))
        return [b.g(side + 0.1), b.word('D', d)], d / 2
    # The tool in the spindle (M6 loaded it; none: radius 0).
    d = TOOL_DIAMETERS.get(b.tool, 0.0)
    return [b.g(side)], b.mm(d * 25.4 / 2)


def heading_move(b, p, heading, length):
    return [b.rnd_units(p[0] + length * math.cos(heading)),
            b.rnd_units(p[1] + length * math.sin(heading))]


def line_words(b, p, q, incremental):
    out = []
    for k, letter in enumerate('XY'):
        v = q[k] - p[k] if incremental else q[k]
        if abs(q[k] - p[k]) > 1e-9 or b.chance(0.3):
            out.append(word(b, letter, b.rnd_units(v), 0.15))
    return out or [word(b, 'X', b.rnd_units(q[0] - p[0] if incremental else q[0]))]


def comp_arc(b, p, heading, rad, incremental):
    """An arc of radius > 2 tool radii, tangent to the heading or turned; returns words, end, heading."""
    heading += math.radians(b.pick([0, 0, b.uniform(-120, 120)]))
    ccw = b.chance(0.5)
    ra = b.rnd_units(max(rad * b.uniform(3, 8), b.mm(2)))
    side = 1 if ccw else -1
    centre = (p[0] + ra * math.cos(heading + side * math.pi / 2),
              p[1] + ra * math.sin(heading + side * math.pi / 2))
    off = (b.rnd_units(centre[0] - p[0]), b.rnd_units(centre[1] - p[1]))
    centre = (p[0] + off[0], p[1] + off[1])
    rr = math.hypot(*off)
    sweep = max(math.radians(b.uniform(20, 260)), 3 * rad / ra) * side  # at least 3 radii long
    a0 = math.atan2(p[1] - centre[1], p[0] - centre[0])
    q = [b.rnd_units(centre[0] + rr * math.cos(a0 + sweep)),
         b.rnd_units(centre[1] + rr * math.sin(a0 + sweep))]
    words = [b.motion_word('G3' if ccw else 'G2')] + line_words(b, p, q, incremental)
    if abs(math.degrees(sweep)) < 170 and b.chance(0.4):
        words.append(b.word('R', rr))
    else:
        words += [word(b, 'I', off[0], 0.1), word(b, 'J', off[1], 0.1)]
    return words, q, heading + sweep


def path(b, p, rad, heading):
    """Moves of a compensated path from p; returns the end and heading."""
    for _ in range(b.rnd.randint(1, 6)):
        incremental = b.chance(0.2)
        dm = [b.g(91 if incremental else 90)] if (b.dist == 91) != incremental else []
        b.later(dist=91 if incremental else 90)
        if b.chance(0.1):  # a Z move inside compensation
            dz = b.rnd_units(b.length(-3, 3))
            b.pos[2] += dz
            words = [b.motion_word('G1'), word(b, 'Z', dz if incremental else b.pos[2])]
            b.need_feed(words)
            b.emit(dm + words)
            continue
        if b.chance(0.35):
            words, q, heading = comp_arc(b, p, heading, rad, incremental)
        else:
            heading += math.radians(b.pick([0, b.uniform(-120, 120), b.uniform(-150, 150)]))
            q = heading_move(b, p, heading, max(rad * b.uniform(4, 12), b.mm(3)))
            words = [b.motion_word('G1')] + line_words(b, p, q, incremental)
        b.need_feed(words)
        b.emit(dm + words)
        p = q
        b.pos[0], b.pos[1] = q
    return p, heading


def compensation(b):
    if b.plane != 17:
        b.emit([b.g(17)])
        b.plane = 17
    p = b.anchor()
    on, rad = choose_tool(b)
    heading = b.uniform(0, 2 * math.pi)
    q = heading_move(b, p, heading, max(rad * b.uniform(3, 10), b.mm(3)))
    g = b.pick(['G1', 'G0'], [3, 1])
    b.motion = None
    words = on + [b.motion_word(g)] + line_words(b, p, q, False)
    if g == 'G1':
        b.need_feed(words)
    b.emit(words)
    b.pos[0], b.pos[1] = q
    q, heading = path(b, q, rad, heading)
    # Exit: G40 with a move away, or G40 alone and then a move.
    heading += math.radians(b.uniform(-120, 120))
    e = heading_move(b, q, heading, max(rad * b.uniform(3, 10), b.mm(3)))
    if b.dist != 90:
        b.emit([b.g(90)])
        b.dist = 90
    alone = b.chance(0.3)
    if alone:
        b.emit([b.g(40)])
    words = [b.motion_word(b.pick(['G1', 'G0']))] + line_words(b, q, e, False)
    if b.motion == 'G1':
        b.need_feed(words)
    b.emit(words if alone else [b.g(40)] + words)
    b.pos[0], b.pos[1] = e
