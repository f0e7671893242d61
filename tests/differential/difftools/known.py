"""The known-differences file: differences between usina and Debian's rs274
that are understood and listed with their reason.

known_differences.tsv, one difference a line, tab-separated:
  id        a name; known/<id>.ngc is its minimal program
  signature a regular expression the difference's signature must match
            (`trace:arc.center/turn`, `usina-error:E_...`, `lcnc-error:...`)
  site      a regular expression the program line where it shows must
            match (searched, case-insensitive), `.` for any (or none known)
  program   a regular expression the whole program must match, `.` for any
  why       the reason, in words
Lines starting with # are comments."""
import os
import re


class Entry:
    def __init__(self, fields, folder):
        self.id, self.signature, self.site, self.program, self.why = fields
        self.path = os.path.join(folder, 'known', self.id + '.ngc')

    def matches(self, diff, text):
        if not re.fullmatch(self.signature, diff.signature()):
            return False
        lines = text.splitlines()
        site = lines[diff.site - 1] if diff.site and diff.site <= len(lines) else ''
        if self.site != '.' and not re.search(self.site, site, re.I):
            return False
        return self.program == '.' or re.search(self.program, text, re.I | re.S) is not None


def load(path):
    folder = os.path.dirname(os.path.abspath(path))
    entries = []
    for n, line in enumerate(open(path), 1):
        line = line.rstrip('\n')
        if not line.strip() or line.startswith('#'):
            continue
        fields = line.split('\t')
        if len(fields) != 5:
            raise SystemExit(f'{path}:{n}: 5 tab-separated fields expected, got {len(fields)}')
        entries.append(Entry(fields, folder))
    return entries


def explain(entries, diff, text):
    """The entry that lists this difference, or None."""
    for e in entries:
        if e.matches(diff, text):
            return e
    return None
