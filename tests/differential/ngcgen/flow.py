"""Parameters (numbered, named, global, local; several on one line, read
before any is written), O-word subroutines (arguments, local and global
names, return values, recursion, M70/M72/M73), loops (repeat, while, do,
break, continue) and conditionals (if/elseif/else)."""
import math

from .expressions import Expr, equal_to, expression

SNAPSHOT = ('units', 'plane', 'dist', 'pos', 'feed_ok', 'spindle', 'speed', 'motion', 'retract',
            'tool', 'tlo', 'g92_on', 'params')


def snapshot(b):
    s = {k: getattr(b, k) for k in SNAPSHOT}
    s['pos'] = None if b.pos is None else list(b.pos)
    s['params'] = dict(b.params)
    return s


def restore(b, s):
    for k in SNAPSHOT:
        v = s[k]
        setattr(b, k, list(v) if isinstance(v, list) else dict(v) if isinstance(v, dict) else v)


def param_name(b, local_ok=True):
    r = b.rnd.random()
    if r < 0.45:
        return f'#{b.fresh_param()}'
    if r < 0.75 or not local_ok:
        return f'#<_gf{b.fresh_param()}>'
    return f'#<lf{b.fresh_param()}>'


def assign(b):
    """One to three assignments on a line; each reads the values before the line."""
    parts, new = [], {}
    for _ in range(b.pick([1, 1, 2, 3])):
        e = expression(b, b.pick([0, 1, 2, 3]))
        if len(e.text) > 60:  # rs274 reads lines of 255 characters at most
            e = Expr(b.num(round(e.value, 3), 3), round(e.value, 3))
        name = b.pick(list(b.params)) if b.params and b.chance(0.3) else param_name(b)
        parts.append(f'{name} = {e.text if e.prec == 10 and b.chance(0.5) else "[" + e.text + "]"}')
        new[name] = e.value
    b.params.update(new)
    b.raw(' '.join(parts))


# ---- subroutines ---------------------------------------------------------

def define_moves_sub(b):
    """A subroutine of incremental moves in its arguments #1 #2; returns (label,
    nargs, displacement(args) -> (dx, dy, dz), keeps_modes)."""
    label = f'o<s{b.fresh_o()}>' if b.chance(0.5) else f'o{b.fresh_o()}'
    save = b.pick(['', 'M70', 'M73'], [2, 1, 1])
    body, steps = [], []
    if save:
        body.append(save)
    body.append('G17 G91')
    if b.chance(0.4):
        body.append('#<lk> = [#1 * 2]')
        steps.append(('line', lambda a: (2 * a[0], 0.0, 0.0), 'G1 X#<lk>'))
    if b.chance(0.5):
        steps.append(('line', lambda a: (a[0], a[1], 0.0), 'G1 X#1 Y#2'))
    if b.chance(0.5):
        steps.append(('arc', lambda a: (2 * a[0], 0.0, 0.0), f'G{b.pick([2, 3])} X[#1 * 2] Y0 I#1 J0'))
    if b.chance(0.3):
        steps.append(('line', lambda a: (0.0, 0.0, -a[1] / 4), 'G0 Z[#2 / -4]'))
    if not steps or b.chance(0.3):
        steps.append(('line', lambda a: (0.0, -a[1], 0.0), 'G1 Y[0 - #2]'))
    if b.chance(0.3):  # an early return never taken
        o = f'o{b.fresh_o()}'
        body += [f'{o} if [#1 LT -1000]', f'  {label} return', f'{o} endif']
    body += [text for _, _, text in steps]
    if save == 'M70':
        body.append('M72')
    elif not save:
        body.append('G90')
    if b.chance(0.3):
        body.append('#<_gsub_out> = [#1 + #2]')
    b.subs_text += [f'{label} sub'] + ['  ' + t for t in body] + [f'{label} endsub']

    def displacement(a):
        d = [0.0, 0.0, 0.0]
        for _, f, _ in steps:
            for k, v in enumerate(f(a)):
                d[k] += v
        return d
    sub = {'label': label, 'kind': 'moves', 'disp': displacement, 'keeps': bool(save),
           'gout': any('_gsub_out' in t for t in body)}
    b.subs.append(sub)
    return sub


def define_value_sub(b):
    label = f'o<v{b.fresh_o()}>'
    k = round(b.uniform(-3, 3), 2)
    b.subs_text += [f'{label} sub', f'  #<t> = [#1 * {b.num(k, 2)}]',
                    f'  {label} return [#<t> + #2]', f'{label} endsub']
    sub = {'label': label, 'kind': 'value', 'f': lambda a: a[0] * k + a[1]}
    b.subs.append(sub)
    return sub


def define_recursive_sub(b):
    label = f'o<r{b.fresh_o()}>'
    cond = f'o{b.fresh_o()}'
    b.subs_text += [f'{label} sub', f'  {cond} if [#1 GT 0]', '    G91 G1 X#2',
                    f'    {label} call [#1 - 1] [#2]', f'  {cond} endif', '  G90', f'{label} endsub']
    sub = {'label': label, 'kind': 'recursive',
           'disp': lambda a: [max(0, math.ceil(a[0])) * a[1], 0.0, 0.0], 'keeps': False}
    b.subs.append(sub)
    return sub


def argument(b, v):
    """An argument worth v: a number or an expression."""
    if b.chance(0.3):
        return f'[{equal_to(b, v, 1).text}]'
    return f'[{b.num(v)}]'


def nonzero_length(b, lo, hi):
    v = b.rnd_units(b.length(lo, hi))
    return v if abs(v) > b.mm(0.5) else b.rnd_units(b.mm(1.5))


def call(b):
    if not b.subs or b.chance(0.3):
        sub = b.pick([define_moves_sub, define_moves_sub, define_value_sub,
                      define_recursive_sub])(b)
    else:
        sub = b.pick(b.subs)
    if sub['kind'] == 'recursive':
        vals = [float(b.rnd.randint(0, 4)), nonzero_length(b, -8, 8)]
    elif sub['kind'] == 'moves':
        vals = [nonzero_length(b, -10, 10), nonzero_length(b, -10, 10)]
    else:
        vals = [round(b.uniform(-10, 10), 3), round(b.uniform(-10, 10), 3)]
    args = [argument(b, v) for v in vals]
    if sub['kind'] != 'value' and not b.feed_ok:
        b.emit([b.word('F', b.feed_value())])
        b.feed_ok = True
    b.raw(f'{sub["label"]} call ' + ' '.join(args))
    if sub['kind'] == 'value':
        name = param_name(b, False)
        b.raw(f'{name} = #<_value>')
        b.params[name] = sub['f'](vals)
        return
    d = sub['disp'](vals)
    if b.pos is not None:
        b.pos = [p + dv for p, dv in zip(b.pos, d)]
    b.motion = None
    if sub['kind'] == 'moves' and not sub['keeps']:
        b.plane = 17  # its body says G17 (the recursive one leaves the plane)
    if not sub['keeps']:
        b.dist = 90
    if sub.get('gout'):
        b.params['#<_gsub_out>'] = vals[0] + vals[1]


# ---- loops and conditionals ---------------------------------------------

def incremental_moves(b, count):
    """Position-independent moves for a loop body; returns their displacement."""
    d = [0.0, 0.0, 0.0]
    lines = ['G91']
    for _ in range(count):
        dx, dy = b.rnd_units(b.length(-8, 8)), b.rnd_units(b.length(-8, 8))
        if b.chance(0.3):
            lines.append(f'G{b.pick([2, 3])} X{b.num(2 * dx)} Y0 I{b.num(dx)} J0')
            d[0] += 2 * dx
            continue
        lines.append(f'G{b.pick([0, 1])} X{b.num(dx)} Y{b.num(dy)}')
        d[0] += dx
        d[1] += dy
    lines.append('G90')
    return lines, d


def loop(b):
    if b.plane != 17:
        b.emit([b.g(17)])
        b.plane = 17
    if not b.feed_ok:
        b.emit([b.word('F', b.feed_value())])
        b.feed_ok = True
    o = f'o{b.fresh_o()}'
    kind = b.pick(['repeat', 'while', 'do'])
    count = b.rnd.randint(0 if kind != 'do' else 1, 4)
    if kind == 'repeat':
        moves, d = incremental_moves(b, b.rnd.randint(1, 3))
        b.raw(f'{o} repeat [{count}]')
        for t in moves:
            b.raw('  ' + t)
        b.raw(f'{o} endrepeat')
        total = [count * v for v in d]
        if b.pos is not None:
            b.pos = [p + v for p, v in zip(b.pos, total)]
    else:
        k = f'#<_k{b.fresh_param()}>' if b.chance(0.5) else f'#{b.fresh_param()}'
        x0, dx = b.rnd_units(b.length(-30, 0)), b.rnd_units(b.length(1, 10))
        y = b.rnd_units(b.length(-30, 30))
        stop = b.rnd.randint(0, count) if b.chance(0.3) else None
        b.raw(f'{k} = 0')
        b.raw(f'{o} while [{k} LT {count}]' if kind == 'while' else f'{o} do')
        b.raw(f'  {k} = [{k} + 1]')
        if stop is not None:
            c = f'o{b.fresh_o()}'
            b.raw(f'  {c} if [{k} EQ {stop}]')
            # rs274 leaves a flag set after a break out of a while and after
            # a continue in a do (known_differences.tsv break-then-do,
            # continue-then-break): break leaves do loops, continue goes on in
            # while loops, where the flag is cleared.
            b.raw(f'    {o} {"break" if kind == "do" else "continue"}')
            b.raw(f'  {c} endif')
        b.raw(f'  G90 G1 X[{k} * {b.num(dx)} + {b.num(x0)}] Y{b.num(y)}')
        if kind == 'do':
            b.raw(f'{o} while [{k} LT {count}]')
        else:
            b.raw(f'{o} endwhile')
        b.pos = None  # break/continue decide the last point; let the next segment anchor
        b.dist = 90
        b.params[k] = None
    b.motion = None


def condition(b):
    """An expression and whether it is true."""
    e = expression(b, b.pick([1, 2]))
    if b.chance(0.5):
        limit = round(e.value + b.pick([-1, 1]) * b.uniform(0.5, 3), 2)
        op = b.pick(['LT', 'GT', 'LE', 'GE'])
        text = f'{e.bracketed()} {op} {b.num(limit, 2)}'
        from .expressions import binary
        return text, binary(op, e.value, limit) != 0
    if abs(e.value) < 1e-3:
        return f'{e.bracketed()} LT 100000', True
    return e.text, True  # a value as a condition: true when not zero


def conditional(b, segment):
    """if/elseif/else around segments; the generator follows the branch taken."""
    o = f'o{b.fresh_o()}'
    before = snapshot(b)
    branches = [('if',) + condition(b)]
    for _ in range(b.pick([0, 0, 1, 2])):
        branches.append(('elseif',) + condition(b))
    if b.chance(0.5):
        branches.append(('else', '', True))
    taken, after = None, None
    b.depth += 1
    for kw, cond, true in branches:
        restore(b, before)
        b.raw(f'{o} {kw} [{cond}]' if cond else f'{o} {kw}')
        for _ in range(b.rnd.randint(1, 2)):
            segment(b)
        if taken is None and true:
            taken, after = kw, snapshot(b)
    b.depth -= 1
    b.raw(f'{o} endif')
    restore(b, after if after is not None else before)
    b.motion = None
