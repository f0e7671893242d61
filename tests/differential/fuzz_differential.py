#!/usr/bin/env python3
"""Differential fuzzer: random valid RS274NGC programs run through usina and
through LinuxCNC's stand-alone interpreter (Debian's rs274), traces compared.

  fuzz_differential.py USINA SHARED_DIR [--seconds S] [--seed-start N] [--count N]
                       [--known FILE] [--out DIR] [--minimise-budget S]
  fuzz_differential.py USINA SHARED_DIR --seed N [--minimise]    one program
  fuzz_differential.py --print N                                  print program N

Seed N always gives the same program (ngcgen/). A run takes seeds N, N+1,
... until --count programs or --seconds have passed, whichever comes first.
A difference not explained by the known-differences file is minimised,
printed with its seed, and makes the run fail (exit 1); the known ones are
counted. Each known entry's minimal program is checked first: it must still
differ, and as its entry says. Exit 0 with "skipped" when rs274 or the
shared folder is missing (as run_differential.sh)."""
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from difftools import known as known_mod  # noqa: E402
from difftools.engines import Engines  # noqa: E402
from difftools.minimise import Minimiser  # noqa: E402
from ngcgen.program import generate  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def parse():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('usina', nargs='?')
    ap.add_argument('shared', nargs='?')
    ap.add_argument('--seconds', type=float, default=60.0)
    ap.add_argument('--seed-start', type=int, default=1)
    ap.add_argument('--count', type=int, default=10 ** 9)
    ap.add_argument('--known', default=os.path.join(HERE, 'known_differences.tsv'))
    ap.add_argument('--out', default=None, help='folder for the programs that differ')
    ap.add_argument('--minimise-budget', type=float, default=60.0,
                    help='seconds spent minimising each new difference')
    ap.add_argument('--minimise-max', type=int, default=3,
                    help='new differences minimised at the end (the others are listed by seed)')
    ap.add_argument('--seed', type=int, help='run one program and show the difference')
    ap.add_argument('--minimise', action='store_true', help='with --seed: minimise it')
    ap.add_argument('--print', type=int, metavar='SEED', help='print the program of SEED')
    ap.add_argument('--quiet', action='store_true', help='no line per known difference')
    return ap.parse_args()


def describe(seed, diff, text):
    lines = text.splitlines()
    site = lines[diff.site - 1] if diff.site and diff.site <= len(lines) else '?'
    return f'seed {seed}: {diff.signature()} at line {diff.site}: {site}\n  ' + \
        diff.text.replace('\n', '\n  ')


def check_known(engines, entries):
    """Each listed difference's minimal program still differs as listed."""
    bad = []
    for e in entries:
        if not os.path.isfile(e.path):
            bad.append(f'{e.id}: {e.path} is missing')
            continue
        text = open(e.path).read()
        d, _, _ = engines.check(text)
        if d is None:
            bad.append(f'{e.id}: its program no longer differs: usina now agrees with rs274, '
                       f'remove the entry (and known/{e.id}.ngc)')
        elif not e.matches(d, text):
            bad.append(f'{e.id}: its program now differs otherwise: {d.signature()} at line '
                       f'{d.site}\n  {d.text}')
    return bad


def one(args, engines):
    text = generate(args.seed)
    d, lc, us = engines.check(text)
    print(text)
    print(f'rs274: {lc.error or "ran to the end"}\nusina: {us.error or "ran to the end"}')
    if d is None:
        print(f'seed {args.seed}: same')
        return 0
    print(describe(args.seed, d, text))
    if args.minimise:
        small = Minimiser(engines, budget_s=args.minimise_budget * 5).run(text, d.signature())
        print(f'--- minimised ({small.count(chr(10))} lines) ---\n{small}', end='')
    return 1


def campaign(args, engines, entries):
    problems = check_known(engines, entries)
    start = time.monotonic()
    counts = {'programs': 0, 'same': 0, 'both_rejected': 0}
    known_hits, new = {}, []
    seed = args.seed_start
    while counts['programs'] < args.count and time.monotonic() - start < args.seconds:
        text = generate(seed)
        d, lc, _ = engines.check(text)
        counts['programs'] += 1
        if d is None:
            counts['same'] += 1
            counts['both_rejected'] += lc.error is not None
        else:
            e = known_mod.explain(entries, d, text)
            if e is not None:
                known_hits.setdefault(e.id, []).append(seed)
                if not args.quiet:
                    print(f'known {e.id}: seed {seed}')
            else:
                new.append((seed, d, text))
                print('NEW ' + describe(seed, d, text), flush=True)
        seed += 1
    elapsed = time.monotonic() - start
    report(args, engines, counts, known_hits, new, elapsed, seed)
    for p in problems:
        print('KNOWN LIST: ' + p)
    return 1 if new or problems else 0


def report(args, engines, counts, known_hits, new, elapsed, seed):
    n = counts['programs']
    print(f'{n} programs (seeds {args.seed_start}-{seed - 1}) in {elapsed:.0f} s: '
          f'{counts["same"]} agree ({counts["both_rejected"]} of them rejected by both), '
          f'{sum(len(v) for v in known_hits.values())} known differences, {len(new)} new')
    for k, seeds in sorted(known_hits.items()):
        print(f'  known {k}: {len(seeds)} (seeds {", ".join(map(str, seeds[:5]))}'
              f'{", ..." if len(seeds) > 5 else ""})')
    groups = {}
    for seed, d, _ in new:
        groups.setdefault(d.signature(), []).append(seed)
    for sig, seeds in sorted(groups.items(), key=lambda kv: -len(kv[1])):
        print(f'  NEW {sig}: {len(seeds)} (seeds {", ".join(map(str, seeds[:8]))}'
              f'{", ..." if len(seeds) > 8 else ""})')
    if new:
        print(f'each NEW difference: fix it, or list it in {os.path.relpath(args.known)} with '
              f'its reason and a minimal program (tests/differential/README.md)')
    if args.out:
        os.makedirs(args.out, exist_ok=True)
        for seed, _, text in new:
            with open(os.path.join(args.out, f'seed-{seed}.ngc'), 'w') as f:
                f.write(text)
    for seed, d, text in new[:args.minimise_max]:
        small = Minimiser(engines, budget_s=args.minimise_budget).run(text, d.signature())
        print(f'--- seed {seed} ({d.signature()}) minimised to {small.count(chr(10))} lines:\n'
              f'{small}---')
        if args.out:
            with open(os.path.join(args.out, f'seed-{seed}-min.ngc'), 'w') as f:
                f.write(small)


def main():
    args = parse()
    if args.print is not None:
        sys.stdout.write(generate(args.print))
        return 0
    if not args.usina or not args.shared:
        sys.exit('usage: fuzz_differential.py USINA SHARED_DIR [options]')
    why = Engines.missing(args.shared)
    if why:
        print(f'differential fuzz: {why}: skipped')
        return 0
    engines = Engines(args.usina, args.shared)
    check = engines.self_check()
    if check and check[0] == 'skip':
        print(f'differential fuzz: {check[1]}: skipped')
        return 0
    if check:
        print(f'differential fuzz: {check[1]}')
        return 2
    if args.seed is not None:
        return one(args, engines)
    entries = known_mod.load(args.known) if os.path.isfile(args.known) else []
    return campaign(args, engines, entries)


if __name__ == '__main__':
    sys.exit(main())
