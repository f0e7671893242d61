"""Work offsets (G54-G59.3, G10 L2/L20 with rotation, G92 and its cancels,
G52, the offset parameters), home positions (G28/G30 and their .1),
units, tools and tool length offsets, spindle, coolant, path modes and
comments."""
from .builder import AXES
from .expressions import word

SYSTEMS = [54, 55, 56, 57, 58, 59, 59.1, 59.2, 59.3]


def some_axes(b, lo=-30, hi=30, p=0.6):
    out = []
    for a in range(3):
        if b.chance(p):
            out.append(word(b, AXES[a], b.rnd_units(b.length(lo, hi) if a < 2 else b.length(-10, 10))))
    return out or [word(b, 'Z', b.rnd_units(b.length(-10, 10)))]


def select_system(b):
    s = b.pick(SYSTEMS)
    b.emit([b.g(s)])


def offsets(b):
    r = b.rnd.random()
    if r < 0.3:
        words = [b.g(10), 'L2', f'P{b.rnd.randint(0, 9)}'] + some_axes(b)
        if b.chance(0.3) and not b.g92_on:  # known_differences.tsv: g92-rotation
            words.append(b.word('R', round(b.uniform(-60, 60), 2), 2))
        b.emit(words)
        if b.chance(0.6):
            select_system(b)
    elif r < 0.45:
        b.emit([b.g(10), 'L20', f'P{b.rnd.randint(0, 9)}'] + some_axes(b))
        if b.chance(0.5):
            select_system(b)
    elif r < 0.55:
        select_system(b)
    elif r < 0.75:
        b.emit([b.g(92)] + some_axes(b))
        b.g92_on = True
        if b.chance(0.3):
            code = b.pick([92.1, 92.2, 92.3])
            b.emit([b.g(code)])
            b.g92_on = code == 92.3
    elif r < 0.85:
        b.emit([b.g(52)] + some_axes(b))
        b.g92_on = True
        if b.chance(0.3):
            b.emit([b.g(52), 'X0', 'Y0', 'Z0'])
            b.g92_on = False
    else:
        # The G5x offsets as parameters (#5221 X of G54, 20 apart), then the
        # system selected so they take effect.
        n = b.rnd.randint(1, 9)
        a = b.rnd.randint(0, 2)
        b.raw(f'#{5201 + 20 * n + a} = {b.num(b.rnd_units(b.length(-20, 20)))}')
        b.emit([b.g(SYSTEMS[n - 1])])
    b.pos = None


def home(b):
    """G28/G30, after storing a home position (G28.1/G30.1 or parameters) or not."""
    base = b.pick([28, 30])
    r = b.rnd.random()
    if r < 0.3:
        b.need_pos()
        b.emit([b.g(base + 0.1)])
    elif r < 0.45:
        first = 5161 if base == 28 else 5181
        for a in range(3):
            if b.chance(0.6):
                b.raw(f'#{first + a} = {b.num(b.rnd_units(b.length(-20, 20)))}')
    words = [b.g(base)]
    if b.chance(0.6):
        words += some_axes(b, -20, 20, 0.5)
    b.emit(words)
    b.pos = None
    b.motion = None


def units(b):
    u = 20 if b.units == 21 else 21
    if b.motion == 'cycle':  # known_differences.tsv: units-in-cycle
        b.emit([b.g(80)])
        b.motion = None
    if b.tlo:
        # rs274's stand-alone canon keeps a tool length offset in the unit it
        # was set in across G20/G21 (known_differences.tsv: tlo-units).
        b.emit([b.g(49)])
        b.tlo = False
    b.emit([b.g(u)])
    b.set_units(u)
    if b.chance(0.5):
        b.feed_ok = False  # say F again in the new unit, or test how the old one carries over


def tool(b):
    r = b.rnd.random()
    if r < 0.4:
        # Not T0: rs274's stand-alone canon keeps the last tool's data in the
        # spindle after T0 M6 (known_differences.tsv: t0-keeps-tool).
        t = b.rnd.randint(1, 13)
        # From a known point: rs274 reads the point back from its canon at a
        # tool change (known_differences.tsv: m6-rereads-canon).
        b.anchor()
        b.emit([f'T{t}', b.m(6)])
        b.tool = t
        b.spindle = 'off'  # LinuxCNC's tool change stops the spindle
        if b.chance(0.5):
            b.emit([b.g(43)])
            b.tlo = True
    elif r < 0.7:
        b.emit([b.g(43), f'H{b.rnd.randint(0, 13)}'])
        b.tlo = True
    elif r < 0.85:
        b.emit([b.g(43.1), b.word('Z', b.rnd_units(b.length(-5, 5)))])
        b.tlo = True
    else:
        b.emit([b.g(49)])
        b.tlo = False
    b.pos = None  # the tool tip's program coordinates moved


def spindle(b):
    r = b.rnd.random()
    if r < 0.6:
        b.speed = float(b.rnd.randint(0, 5) * 500)
        d = b.pick(['cw', 'ccw', 'off'])
        b.emit([b.word('S', b.speed), b.m({'cw': 3, 'ccw': 4, 'off': 5}[d])])
        b.spindle = d
    elif r < 0.8:
        b.emit([b.m(b.pick([7, 8, 9]))])
    else:
        mode = b.pick([61, 61.1, 64])
        b.emit([b.g(mode)] + ([b.word('P', 0.01)] if mode == 64 and b.chance(0.5) else []))


def comment(b):
    r = b.rnd.random()
    if r < 0.4:
        b.raw(f'(MSG, step {len(b.lines)})')
    elif r < 0.7:
        known = [k for k, v in b.params.items() if v is not None]
        b.raw(f'(DEBUG, value {known[0]})' if known else '(DEBUG, nothing)')
    else:
        b.raw(f'; comment {len(b.lines)}')
