#!/usr/bin/env python3
"""Runs usina on LinuxCNC's conformance set (../shared/conformance/rs274ngc)
and compares each trace with LinuxCNC's by the rules of spec/trace.md.

usage: run_conformance.py USINA SHARED_DIR [--only ID] [--known FILE] [--verbose]
Prints one line per failing program, then 'N passed, M failed'. Exits 1 when
a program fails that is not listed in the known-differences file (or a
listed one passes: then the list must be updated)."""
import argparse
import concurrent.futures as cf
import json
import os
import subprocess
import sys
import tempfile

MOTION = ('traverse', 'feed', 'arc', 'dwell', 'probe')
SUB_PATH = ['linuxcnc/nc_files', 'linuxcnc/nc_files/ngcgui_lib',
            'linuxcnc/nc_files/ngcgui_lib/utilitysubs', 'linuxcnc/nc_files/ngcgui_lib/lathe',
            'linuxcnc/nc_files/remap-subroutines', 'linuxcnc/nc_files/remap_lib/common_nc_subs',
            'linuxcnc/configs/sim/axis/remap/extend-builtins/macros/mill',
            'linuxcnc/configs/sim/axis/remap/extend-builtins/macros/lathe',
            'linuxcnc/configs/sim/axis/probe/basic_probe/macros',
            'linuxcnc/nc_files/gladevcp_lib']


def motion_ops(lines):
    out = []
    for line in lines:
        line = line.strip()
        if not line:
            continue
        o = json.loads(line)
        if o.get('op') in MOTION:
            out.append(o)
    return out


def close(a, b, tol):
    return a is not None and b is not None and len(a) == len(b) and all(
        abs(x - y) <= tol for x, y in zip(a, b))


def first_difference(exp, act, tol=2e-3):
    for i, (e, a) in enumerate(zip(exp, act)):
        bad = None
        if e['op'] != a.get('op'):
            bad = 'op'
        elif e['op'] == 'dwell':
            bad = None if abs(e['s'] - a.get('s', -1)) <= 1e-6 else 's'
        elif not close(e['to'], a.get('to'), tol):
            bad = 'to'
        elif e['op'] == 'arc' and (not close(e['center'], a.get('center'), tol) or e['turn'] != a.get('turn')):
            bad = 'center/turn'
        elif e['op'] in ('feed', 'arc') and e.get('f') is not None and a.get('f') is not None and \
                abs(e['f'] - a['f']) > 1e-6 * max(1, abs(e['f'])):
            bad = 'f'
        if bad:
            return f'op {i + 1}: {bad}: expected {json.dumps(e)} got {json.dumps(a)}'
    if len(exp) != len(act):
        return f'motion op count: expected {len(exp)}, got {len(act)}'
    return None


def run_one(usina, root, row):
    pid, _src, _path, table, _end, folder, peck = row
    lib = os.path.join(root, 'lib')
    sub = ':'.join([os.path.join(lib, p) for p in SUB_PATH] + [os.path.join(lib, folder)])
    cmd = [usina, 'trace', os.path.join(root, 'programs', pid + '.ngc'), '--machine-units', 'inch',
           '--tool-table', os.path.join(root, 'tools', table), '--subroutine-path', sub,
           '--peck-clearance', peck]
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=120, cwd=tempfile.gettempdir())
    except subprocess.TimeoutExpired:
        return pid, 'timeout'
    if p.returncode > 1 or p.returncode < 0:
        return pid, f'exit status {p.returncode}: {p.stderr.strip()[:300]}'
    try:
        act = motion_ops(p.stdout.splitlines())
    except json.JSONDecodeError as e:
        return pid, f'bad JSON: {e}'
    with open(os.path.join(root, 'expected', pid + '.jsonl')) as f:
        exp = motion_ops(f)
    diff = first_difference(exp, act)
    if diff and p.stderr.strip():
        diff += ' | ' + p.stderr.strip().splitlines()[0][:300]
    return pid, diff


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('usina')
    ap.add_argument('shared')
    ap.add_argument('--only')
    ap.add_argument('--known')
    ap.add_argument('--verbose', action='store_true')
    args = ap.parse_args()
    args.usina = os.path.abspath(args.usina)
    args.shared = os.path.abspath(args.shared)
    root = os.path.join(args.shared, 'conformance', 'rs274ngc')
    if not os.path.isdir(root):
        print(f'no conformance set at {root}: skipped')
        return 0
    rows = [l.rstrip('\n').split('\t') for l in open(os.path.join(root, 'manifest.tsv')) if not l.startswith('#')]
    if args.only:
        rows = [r for r in rows if args.only in r[0]]
    known = {}
    if args.known and os.path.exists(args.known):
        for line in open(args.known):
            if line.strip() and not line.startswith('#'):
                parts = line.rstrip('\n').split('\t')
                known[parts[0]] = parts[1:] if len(parts) > 1 else []
    failed, passed, unexpected, fixed = [], 0, [], []
    with cf.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as ex:
        for pid, diff in ex.map(lambda r: run_one(args.usina, root, r), rows):
            if diff:
                failed.append((pid, diff))
                if pid not in known:
                    unexpected.append(pid)
            else:
                passed += 1
                if pid in known:
                    fixed.append(pid)
    for pid, diff in sorted(failed):
        mark = '' if pid in known else 'NEW '
        if args.verbose or pid not in known:
            print(f'{mark}FAIL {pid}: {diff}')
    for pid in fixed:
        print(f'FIXED {pid}: passes now; remove it from the known-differences list')
    total = passed + len(failed)
    print(f'conformance: {100.0 * passed / max(total, 1):.1f}% of {total} programs match LinuxCNC')
    print(f'{passed} passed, {len(failed)} failed')
    return 1 if unexpected or fixed else 0


if __name__ == '__main__':
    sys.exit(main())
