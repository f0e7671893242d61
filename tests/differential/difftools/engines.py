"""Running a program through LinuxCNC's rs274 and through usina, and
comparing the two traces.

rs274 is run exactly as ../shared/conformance/lcnc-trace.sh runs it (a fresh
empty parameter file, the generic tool table, standard input closed) and its
canon output converted by ../shared/conformance/canon2jsonl.py, imported
rather than started per program: a Python start costs more than rs274
itself. `Engines.self_check` runs lcnc-trace.sh once and fails when the two
ways disagree. The traces are compared by ../shared/conformance/compare_traces.py."""
import atexit
import contextlib
import io
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile


# rs274 prints positions and offsets with 4 decimals of the program's unit;
# canon2jsonl adds the G5x offset, the G92 offset and the position, each
# rounded to 0.00005 in under G20: up to 3 x 1.27 um apart from the exact
# sum. The conformance set's 0.002 mm would flag that as a difference.
TOLERANCE_MM = 0.004

# Under G20 a move rs274 prints differs from the exact one by up to two
# positions' error, 2 x 3 x 1.27 um: a move shorter than the tolerance plus
# that may be dropped from one trace and kept in the other (0.0046 mm exact
# in usina, printed as 0.0025 mm by rs274). Such a move is skipped when it
# is what stands between two traces that agree on either side of it.
AMBIGUOUS_INCH_MOVE_MM = TOLERANCE_MM + 2 * 3 * 0.00127


class Outcome:
    """What one engine made of a program: its trace, and its error if it stopped on one."""

    def __init__(self, trace, error, error_line=None, ops=None):
        self.trace = trace  # JSONL text
        self.error = error  # None: the program ran to its end
        self.error_line = error_line  # 1-based, when the engine says it
        self.ops = ops or []


class Difference:
    def __init__(self, kind, detail, site, text):
        self.kind = kind  # 'trace', 'usina-error', 'lcnc-error'
        self.detail = detail  # what differs (the op and field, or the error)
        self.site = site  # the program line (1-based) where it shows, or None
        self.text = text  # the comparison's own words

    def signature(self):
        return f'{self.kind}:{self.detail}'


class Engines:
    def __init__(self, usina, shared, work=None, timeout=20.0):
        self.timeout = timeout  # seconds; a minimiser's cut can leave a loop that never ends
        self.usina = os.path.realpath(usina)
        self.shared = os.path.realpath(shared)
        self.conf = os.path.join(self.shared, 'conformance')
        self.table = os.path.join(self.conf, 'rs274ngc', 'tools', 'generic.tbl')
        self.work = work or tempfile.mkdtemp(prefix='usina-difffuzz-')
        atexit.register(shutil.rmtree, self.work, True)
        # rs274 keeps its tool table in $HOME/.tool.mmap, shared with every
        # other rs274 of the user: two at once clobber each other's tools
        # ("Requested tool 12 not found"). A home of its own for this one.
        self.env = dict(os.environ, HOME=self.work)
        if self.conf not in sys.path:
            sys.path.insert(0, self.conf)
        import canon2jsonl  # noqa: E402  (from ../shared, never copied)
        import compare_traces  # noqa: E402
        self.canon2jsonl, self.compare_traces = canon2jsonl, compare_traces
        self.runs = 0

    @staticmethod
    def missing(shared):
        """Why the fuzzer cannot run here, or None."""
        if shutil.which('rs274') is None:
            return 'rs274 (apt-get install linuxcnc-uspace) is not installed'
        if not os.path.isfile(os.path.join(shared, 'conformance', 'lcnc-trace.sh')):
            return f'{shared}/conformance/lcnc-trace.sh is missing'
        return None

    def write(self, text):
        path = os.path.join(self.work, 'prog.ngc')
        with open(path, 'w') as f:
            f.write(text)
        return path

    def lcnc(self, text):
        path = self.write(text)
        var = os.path.join(self.work, 'p.var')
        canon = os.path.join(self.work, 'p.canon')
        open(var, 'w').close()
        with open(canon, 'w') as out:
            try:
                res = subprocess.run(['rs274', '-g', '-v', var, '-t', self.table, path],
                                     stdin=subprocess.DEVNULL, stdout=out, stderr=subprocess.PIPE,
                                     cwd=self.work, timeout=self.timeout, env=self.env)
            except subprocess.TimeoutExpired:
                return Outcome('', f'timeout: rs274 ran over {self.timeout:g} s')
        buf = io.StringIO()
        with contextlib.redirect_stdout(buf):
            self.canon2jsonl.main(canon)
        error = None
        if res.returncode != 0:
            lines = [ln for ln in res.stderr.decode(errors='replace').splitlines()
                     if ln.strip() != 'executing']
            error = '\n'.join(lines[-2:]) or f'rs274 exit {res.returncode}'
        return Outcome(buf.getvalue(), error, block_line(text, error))

    def run_usina(self, text):
        path = self.write(text)
        cmd = [self.usina, 'trace', '--peck-clearance', '0.254', '--machine-units', 'inch',
               '--tool-table', self.table, 'prog.ngc']
        try:
            res = subprocess.run(cmd, stdin=subprocess.DEVNULL, capture_output=True,
                                 cwd=self.work, timeout=self.timeout)
        except subprocess.TimeoutExpired:
            return Outcome('', f'timeout: usina ran over {self.timeout:g} s')
        err = res.stderr.decode(errors='replace')
        error, line = None, None
        if res.returncode != 0:
            m = re.search(r'prog\.ngc:(\d+):\d+: error: (.*)', err)
            error = m.group(2) if m else (err.strip().splitlines() or [f'exit {res.returncode}'])[0]
            line = int(m.group(1)) if m else None
        return Outcome(res.stdout.decode(errors='replace'), error, line)

    def compare(self, a, b, inch=False):
        """compare_traces.py's verdict on two traces: None when they match, else its message."""
        pa, pb = os.path.join(self.work, 'lcnc.jsonl'), os.path.join(self.work, 'usina.jsonl')
        na, nb = normalise(a), normalise(b)
        if inch:
            na, nb = skip_ambiguous_moves(na, nb)
        with open(pa, 'w') as f:
            f.write(dump(na))
        with open(pb, 'w') as f:
            f.write(dump(nb))
        buf = io.StringIO()
        saved = sys.argv
        sys.argv = ['compare_traces.py', pa, pb, '--tol', str(TOLERANCE_MM)]
        try:
            with contextlib.redirect_stdout(buf):
                rc = self.compare_traces.main()
        finally:
            sys.argv = saved
        return None if rc == 0 else buf.getvalue().strip()

    def check(self, text):
        """Runs both; returns (Difference or None, lcnc Outcome, usina Outcome)."""
        self.runs += 1
        lc = self.lcnc(text)
        if lc.error and lc.error.startswith('timeout'):
            return Difference('timeout', 'rs274', None, lc.error), lc, Outcome('', None)
        us = self.run_usina(text)
        if (lc.error is None) != (us.error is None):
            if us.error is not None:
                code = re.search(r'\[(E_[A-Z_]+)\]', us.error)
                return Difference('usina-error', code.group(1) if code else us.error,
                                  us.error_line, f'usina: {us.error}'), lc, us
            first = lc.error.splitlines()[0]
            return Difference('lcnc-error', first, lc.error_line, f'rs274: {lc.error}'), lc, us
        lc_trace = lc.trace
        if lc.error and us.error:
            if lc.error_line and us.error_line and lc.error_line != us.error_line:
                return Difference('error-line', f'rs274 line {lc.error_line}', us.error_line,
                                  f'rs274 stops at line {lc.error_line}: {lc.error}\n'
                                  f'usina stops at line {us.error_line}: {us.error}'), lc, us
            # Both refuse the same block: rs274 may have moved in it before
            # it found the fault (usina checks a block before it moves).
            lc_trace = motion_prefix(lc.trace, len(motion_ops(us.trace)))
        verdict = self.compare(lc_trace, us.trace, inch=re.search(r'G20', text) is not None)
        if verdict is None:
            return None, lc, us
        return Difference('trace', trace_detail(verdict, us.trace),
                          trace_site(verdict, us), verdict), lc, us

    def self_check(self):
        """('skip', why) when rs274 does not run here, ('error', why) when this
        runner and lcnc-trace.sh disagree, None when all is well."""
        prog = 'G21 G0 X1 Y2\nG1 Z-1 F100\nG2 X3 Y2 R1\nM2\n'
        path = self.write(prog)
        out = subprocess.run(['bash', os.path.join(self.conf, 'lcnc-trace.sh'), path],
                             capture_output=True, cwd=self.work, timeout=60,
                             env=self.env).stdout.decode()
        if 'traverse' not in out:
            return 'skip', 'rs274 is installed but does not run here'
        mine = self.lcnc(prog).trace
        if mine != out:
            return 'error', f'this runner and lcnc-trace.sh disagree:\n{mine}\n---\n{out}'
        return None


def normalise(trace):
    """Both traces, before compare_traces.py sees them:

    - each arc's centre is moved along its normal onto the plane of its
      start. trace.md gives a centre the axial coordinate of the arc's
      start, so that coordinate says nothing the previous op's `to` does not;
      canon2jsonl.py takes it from the last program position it saw, which
      is stale after G92 or G5x change between two moves;
    - a straight move shorter than the comparison's tolerance is dropped:
      rs274 prints it as no move or as one of 0.0001 in, and whether one is
      made at all can hang on an ulp (a cycle started at R, computed in
      inches by rs274 and in mm by usina)."""
    out, last = [], [0.0, 0.0, 0.0]  # both start at the machine's origin
    for line in trace.splitlines():
        if not line.strip():
            continue
        o = json.loads(line)
        if o.get('op') in ('traverse', 'feed') and o.get('to') and \
                max(abs(a - b) for a, b in zip(o['to'], last)) < TOLERANCE_MM:
            continue
        if o.get('op') == 'arc' and last is not None and o.get('center') and o.get('normal'):
            n = o['normal']
            k = sum(v * v for v in n) ** 0.5
            if k > 0:
                n = [v / k for v in n]
                d = sum((c - s) * v for c, s, v in zip(o['center'], last, n))
                o['center'] = [c - d * v for c, v in zip(o['center'], n)]
        if o.get('op') in ('traverse', 'feed', 'arc', 'probe') and o.get('to'):
            last = o['to']
        out.append(o)
    return out


def dump(ops):
    return ''.join(json.dumps(o) + '\n' for o in ops)


def skip_ambiguous_moves(a, b):
    """Both motion-op lists without the short straight moves (shorter than
    AMBIGUOUS_INCH_MOVE_MM) that one has and the other lacks: a move is
    skipped only where the two lists differ and the op after it matches the
    other list's op, or where it comes after the other list's last op. A
    real difference is left for compare_traces.py."""
    a, b = [o for o in a if o.get('op') in MOTION], [o for o in b if o.get('op') in MOTION]
    ta, tb = ambiguous(a), ambiguous(b)
    out_a, out_b, i, j = [], [], 0, 0
    while i < len(a) and j < len(b):
        if not same_motion(a[i], b[j]):
            if tb[j] and j + 1 < len(b) and same_motion(a[i], b[j + 1]):
                j += 1
                continue
            if ta[i] and i + 1 < len(a) and same_motion(a[i + 1], b[j]):
                i += 1
                continue
        out_a.append(a[i])
        out_b.append(b[j])
        i, j = i + 1, j + 1
    # What is left after the other list's end: its ambiguous moves too.
    return (out_a + [o for o, t in zip(a[i:], ta[i:]) if not t],
            out_b + [o for o, t in zip(b[j:], tb[j:]) if not t])


MOTION = ('traverse', 'feed', 'arc', 'dwell', 'probe')


def ambiguous(ops):
    """For each op, whether it is a straight move shorter than AMBIGUOUS_INCH_MOVE_MM."""
    out, last = [], [0.0, 0.0, 0.0]
    for o in ops:
        out.append(o.get('op') in ('traverse', 'feed') and
                   max(abs(x - y) for x, y in zip(o['to'], last)) < AMBIGUOUS_INCH_MOVE_MM)
        if o.get('to'):
            last = o['to']
    return out


def same_motion(a, b):
    return a.get('op') == b.get('op') and (a.get('to') is None) == (b.get('to') is None) and \
        (a.get('to') is None or max(abs(x - y) for x, y in zip(a['to'], b['to'])) <= TOLERANCE_MM)


def motion_prefix(trace, n):
    """The trace up to its n-th motion op."""
    out, seen = [], 0
    for line in trace.splitlines():
        if line.strip() and json.loads(line).get('op') in ('traverse', 'feed', 'arc', 'dwell',
                                                           'probe'):
            if seen == n:
                break
            seen += 1
        out.append(line)
    return '\n'.join(out) + '\n'


def motion_ops(trace):
    out = []
    for line in trace.splitlines():
        if line.strip():
            o = json.loads(line)
            if o.get('op') in ('traverse', 'feed', 'arc', 'dwell', 'probe'):
                out.append(o)
    return out


def trace_detail(verdict, usina_trace):
    m = re.match(r'op (\d+): (\S+) differs\n\s+expected (\{.*\})', verdict)
    if m:
        return f'{json.loads(m.group(3))["op"]}.{m.group(2)}'
    if verdict.startswith('motion op count'):
        return 'count'
    return verdict.splitlines()[0]


def trace_site(verdict, us):
    """The program line of the first motion op that differs, as usina's trace says it."""
    ops = motion_ops(us.trace)
    m = re.match(r'op (\d+):', verdict)
    if m and int(m.group(1)) <= len(ops):
        return ops[int(m.group(1)) - 1].get('src', [None])[0]
    if us.error_line is not None:
        return us.error_line
    return ops[-1].get('src', [None])[0] if ops else None


def block_line(text, error):
    """The line of the block rs274 names in its error (its last stderr line is the block)."""
    if not error:
        return None
    block = error.splitlines()[-1].strip()
    found = [n for n, line in enumerate(text.splitlines(), 1) if line.strip() == block]
    return found[0] if len(found) == 1 else None
