"""The program builder: what the generator knows of the machine's state while
it writes a program, the numbers it writes, and the blocks.

The generator only writes programs it believes valid. It tracks the modal
state and, where it can, the current point in program coordinates
(`pos`, program units): an arc in G90 or a cutter compensation path needs
it. Where the point is not known (after offsets change, a home move, a
cycle), a segment that needs it first writes an anchor, `G90 G0 X Y Z`,
after which the point is known in whatever frame is active."""
import random

# In-plane axes (first, second) and the axis on the plane's normal, as
# indices of X Y Z, for G17 G18 G19 (G18's plane is ZX: Z first).
PLANES = {17: ((0, 1), 2), 18: ((2, 0), 1), 19: ((1, 2), 0)}
AXES = 'XYZ'
CENTRE = 'IJK'  # the centre (and G87 offset) word of each axis


class Builder:
    def __init__(self, seed, scale=1.0):
        self.seed = seed
        self.rnd = random.Random(seed)
        self.lines = []
        self.scale = scale  # how big the part is, 1.0 = about 100 mm
        self.units = 21
        self.plane = 17
        self.dist = 90
        self.pos = None  # program units; None: unknown
        self.feed_ok = False
        self.spindle = 'off'
        self.speed = 0.0
        self.motion = None  # 'G0', 'G1', 'cycle', ... (None: G80)
        self.retract = 99
        self.tool = 0  # the tool in the spindle (M6)
        self.tlo = False  # a tool length offset may be in effect (G43, G43.1)
        self.g92_on = False  # a G92/G52 offset may be in effect
        self.inverse_time = False
        self.params = {}  # parameter -> value the generator knows
        self.next_o = 100
        self.next_param = 100
        self.subs = []  # (name, nargs, displacement function) usable in calls
        self.depth = 0  # nesting of loops/conditionals being written
        # How this program writes its words (chosen once so a minimised
        # program still reads like the original).
        r = self.rnd
        self.style = {
            'lower': r.random() < 0.15,
            'nospace': r.random() < 0.1,
            'zeros': r.random() < 0.2,  # G01, G00, M03
            'numbers': r.random() < 0.15,  # N words
        }
        self.n = 0
        self.pending = {}  # state a block changes, applied once its words are written

    def later(self, **changes):
        """State the block being written changes: its own words still read the
        old state (RS274NGC reads every word before the block takes effect)."""
        self.pending.update(changes)

    # ---- random numbers -------------------------------------------------
    def chance(self, p):
        return self.rnd.random() < p

    def pick(self, seq, weights=None):
        if weights is None:
            return self.rnd.choice(seq)
        return self.rnd.choices(seq, weights=weights)[0]

    def uniform(self, lo, hi):
        return self.rnd.uniform(lo, hi)

    def mm(self, v):
        """A length in mm, in program units."""
        return v if self.units == 21 else v / 25.4

    def length(self, lo, hi):
        """A random length between lo and hi mm (times the part's scale), in program units."""
        return self.mm(self.uniform(lo, hi) * self.scale)

    def decimals(self):
        return 4 if self.units == 21 else 5

    def rnd_units(self, v):
        """v rounded as the program writes it."""
        return round(v, self.decimals())

    # ---- text -------------------------------------------------------------
    def num(self, v, decimals=None):
        d = self.decimals() if decimals is None else decimals
        s = f'{v:.{d}f}'
        if '.' in s:
            s = s.rstrip('0').rstrip('.')
        if s in ('-0', ''):
            s = '0'
        if self.style['zeros'] and '.' not in s and self.chance(0.3):
            s += '.0'
        return s

    def code(self, letter, value):
        """A G or M code as this program writes it (G1, G01, g1)."""
        text = str(value)
        if self.style['zeros'] and isinstance(value, int) and value < 10:
            text = '0' + text
        return letter + text

    def emit(self, words, comment=None):
        """An ordinary block: a list of words ('G1', 'X1.5', 'X[#1+2]')."""
        words = [w for w in words if w]
        text = ('' if self.style['nospace'] else ' ').join(words)
        if self.style['lower']:
            text = lower_words(text)
        if self.style['numbers'] and self.depth == 0:
            self.n += 10
            text = f'N{self.n} {text}'
        if comment:
            text += f' ({comment})'
        self.lines.append(text)
        for k, v in self.pending.items():
            setattr(self, k, v)
        self.pending = {}

    def raw(self, text):
        """A line written as is (O-words, parameter assignments, comments)."""
        self.lines.append(text)

    def word(self, letter, v, decimals=None):
        return letter + self.num(v, decimals)

    def g(self, value):
        if isinstance(value, float):
            return 'G' + self.num(value, 1)
        return self.code('G', value)

    def m(self, value):
        return self.code('M', value)

    # ---- state helpers -------------------------------------------------
    def anchor(self, z=None):
        """Make the current point known: G90 G0 to a point of the part."""
        p = [self.rnd_units(self.length(-40, 40)), self.rnd_units(self.length(-40, 40)),
             self.rnd_units(self.length(0, 20) if z is None else z)]
        if z is not None:
            p[2] = self.rnd_units(z)
        self.emit([self.g(90) if self.dist != 90 or self.chance(0.3) else '', self.g(0),
                   self.word('X', p[0]), self.word('Y', p[1]), self.word('Z', p[2])])
        self.dist = 90
        self.pos = p
        self.motion = 'G0'
        return p

    def need_pos(self):
        if self.pos is None:
            self.anchor()
        return self.pos

    def need_feed(self, words):
        """Adds F to a feed block's words when no feed rate is set yet."""
        if not self.feed_ok or self.inverse_time or self.chance(0.1):
            words.append(self.word('F', self.feed_value()))
            self.feed_ok = True

    def feed_value(self):
        if self.inverse_time:
            return round(self.uniform(0.5, 20), 2)
        return round(self.mm(self.uniform(50, 2000)), 2 if self.units == 21 else 3)

    def motion_word(self, g):
        """The motion code of a block: left out when the mode is already g (modal)."""
        if self.motion == g and self.chance(0.5):
            return ''
        self.motion = g
        return self.g(int(g[1:]) if '.' not in g else float(g[1:]))

    def set_units(self, units):
        if units == self.units:
            return
        k = 25.4 if units == 21 else 1 / 25.4
        if self.pos is not None:
            self.pos = [v * k for v in self.pos]
        self.units = units

    def fresh_param(self):
        self.next_param += 1
        return self.next_param

    def fresh_o(self):
        self.next_o += 1
        return self.next_o

    def text(self):
        return '\n'.join(self.lines) + '\n'


def lower_words(text):
    """Lower-case letters outside comments."""
    out, depth = [], 0
    for ch in text:
        if ch == '(':
            depth += 1
        elif ch == ')':
            depth = max(0, depth - 1)
        out.append(ch.lower() if depth == 0 else ch)
    return ''.join(out)
