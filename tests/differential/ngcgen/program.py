"""A whole program from a seed: a start-up, segments of every kind chosen at
random, the subroutines they call defined at the top, and an end."""
from . import compensation, cycles, flow, motion, setup
from .builder import Builder

# Segment kinds and how often they come (weights); `needs` a condition.
SEGMENTS = [
    ('straight', motion.straight, 6),
    ('arc', motion.arc, 5),
    ('plane', motion.plane, 1),
    ('feed_mode', motion.feed_mode, 1),
    ('dwell', motion.dwell, 0.5),
    ('probe', motion.probe, 0.7),
    ('cycle', cycles.cycle, 5),
    ('compensation', compensation.compensation, 3),
    ('offsets', setup.offsets, 2.5),
    ('home', setup.home, 1),
    ('units', setup.units, 1),
    ('tool', setup.tool, 1),
    ('spindle', setup.spindle, 1),
    ('comment', setup.comment, 0.5),
    ('assign', flow.assign, 2),
    ('call', flow.call, 2),
    ('loop', flow.loop, 1.5),
    ('conditional', None, 1),
]


def segment(b, allowed=None):
    names = [s for s in SEGMENTS if allowed is None or s[0] in allowed]
    if b.depth >= 2:
        names = [s for s in names if s[0] not in ('conditional',)]
    name, fn, _ = b.pick(names, [s[2] for s in names])
    if name == 'conditional':
        flow.conditional(b, lambda bb: segment(bb, allowed))
    else:
        fn(b)
    return name


def start(b):
    """The start-up block(s): units always (the trace's units must be known), the rest sometimes."""
    b.units = b.pick([20, 21], [1, 2])
    words = [b.g(b.units)]
    if b.chance(0.7):
        words += [b.g(17), b.g(90)]
    if b.chance(0.4):
        words += [b.g(94), b.g(40), b.g(49), b.g(80)]
    if b.chance(0.3):
        words.append(b.g(b.pick([54, 55])))
    if b.chance(0.8):
        words.append(b.word('F', b.feed_value()))
        b.feed_ok = True
    b.emit(words)
    if b.chance(0.4):
        t = b.rnd.randint(1, 13)
        b.emit([f'T{t}', b.m(6)])
        b.tool = t  # before the spindle starts: M6 stops it
    if b.chance(0.5):
        b.speed = float(b.rnd.randint(1, 20) * 100)
        b.spindle = b.pick(['cw', 'ccw'])
        b.emit([b.word('S', b.speed), b.m(3 if b.spindle == 'cw' else 4)])
    if b.chance(0.7):
        b.anchor()


def generate(seed, size=None, only=None):
    """The program of `seed` (text). `only` limits the segment kinds (a set of names)."""
    b = Builder(seed)
    b.subs_text = []
    b.raw(f'(usina differential fuzz, seed {seed})')
    start(b)
    for _ in range(size or b.rnd.randint(6, 24)):
        segment(b, only)
    b.raw(b.pick(['M2', 'M30', 'M2']))
    body = b.lines
    lines = [body[0]] + b.subs_text + body[1:]
    if b.chance(0.1):
        lines = ['%'] + lines + ['%']
    return '\n'.join(lines) + '\n'
