"""Random RS274NGC expressions whose value the generator knows.

An expression is built as a tree, its value computed as LinuxCNC computes it
(degrees for trigonometry, left to right within a precedence level, EQ/NE
within 0.0001), and written with the fewest brackets its precedence needs,
sometimes more. Every operation is kept inside its domain (no division by
zero, no square root of a negative, ...), so the program stays valid."""
import math

# LinuxCNC's precedence levels (interp_read.cc precedence()).
PREC = {'AND': 2, 'OR': 2, 'XOR': 2, 'EQ': 3, 'NE': 3, 'GT': 3, 'GE': 3, 'LT': 3, 'LE': 3,
        '+': 4, '-': 4, '*': 5, '/': 5, 'MOD': 5, '**': 6}
ATOM = 10


class Expr:
    def __init__(self, text, value, prec=ATOM, fragile=False):
        self.text, self.value, self.prec = text, value, prec
        # The value comes from a library function (sin, exp, ...): LinuxCNC
        # may get it a few ulps apart (it converts angles in long double).
        self.fragile = fragile

    def bracketed(self):
        return self.text if self.prec == ATOM else f'[{self.text}]'


def binary(op, a, b):
    if op == '+':
        return a + b
    if op == '-':
        return a - b
    if op == '*':
        return a * b
    if op == '/':
        return a / b
    if op == 'MOD':
        r = math.fmod(a, b)
        return r + abs(b) if r < 0 else r
    if op == '**':
        return a ** b
    if op == 'EQ':
        return float(abs(a - b) < 1e-4)
    if op == 'NE':
        return float(abs(a - b) >= 1e-4)
    if op == 'GT':
        return float(a > b)
    if op == 'GE':
        return float(a >= b)
    if op == 'LT':
        return float(a < b)
    if op == 'LE':
        return float(a <= b)
    if op == 'AND':
        return float(a != 0 and b != 0)
    if op == 'OR':
        return float(a != 0 or b != 0)
    if op == 'XOR':
        return float((a != 0) != (b != 0))
    raise ValueError(op)


def combine(b, op, left, right):
    """left op right, bracketing an operand only where precedence needs it
    (left-associative: the right operand of an equal level is bracketed)."""
    p = PREC[op]
    lt = left.text if left.prec >= p and not (b.chance(0.15)) else f'[{left.text}]'
    if left.prec == ATOM:
        lt = left.text
    rt = right.text if right.prec > p and not (b.chance(0.15)) else f'[{right.text}]'
    if right.prec == ATOM:
        rt = right.text
    sep = ' ' if b.chance(0.7) or op.isalpha() else ''
    return Expr(f'{lt}{sep}{op}{sep}{rt}', binary(op, left.value, right.value), p,
                left.fragile or right.fragile)


def literal(b, lo=-10.0, hi=10.0):
    if b.chance(0.4):
        v = float(b.rnd.randint(int(lo), int(hi)))
        return Expr(b.num(v, 0), v)
    v = round(b.uniform(lo, hi), 3)
    return Expr(b.num(v, 3), v)


def predefined(b):
    """A predefined named parameter whose value the state tells."""
    choices = [('#<_metric>', 1.0 if b.units == 21 else 0.0),
               ('#<_imperial>', 1.0 if b.units == 20 else 0.0),
               ('#<_absolute>', 1.0 if b.dist == 90 else 0.0),
               ('#<_incremental>', 1.0 if b.dist == 91 else 0.0),
               ('#<_plane>', {17: 170.0, 18: 180.0, 19: 190.0}[b.plane])]
    text, v = b.pick(choices)
    return Expr(text, v)


def leaf(b):
    known = [k for k, v in b.params.items() if v is not None and abs(v) < 1e4]
    r = b.rnd.random()
    if known and r < 0.4:
        k = b.pick(known)
        return Expr(k, b.params[k])
    if r < 0.47:
        return predefined(b)
    return literal(b)


def near_integer(v, tol=1e-9):
    return abs(v - round(v)) < tol


def function(b, x):
    """A function of x kept inside its domain (and away from its edges when
    x may be a few ulps off LinuxCNC's value)."""
    v = x.value
    edge = 1e-9 if x.fragile else 0.0
    fns = ['ABS', 'SIN', 'COS']
    if not (x.fragile and near_integer(v)):
        fns += ['FIX', 'FUP']
    if not (x.fragile and near_integer(v + 0.5)):
        fns.append('ROUND')
    if abs(v) <= 1 - edge:
        fns += ['ASIN', 'ACOS']
    if v >= edge:
        fns.append('SQRT')
    if v > edge:
        fns.append('LN')
    if abs(v) < 5:
        fns.append('EXP')
    if abs(math.cos(math.radians(v))) > 0.2:
        fns.append('TAN')
    if abs(abs(v - math.floor(v)) - 0.5) < 1e-3:
        fns = [f for f in fns if f != 'ROUND']  # halves: LinuxCNC's (int)(x + 0.5)
    f = b.pick(fns)
    d = math.radians
    val = {'ABS': lambda: abs(v), 'SIN': lambda: math.sin(d(v)), 'COS': lambda: math.cos(d(v)),
           'TAN': lambda: math.tan(d(v)), 'ASIN': lambda: math.degrees(math.asin(v)),
           'ACOS': lambda: math.degrees(math.acos(v)), 'SQRT': lambda: math.sqrt(v),
           'LN': lambda: math.log(v), 'EXP': lambda: math.exp(v),
           'FIX': lambda: float(math.floor(v)), 'FUP': lambda: float(math.ceil(v)),
           'ROUND': lambda: float(math.floor(abs(v) + 0.5) * (1 if v >= 0 else -1))}[f]()
    if f in ('SIN', 'COS', 'TAN') and abs(val * 2 - round(val * 2)) < 1e-12:
        val = round(val * 2) / 2  # exact in LinuxCNC's long double (SIN[30] = 0.5)
    name = f.lower() if b.chance(0.2) else f
    fragile = x.fragile or f not in ('ABS', 'FIX', 'FUP', 'ROUND')
    return Expr(f'{name}[{x.text}]', val, fragile=fragile)


def expression(b, depth=2):
    """A random expression with a known, finite, moderate value."""
    if depth <= 0 or b.chance(0.3):
        e = leaf(b)
        if b.chance(0.15):
            e = function(b, e)
        return e
    r = b.rnd.random()
    if r < 0.12:
        return function(b, expression(b, depth - 1))
    if r < 0.18:
        y, x = expression(b, depth - 1), expression(b, depth - 1)
        if x.value == 0 and y.value == 0:
            x = Expr('1', 1.0)
        v = math.degrees(math.atan2(y.value, x.value))
        return Expr(f'ATAN[{y.text}]/[{x.text}]', v, fragile=True)
    if r < 0.22:
        e = expression(b, depth - 1)
        return Expr(f'-{e.bracketed()}', -e.value, fragile=e.fragile)
    left, right = expression(b, depth - 1), expression(b, depth - 1)
    op = b.pick(['+', '-', '*', '/', 'MOD', '**', 'EQ', 'NE', 'GT', 'GE', 'LT', 'LE', 'AND',
                 'OR', 'XOR'], [6, 6, 5, 4, 2, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1])
    if op in ('/', 'MOD') and (abs(right.value) < 0.01 or '#<_' in right.text):
        right = Expr('3', 3.0)  # a modal value the generator may misjudge: not as a divisor
    if op == 'MOD' and (right.fragile or left.fragile):
        op = '+'  # a remainder near 0 or near the divisor flips on an ulp
    if op in ('GT', 'GE', 'LT', 'LE') and (right.fragile or left.fragile) and \
            abs(left.value - right.value) < 1e-9:
        op = '+'  # so does a comparison of (nearly) equal values
    if op == '**':
        if left.value <= 0 or left.value > 50:
            left = Expr('2', 2.0)
        right = Expr(str(b.rnd.randint(0, 3)), None)
        right.value = float(right.text)
    if op in ('GE', 'LE', 'EQ', 'NE') and 0 < abs(left.value - right.value) < 2e-4:
        op = '+'  # 2.9 and 2.10 differ there (known_differences.tsv: ge-le-tolerance)
    if op in ('EQ', 'NE') and b.chance(0.5):
        right = Expr(left.text, left.value, left.prec, left.fragile)  # equal on purpose
    e = combine(b, op, left, right)
    if not math.isfinite(e.value) or abs(e.value) > 1e6:
        return literal(b)
    return e


def equal_to(b, target, depth=2):
    """An expression worth `target` (within the program's rounding): a random
    expression plus the rounded difference."""
    e = expression(b, depth)
    if b.chance(0.3) and abs(e.value) > 0.1:
        k = round(target / e.value, 4) if abs(target) > 1e-9 else 0.0
        e = combine(b, '*', Expr(b.num(k, 4), k), e) if k != 0 else Expr('0', 0.0)
    c = round(target - e.value, b.decimals() + 1)
    op = '+' if c >= 0 else '-'
    return combine(b, op, e, Expr(b.num(abs(c), b.decimals() + 1), abs(c)))


def word(b, letter, value, p=0.25):
    """A word worth `value`: a number, or sometimes an expression."""
    if b.chance(p):
        e = equal_to(b, value)
        if len(e.text) <= 40:  # rs274 reads lines of 255 characters at most
            return f'{letter}[{e.text}]'
    return b.word(letter, value)
