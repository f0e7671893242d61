#!/usr/bin/env python3
"""Runs `usina check` on the wild corpus (real programs from public repositories) and
compares each outcome with the one manifest.tsv says the program deserves.

Outcomes are `ok` or `CODE@LINE` (the first error; grbl errors as `E_GRBL:N@LINE`, N being
the number Grbl prints). An entry marked `xfail` is one usina gets wrong today (a false
error, or a missing one): it is expected NOT to meet its outcome, and meeting it is an
"unexpected pass" that fails the run until the xfail is removed, as LLVM's lit does. The
same holds for `--dialect auto`: each program should be guessed as its manifest dialect,
and `auto_xfail` marks today's wrong guesses.

Usage: run_wild.py USINA MANIFEST --corpus DIR [--corpus DIR ...] [--may-lack LICENCE ...]
                   [--all] [--actual]
The first --corpus folder that exists is used; with none, the run is skipped (exit 77).
A file of the manifest whose licence is given by --may-lack may be missing from it (the
repository's own copy, files/, leaves out what it may not carry): it is left out of the
run and counted; any other missing file, or one whose SHA-256 differs, fails the run.
--all prints every row; --actual prints today's outcomes as TSV (file, outcome, guess),
for updating the manifest by hand.
"""
import argparse
import collections
import csv
import hashlib
import json
import os
import re
import subprocess
import sys
import time

SKIP = 77
HERE = os.path.dirname(os.path.abspath(__file__))  # options' paths are relative to it
FIELDS = ["file", "dialect", "options", "expect", "xfail", "today", "auto_xfail", "auto_today",
          "repo", "path", "commit", "licence", "sha256", "note"]


def read_manifest(path):
    with open(path, newline="", encoding="utf-8") as f:
        lines = [line for line in f if not line.startswith("#")]
    rows = list(csv.DictReader(lines, delimiter="\t"))
    for row in rows:
        missing = [k for k in FIELDS if row.get(k) in (None, "")]
        if missing:
            sys.exit(f"manifest: {row.get('file')}: empty field(s) {', '.join(missing)}")
    return rows


def options_of(row):
    return [] if row["options"] == "-" else row["options"].split()


def outcome_of(diag_file):
    """The first error of one file's JSON diagnostics, or ok."""
    for d in diag_file["diagnostics"]:
        if d["severity"] != "error":
            continue
        code = d["code"]
        number = re.search(r"grbl error:(\d+)", d["message"])
        if code == "E_GRBL" and number:
            code += ":" + number.group(1)
        return f"{code}@{d['line']}"
    return "ok" if diag_file["status"] == 0 else f"status {diag_file['status']}"


def run_checks(usina, corpus, rows):
    """Today's outcome of every row: one usina run per (dialect, options) group."""
    groups = collections.defaultdict(list)
    for row in rows:
        groups[(row["dialect"], row["options"])].append(row)
    actual = {}
    for (dialect, _), members in groups.items():
        files = [os.path.join(corpus, r["file"]) for r in members]
        cmd = [usina, "check", "--dialect", dialect, *options_of(members[0]), "--format", "json",
               "--max-errors", "1", "--quiet", *files]
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=600, cwd=HERE)
        try:
            results = json.loads(proc.stdout)["files"]
        except (ValueError, KeyError):
            results = []
        if len(results) != len(files):
            for r in members:
                actual[r["file"]] = f"usage error (status {proc.returncode}): " + \
                    proc.stderr.strip().replace("\n", " ")[:120]
            continue
        for r, res in zip(members, results):
            actual[r["file"]] = outcome_of(res)
    return actual


GUESS = re.compile(r"--dialect auto chose (\S+) \((.*)\) \[N_DIALECT_GUESS\]")


def run_guesses(usina, corpus, rows):
    """Today's --dialect auto guess of every row, with the clue usina gave."""
    groups = collections.defaultdict(list)
    for row in rows:
        groups[row["options"]].append(row)
    guesses = {}
    for options, members in groups.items():
        files = [os.path.join(corpus, r["file"]) for r in members]
        cmd = [usina, "check", "--dialect", "auto", *options_of(members[0]), "--max-errors", "1",
               *files]
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=600, cwd=HERE)
        notes = GUESS.findall(proc.stderr)
        if len(notes) != len(files):  # one note a file, in order; else ask file by file
            notes = []
            for f in files:
                one = subprocess.run([*cmd[:-len(files)], f], capture_output=True, text=True,
                                     cwd=HERE)
                found = GUESS.findall(one.stderr)
                notes.append(found[0] if found else ("?", "no note"))
        for r, note in zip(members, notes):
            guesses[r["file"]] = note
    return guesses


def verdict(got, expect, xfail, today):
    """PASS/FAIL, or for an xfail: XFAIL while usina still gives today's outcome, XPASS when it
    gives the expected one, FAIL when it gives a third one (triage it again)."""
    if xfail == "-":
        return "PASS" if got == expect else "FAIL"
    if got == expect:
        return "XPASS"
    return "XFAIL" if got == today else "FAIL"


def check_corpus(corpus, rows, may_lack):
    """The rows whose file is in the corpus, and what is wrong with it."""
    bad, present = [], []
    for r in rows:
        path = os.path.join(corpus, r["file"])
        if not os.path.exists(path) and r["licence"] in may_lack:
            continue
        try:
            with open(path, "rb") as f:
                digest = hashlib.sha256(f.read()).hexdigest()
        except OSError as e:
            bad.append(f"{r['file']}: {e.strerror}")
            continue
        if digest != r["sha256"]:
            bad.append(f"{r['file']}: sha256 differs from the manifest")
            continue
        present.append(r)
    return present, bad


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("usina")
    ap.add_argument("manifest")
    ap.add_argument("--corpus", action="append", default=[])
    ap.add_argument("--may-lack", action="append", default=[])
    ap.add_argument("--all", action="store_true")
    ap.add_argument("--actual", action="store_true")
    a = ap.parse_args()
    a.usina = os.path.abspath(a.usina)
    corpus = next((os.path.abspath(c) for c in a.corpus if os.path.isdir(c)), None)
    if corpus is None:
        print("programs.wild: skipped: no corpus in " + ", ".join(a.corpus) +
              " (tests/programs/wild/README.md says where it comes from)")
        return SKIP
    listed = read_manifest(a.manifest)
    rows, bad = check_corpus(corpus, listed, set(a.may_lack))
    if bad:
        print(f"corpus {corpus} does not match the manifest:\n  " + "\n  ".join(bad))
        return 1
    if len(rows) < len(listed):
        print(f"{len(listed) - len(rows)} programs of the manifest are not in {corpus}: "
              f"their licence ({', '.join(sorted(set(a.may_lack)))}) keeps them out of it")
    start = time.monotonic()
    actual = run_checks(a.usina, corpus, rows)
    guesses = run_guesses(a.usina, corpus, rows)
    seconds = time.monotonic() - start
    if a.actual:
        for r in rows:
            g, why = guesses[r["file"]]
            print(f"{r['file']}\t{actual[r['file']]}\t{g}\t{why}")
        return 0
    return report(rows, actual, guesses, seconds, corpus, a.all)


def report(rows, actual, guesses, seconds, corpus, show_all):
    counts = collections.Counter()
    lines = []
    for r in rows:
        got = actual[r["file"]]
        v = verdict(got, r["expect"], r["xfail"], r["today"])
        guess, why = guesses[r["file"]]
        g = verdict(guess, r["dialect"], r["auto_xfail"], r["auto_today"])
        counts[v] += 1
        counts["auto " + g] += 1
        if show_all or v in ("FAIL", "XPASS") or g in ("FAIL", "XPASS"):
            lines.append((v, g, r, got, guess, why))
    print(f"{'outcome':7} {'auto':7} {'file':58} {'expected':26} {'today':26} guess (clue)")
    for v, g, r, got, guess, why in lines:
        print(f"{v:7} {g:7} {r['file'][:58]:58} {r['expect'][:26]:26} {got[:26]:26} "
              f"{guess} ({why})")
        if v == "XPASS":
            print(f"        unexpected pass: remove the xfail \"{r['xfail']}\"")
        if v == "FAIL" and r["xfail"] != "-":
            print(f"        xfail outcome changed (was {r['today']}): triage it again")
        if g == "XPASS":
            print(f"        unexpected pass: remove the auto_xfail \"{r['auto_xfail']}\"")
    right = sum(1 for r in rows if guesses[r["file"]][0] == r["dialect"])
    print(f"\n{len(rows)} programs in {corpus}, checked in {seconds:.1f} s")
    print("outcomes: " + ", ".join(f"{counts[k]} {k}" for k in ("PASS", "XFAIL", "FAIL", "XPASS")))
    print(f"--dialect auto: {right}/{len(rows)} right ({100.0 * right / len(rows):.1f} %); " +
          ", ".join(f"{counts['auto ' + k]} {k}" for k in ("PASS", "XFAIL", "FAIL", "XPASS")))
    failed = sum(counts[k] for k in ("FAIL", "XPASS", "auto FAIL", "auto XPASS"))
    print(f"verdicts: {len(rows) * 2 - failed} as expected, {failed} not")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
