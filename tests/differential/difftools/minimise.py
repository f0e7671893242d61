"""Minimising a program that shows a difference, keeping the difference.

Lines are removed by delta debugging (Zeller's ddmin: chunks, then their
complements, halving the chunk size), then one at a time until no line can
go, then the words of each remaining block one at a time. A candidate is
kept when the two interpreters still differ *the same way* (same kind and
detail, e.g. `trace:arc.center/turn` or `usina-error:E_ARC_RADIUS_MISMATCH`),
so the small program shows the bug the big one found and not another."""
import re
import time


class Minimiser:
    def __init__(self, engines, budget_s=120.0, max_runs=1500):
        self.engines = engines
        self.deadline = None
        self.budget_s = budget_s
        self.max_runs = max_runs
        self.runs = 0

    def out_of_budget(self):
        return time.monotonic() > self.deadline or self.runs >= self.max_runs

    def still(self, lines, signature):
        if self.out_of_budget():
            return False
        self.runs += 1
        d, _, _ = self.engines.check('\n'.join(lines) + '\n')
        return d is not None and d.signature() == signature

    def ddmin(self, lines, signature):
        n = 2
        while len(lines) >= 2 and not self.out_of_budget():
            size = max(1, len(lines) // n)
            chunks = [lines[i:i + size] for i in range(0, len(lines), size)]
            reduced = False
            for i in range(len(chunks)):
                rest = [ln for j, c in enumerate(chunks) if j != i for ln in c]
                if self.still(rest, signature):
                    lines, n, reduced = rest, max(n - 1, 2), True
                    break
            if not reduced:
                if size == 1:
                    break
                n = min(len(lines), n * 2)
        return lines

    def one_by_one(self, lines, signature):
        changed = True
        while changed and not self.out_of_budget():
            changed = False
            i = 0
            while i < len(lines):
                cand = lines[:i] + lines[i + 1:]
                if self.still(cand, signature):
                    lines, changed = cand, True
                else:
                    i += 1
        return lines

    def words(self, lines, signature):
        """Drops words of ordinary blocks (not O-words, assignments or comments)."""
        for i in range(len(lines)):
            if re.match(r'\s*([oO#(;%]|$)', lines[i]):
                continue
            parts = split_words(lines[i])
            j = 0
            while j < len(parts) and len(parts) > 1:
                cand = parts[:j] + parts[j + 1:]
                trial = lines[:i] + [' '.join(cand)] + lines[i + 1:]
                if self.still(trial, signature):
                    parts, lines = cand, trial
                else:
                    j += 1
        return lines

    def run(self, text, signature):
        """The smallest program found that still differs with `signature`."""
        self.deadline = time.monotonic() + self.budget_s
        lines = text.splitlines()
        lines = self.ddmin(lines, signature)
        lines = self.one_by_one(lines, signature)
        lines = self.words(lines, signature)
        return '\n'.join(lines) + '\n'


def split_words(line):
    """The words of a block: a letter and its value (number, #param or [expression])."""
    out, cur, depth = [], '', 0
    for ch in line.strip():
        if depth == 0 and ch.isalpha() and cur and not cur[-1].isalpha() and not cur.endswith('#<'):
            if not (cur.endswith('#') or '<' in cur and '>' not in cur.split('<')[-1]):
                out.append(cur.strip())
                cur = ''
        if ch == '[':
            depth += 1
        elif ch == ']':
            depth -= 1
        if ch == '(' and depth == 0:
            out.append(cur.strip())
            cur = ''
            out.append(line.strip()[line.strip().index('('):])
            return [w for w in out if w]
        cur += ch
    out.append(cur.strip())
    return [w for w in out if w]
