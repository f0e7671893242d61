#!/usr/bin/env python3
"""Fails when a fuzz target's work grows faster than its input.

    scaling.py FUZZER SEED_DIR [--timeout SECONDS]

For every family of SEED_DIR (files <family>.full.* and <family>.quarter.*,
written by long_seeds.py) the fuzzer runs each file once, and the CPU time
of the full one is compared with four times the quarter's: linear work keeps
the ratio near 1, quadratic work makes it 4. CPU time (user + system of the
child) rather than wall time, and a ratio rather than a limit in seconds, so
the check holds on a loaded machine, under ASan, on a slow or a fast one.
The startup of the fuzzer (an empty input) is subtracted first, and a full
run under MIN_SECONDS always passes (too short to judge, and fast anyway).
A run that does not end within --timeout seconds (wall) fails, and a full run
is stopped as soon as its CPU time has failed the ratio, so a quadratic case
costs seconds, not minutes. A family over the ratio is measured again (up to
ATTEMPTS times, the least CPU time of each size kept), since other work on the
machine only ever inflates a run's CPU time.

Prints one line per family; exits 1 when a family fails.
"""
import os
import subprocess
import sys
import tempfile
import time

# Full / (4 × quarter): 1 for linear work, 4 for quadratic. 2 leaves room
# for noise and n log n (1.2 here).
MAX_RATIO = 2.0
# The quarter's time is taken as at least this, so tiny runs do not judge.
MIN_QUARTER_SECONDS = 0.05
MIN_SECONDS = 0.5
# Measurements of a family before it fails (see judge).
ATTEMPTS = 3


def cpu_of(pid):
    """CPU seconds (user + system) a running process has used so far."""
    try:
        with open("/proc/%d/stat" % pid) as f:
            fields = f.read().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
    except (OSError, IndexError, ValueError):
        return 0.0


def run(fuzzer, path, timeout, cpu_limit=None):
    """CPU seconds of one run of `fuzzer` on `path`, measured through os.wait4;
    None (and a line saying why) when it fails, does not end within `timeout`
    seconds or uses more than `cpu_limit` seconds of CPU."""
    start = time.monotonic()
    name = os.path.basename(path)
    with tempfile.TemporaryFile() as log:
        proc = subprocess.Popen([fuzzer, "-timeout=%d" % timeout, "-rss_limit_mb=2048", path],
                                stdout=log, stderr=subprocess.STDOUT)
        while True:
            pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
            if pid != 0:
                break
            why = None
            if time.monotonic() - start > timeout + 30:
                why = "no end after %.0f s" % (time.monotonic() - start)
            elif cpu_limit is not None and cpu_of(proc.pid) > cpu_limit:
                why = "over %.1f s of CPU, stopped" % cpu_limit
            if why:
                proc.kill()
                os.wait4(proc.pid, 0)
                print("    %s: %s" % (name, why))
                return None
            time.sleep(0.02)
        code = os.waitstatus_to_exitcode(status)
        if code != 0:
            log.seek(0)
            lines = [l for l in log.read().decode(errors="replace").splitlines()
                     if "ERROR" in l or "SUMMARY" in l]
            print("    %s: exit %d %s" % (name, code, " | ".join(lines[:3])))
            return None
        return usage.ru_utime + usage.ru_stime


def families(seed_dir):
    names = sorted(os.listdir(seed_dir))
    for name in names:
        family, label, ext = name.split(".", 2)
        if label == "full":
            quarter = "%s.quarter.%s" % (family, ext)
            if quarter in names:
                yield family, os.path.join(seed_dir, name), os.path.join(seed_dir, quarter)


def judge(fuzzer, base, full, quarter, timeout):
    """(ok, full seconds, quarter seconds, ratio) of one family, or None when a
    run fails. A ratio over MAX_RATIO is measured again, up to ATTEMPTS times,
    keeping the least CPU time of each size: other processes on the machine
    inflate the CPU time of a run (shared caches, memory bandwidth), never
    deflate it, so the least time is the truest. Quadratic work fails every
    attempt; one unlucky run does not."""
    tq = tf = None
    for _ in range(ATTEMPTS):
        q = run(fuzzer, quarter, timeout)
        if q is None:
            return None
        tq = q if tq is None else min(tq, q)
        # The full run is stopped as soon as it has failed the ratio.
        limit = base + max(MIN_SECONDS, 4 * MAX_RATIO * max(tq - base, MIN_QUARTER_SECONDS)) + 1
        f = run(fuzzer, full, timeout, limit)
        if f is not None:
            tf = f if tf is None else min(tf, f)
        if tf is None:
            continue
        fs = max(tf - base, 0.0)
        ratio = fs / (4 * max(tq - base, MIN_QUARTER_SECONDS))
        if fs < MIN_SECONDS or ratio <= MAX_RATIO:
            return True, fs, tq, ratio
    if tf is None:
        return None
    return False, fs, tq, ratio


def main():
    args = sys.argv[1:]
    timeout = 120
    if "--timeout" in args:
        i = args.index("--timeout")
        timeout = int(args[i + 1])
        del args[i:i + 2]
    if len(args) != 2:
        sys.exit(__doc__)
    fuzzer, seed_dir = args
    target = os.path.basename(fuzzer)
    with tempfile.NamedTemporaryFile() as empty:
        base = run(fuzzer, empty.name, timeout)
    if base is None:
        print("scaling FAIL %s: the fuzzer does not run on an empty input" % target)
        return 1
    failed = False
    for family, full, quarter in families(seed_dir):
        verdict = judge(fuzzer, base, full, quarter, timeout)
        if verdict is None:
            print("scaling FAIL %s %s (%d KB)" % (target, family, os.path.getsize(full) // 1024))
            failed = True
            continue
        ok, f, tq, ratio = verdict
        print("scaling %s %s %s: %.2f s for %d KB, %.2f s for a quarter (ratio %.1f)" % (
            "ok  " if ok else "FAIL", target, family, f, os.path.getsize(full) // 1024, tq - base,
            ratio))
        failed = failed or not ok
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
