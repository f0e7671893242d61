#!/usr/bin/env python3
"""Runs every example `usina` command of README.md and docs/*.md as written
(the ctest docs.examples; issue 11: "documented examples must run").

    tests/docs/run_examples.py USINA ROOT [--list] [--file NAME.md]

What is an example: a command that starts with `usina ` (or `build/usina `)
  - on a line of a fenced code block (```, ```sh, ```bash, ```console), a
    line ending in `\\` continued on the next;
  - on a line of an indented code block (4 spaces);
  - in an inline code span (`usina ...`);
  - or as one part of a `cmd && cmd` chain.
What is not (skipped):
  - a synopsis: a command with `[`, `{`, `<`, `|`, `...` or `…` outside
    quotes, or with a placeholder: a single capital letter (`--post P`), or
    a word in capitals that is a file name (`PART.nc`) or stands where a file
    does (`usina check FILE`; after an option, as in `--layer CUT`, a word in
    capitals is a value);
  - a mention: the verb's names only (`usina gen pocket`), or an inline code
    span with fewer than two options (`usina trace --format jsonl` in a
    sentence); an example in a sentence gives its options
    (`usina calc open-loop --pitch 6 --gear-ratio 5 ...`).

Markers, in a shell comment at the end of the command's line:
  `# exit status N`   the command is meant to fail: N is its expected status
                      (e.g. `usina check bad.ngc   # exit status 1: ...`);
  `# not run: WHY`    the command needs what the test does not have (say why).
Without a marker a command must exit 0. Any command killed by a signal, or
not done in 60 s, fails whatever its marker; so does one that uses an old
option name (W_DEPRECATED_OPTION: the docs show the current names).

Where it runs: each .md file in a new temporary folder holding a copy of
examples/ (and every file of examples/ also at the top, so `cover.dxf` and
`examples/cover.dxf` both work), data/ and tests/programs/ (links), build/usina (a
link to the binary under test) and an empty docs/images/; `usina` on the PATH
is the binary under test. A file's commands run in the order written, so an
example may read what an earlier one wrote.
"""
import argparse
import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

TIMEOUT_S = 60
FENCE = re.compile(r"^\s*```\s*([A-Za-z]*)")
SHELL_FENCES = {"", "sh", "bash", "console", "shell"}
INLINE = re.compile(r"`(usina [^`]+|build/usina [^`]+)`")
COMMAND_START = re.compile(r"^(?:\$\s+)?((?:build/)?usina\s.*)$")
PLACEHOLDER = re.compile(r"^[A-Z][A-Z0-9_]*(\.[A-Za-z0-9]+)?$")
EXIT_MARKER = re.compile(r"^exit status (\d+)\b")
NOT_RUN_MARKER = re.compile(r"^not run\b")


class Example:
    def __init__(self, doc, line, command, comment, inline=False):
        self.doc, self.line, self.command, self.comment = doc, line, command, comment
        self.inline = inline

    def where(self):
        return f"{self.doc}:{self.line}"


def split_comment(text):
    """(command, comment): a `#` after a blank and outside quotes starts a comment."""
    quote = None
    for i, c in enumerate(text):
        if quote:
            if c == quote:
                quote = None
        elif c in "\"'":
            quote = c
        elif c == "#" and (i == 0 or text[i - 1] in " \t"):
            return text[:i].rstrip(), text[i + 1:].strip()
    return text.rstrip(), ""


def unquoted(text):
    """The text with quoted parts blanked out."""
    return re.sub(r"\"[^\"]*\"|'[^']*'", '""', text)


def words_of(command):
    try:
        return shlex.split(command)
    except ValueError:
        return None  # unbalanced quotes: not a command


def is_synopsis(command):
    bare = unquoted(command)
    if any(s in bare for s in ("[", "{", "<", "|", "...", "…")):
        return True
    words = words_of(command)
    if words is None:
        return True
    for prev, word in zip(words, words[1:]):
        if not PLACEHOLDER.match(word):
            continue
        if len(word) == 1 or "." in word or not prev.startswith("-"):
            return True
    return False


def is_mention(example):
    words = words_of(example.command) or []
    arguments = [w for w in words[1:] if not re.fullmatch(r"[a-z][a-z0-9-]*", w)]
    if not arguments:
        return True  # `usina gen pocket`: names only
    options = [w for w in words if w.startswith("--")]
    return example.inline and len(options) < 2


def commands_of_line(text):
    """The usina commands of one line of shell (the parts of a && chain)."""
    out = []
    for part in re.split(r"\s&&\s", text):
        m = COMMAND_START.match(part.strip())
        if m:
            out.append(m.group(1).strip())
    return out


def code_lines(lines):
    """(line number, text) of the lines in shell code blocks, continuations joined."""
    fenced, shell, prev_blank = False, False, True
    pending, pending_at = "", 0
    for number, raw in enumerate(lines, 1):
        m = FENCE.match(raw)
        if m:
            fenced, shell = (not fenced), (m.group(1).lower() in SHELL_FENCES)
            continue
        indented = not fenced and raw.startswith("    ") and (prev_blank or pending)
        in_code = (fenced and shell) or indented
        prev_blank = raw.strip() == "" or (prev_blank and indented)
        if not in_code:
            continue
        text = raw.strip()
        if pending:
            text, number = pending + " " + text, pending_at
        if text.endswith("\\"):
            pending, pending_at = text[:-1].rstrip(), number
            continue
        pending = ""
        yield number, text


def examples_of(path, name):
    lines = path.read_text(encoding="utf-8").splitlines()
    found = []
    for number, text in code_lines(lines):
        command, comment = split_comment(text)
        for c in commands_of_line(command):
            found.append(Example(name, number, c, comment))
    fenced = False
    for number, raw in enumerate(lines, 1):
        if FENCE.match(raw):
            fenced = not fenced
            continue
        if fenced or raw.startswith("    "):
            continue
        for m in INLINE.finditer(raw):
            found.append(Example(name, number, m.group(1).strip(), "", inline=True))
    found.sort(key=lambda e: e.line)
    return found


def prepare(folder, root, usina):
    examples = root / "examples"
    shutil.copytree(examples, folder / "examples")
    for f in examples.iterdir():
        if f.is_file():
            shutil.copy(f, folder / f.name)
    # data/ (the materials of usina job) as a link, as the jobs of examples/ find it.
    (folder / "data").symlink_to(root / "data")
    (folder / "tests").mkdir()
    (folder / "tests" / "programs").symlink_to(root / "tests" / "programs")
    (folder / "build").mkdir()
    (folder / "build" / "usina").symlink_to(usina)
    (folder / "bin").mkdir()
    (folder / "bin" / "usina").symlink_to(usina)
    (folder / "docs" / "images").mkdir(parents=True)


def run(example, folder):
    """None when the example behaved as documented, else what went wrong."""
    marker = EXIT_MARKER.match(example.comment)
    expected = int(marker.group(1)) if marker else 0
    env = dict(os.environ, PATH=f"{folder / 'bin'}:{os.environ.get('PATH', '')}")
    try:
        r = subprocess.run(["bash", "-c", example.command], cwd=folder, env=env,
                           capture_output=True, text=True, errors="replace", timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        return f"not done in {TIMEOUT_S} s"
    if r.returncode < 0 or r.returncode >= 128:
        return f"killed by signal {-r.returncode if r.returncode < 0 else r.returncode - 128}" \
               f"\n{r.stderr[-2000:]}"
    if r.returncode != expected:
        return f"exit status {r.returncode}, documented {expected}\n{r.stderr[-2000:]}"
    if "[W_DEPRECATED_OPTION]" in r.stderr:
        return f"an old option name\n{r.stderr[-2000:]}"
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("usina", type=pathlib.Path)
    ap.add_argument("root", type=pathlib.Path)
    ap.add_argument("--list", action="store_true", help="list the examples and the skipped")
    ap.add_argument("--file", help="only this .md file (README.md or docs/NAME.md)")
    args = ap.parse_args()
    root, usina = args.root.resolve(), args.usina.resolve()
    docs = [root / "README.md"] + sorted((root / "docs").glob("*.md"))
    failures, ran, skipped = [], 0, 0
    for doc in docs:
        name = doc.relative_to(root).as_posix()
        if args.file and args.file != name:
            continue
        with tempfile.TemporaryDirectory(prefix="usina_docs_") as tmp:
            folder = pathlib.Path(tmp)
            prepare(folder, root, usina)
            for e in examples_of(doc, name):
                if is_synopsis(e.command) or is_mention(e) or NOT_RUN_MARKER.match(e.comment):
                    skipped += 1
                    if args.list:
                        print(f"skip {e.where()}: {e.command}")
                    continue
                ran += 1
                if args.list:
                    print(f"run  {e.where()}: {e.command}")
                    continue
                problem = run(e, folder)
                if problem:
                    failures.append(f"{e.where()}: {e.command}\n  {problem}")
    for f in failures:
        print(f"FAIL {f}\n")
    print(f"{ran} examples run, {len(failures)} failed, {skipped} synopses, mentions and not "
          "run skipped")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
