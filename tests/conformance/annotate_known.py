#!/usr/bin/env python3
"""Reads 'program<TAB>difference' lines, writes 'program<TAB>first difference<TAB>why'
with the reason of known_reasons.tsv whose pattern the program's id contains."""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
reasons = [l.rstrip('\n').split('\t', 1) for l in open(os.path.join(here, 'known_reasons.tsv'))
           if l.strip() and not l.startswith('#')]
for line in sys.stdin:
    pid, diff = line.rstrip('\n').split('\t', 1)
    why = next((r for p, r in reasons if p in pid), 'not yet explained')
    print(f"{pid}\t{diff.split(' | ')[0]}\t{why}")
