"""Straight moves, arcs (R and IJK, every plane, helices, turns), feed modes,
dwells and probing."""
import math

from .builder import AXES, CENTRE, PLANES
from .expressions import word


def straight(b, n=None):
    """G0/G1 blocks, absolute or incremental, some axes each."""
    for _ in range(n or b.rnd.randint(1, 4)):
        g = b.pick(['G0', 'G1'], [1, 2])
        incremental = b.pos is None or b.chance(0.35)
        words = []
        if incremental and b.dist != 91:
            words.append(b.g(91))
            b.later(dist=91)
        elif not incremental and b.dist != 90:
            words.append(b.g(90))
            b.later(dist=90)
        words.append(b.motion_word(g))
        axes = [a for a in range(3) if b.chance(0.6)] or [b.rnd.randint(0, 2)]
        for a in axes:
            if incremental:
                d = b.rnd_units(b.length(-20, 20))
                if b.pos is not None:
                    b.pos[a] += d
                words.append(word(b, AXES[a], d))
            else:
                v = b.rnd_units(b.length(-40, 40) if a < 2 else b.length(-10, 15))
                b.pos[a] = v
                words.append(word(b, AXES[a], v))
        if g == 'G1':
            b.need_feed(words)
        b.emit(words)


def arc_words(b, start, centre_off, end, axial, plane, incremental, by_radius, radius):
    """The words of an arc from `start` (program units) with centre start + centre_off."""
    (i1, i2), n = PLANES[plane]
    words = []
    for k, a in enumerate((i1, i2)):
        v = end[k] - start[k] if incremental else end[k]
        words.append(word(b, AXES[a], b.rnd_units(v), 0.15))
    if axial is not None:
        words.append(word(b, AXES[n], b.rnd_units(axial), 0.15))
    if by_radius:
        words.append(word(b, 'R', radius, 0.15))
    else:
        for k, a in enumerate((i1, i2)):
            words.append(word(b, CENTRE[a], centre_off[k], 0.15))
    return words


def arc(b):
    """G2/G3 in the current plane: by IJK (any end on the circle) or by R
    (any end within the diameter), a helix sometimes, extra turns P sometimes."""
    incremental = b.pos is None or b.chance(0.3)
    start3 = [0.0, 0.0, 0.0] if b.pos is None else b.pos
    (i1, i2), n = PLANES[b.plane]
    s = (start3[i1], start3[i2])
    by_radius = b.chance(0.4)
    r = b.rnd_units(b.length(1, 30))
    words = []
    if incremental and b.dist != 91:
        words.append(b.g(91))
        b.later(dist=91)
    elif not incremental and b.dist != 90:
        words.append(b.g(90))
        b.later(dist=90)
    g = b.pick(['G2', 'G3'])
    words.append(b.motion_word(g))
    if by_radius:
        chord = b.uniform(0.05, 1.9) * r
        phi = b.uniform(0, 2 * math.pi)
        end = (b.rnd_units(s[0] + chord * math.cos(phi)), b.rnd_units(s[1] + chord * math.sin(phi)))
        off = None
        radius = r if b.chance(0.5) else -r
    else:
        theta = b.uniform(0, 2 * math.pi)
        off = (b.rnd_units(-r * math.cos(theta)), b.rnd_units(-r * math.sin(theta)))
        c = (s[0] + off[0], s[1] + off[1])
        rr = math.hypot(*off)
        if b.chance(0.1):
            end = s  # a full circle
        else:
            t = b.uniform(0, 2 * math.pi)
            end = (b.rnd_units(c[0] + rr * math.cos(t)), b.rnd_units(c[1] + rr * math.sin(t)))
            if incremental:  # the increments are what is written: round them
                end = (s[0] + b.rnd_units(end[0] - s[0]), s[1] + b.rnd_units(end[1] - s[1]))
        radius = None
    axial = None
    if b.chance(0.3):
        d = b.rnd_units(b.length(-10, 10))
        axial = d if incremental else b.rnd_units(start3[n] + d)
    words += arc_words(b, s, off, end, axial, b.plane, incremental, by_radius, radius)
    if b.chance(0.1) and not by_radius:
        words.append(f'P{b.rnd.randint(1, 3)}')
    b.need_feed(words)
    b.emit(words)
    if b.pos is not None:
        b.pos[i1], b.pos[i2] = end
        if axial is not None:
            b.pos[n] = b.pos[n] + axial if incremental else axial


def plane(b):
    p = b.pick([17, 18, 19], [3, 1, 1])
    b.emit([b.g(p)])
    b.plane = p


def feed_mode(b):
    """A few moves in inverse time (G93, F on every block) or per revolution (G95)."""
    if b.chance(0.5):
        b.emit([b.g(93)])
        b.inverse_time = True
        for _ in range(b.rnd.randint(1, 3)):
            arc(b) if b.chance(0.4) else straight(b, 1)
        b.inverse_time = False
        b.emit([b.g(94), b.word('F', b.feed_value())])
        b.feed_ok = True
        return
    words = [b.g(95), b.word('F', b.rnd_units(b.mm(b.uniform(0.02, 0.5))))]
    if b.speed == 0:
        words.append(b.word('S', 1000))
        b.speed = 1000
    b.emit(words)
    b.feed_ok = True
    for _ in range(b.rnd.randint(1, 3)):
        arc(b) if b.chance(0.4) else straight(b, 1)
    b.emit([b.g(94), b.word('F', b.feed_value())])


def dwell(b):
    b.emit([b.g(4), b.word('P', round(b.uniform(0, 2), 3), 3)])


def probe(b):
    """G38.2/G38.3 towards a point; the stand-alone interpreter simulates it."""
    p = b.need_pos()
    code = b.pick([38.2, 38.3, 38.4, 38.5])
    target = list(p)
    axes = [a for a in range(3) if b.chance(0.5)] or [2]
    for a in axes:
        target[a] = b.rnd_units(p[a] + b.length(-15, 15))
    if target == p:
        target[2] = b.rnd_units(p[2] - b.mm(5))
    words = [b.g(90) if b.dist != 90 else '', b.g(code)]
    b.later(dist=90)
    words += [b.word(AXES[a], target[a]) for a in range(3) if target[a] != p[a]]
    b.need_feed(words)
    b.emit(words)
    b.pos = None  # the stand-alone interpreter stops short of the target
    b.motion = None
