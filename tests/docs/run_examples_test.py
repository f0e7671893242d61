#!/usr/bin/env python3
"""The rules of run_examples.py (what is an example, a synopsis, a mention,
a marker) on a small page, so that a change to them is seen (ctest
docs.examples.rules)."""
import pathlib
import sys
import tempfile
import unittest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import run_examples as rx  # noqa: E402

PAGE = """# A page

```
usina gen pocket --rect 60,40 --depth 3 --stepover 2 --post grbl -o p.ngc
usina check FILE
usina draw FILE -o OUT.{dxf,svg} [--view part|toolpath]
usina trace --dialect fanuc PART.nc
usina gen profile --dxf plate.dxf --layer OUTLINE --depth 6 \\
    --post rs274ngc
usina check bad.ngc   # exit status 1: the arc is wrong
usina gen from-dxf --dxf sketch.dxf --post grbl   # not run: made by a script
usina stats --stock-top Z p.ngc
```

```toml
usina = "not shell"
```

Indented:

    build/usina draw a.ngc -o a.svg && build/usina draw a.ngc -o a.dxf

In a sentence, `usina gen pocket` and `usina trace --format jsonl` are
mentions; `usina calc open-loop --pitch 6 --gear-ratio 5 --steps 48` is an
example.
"""


class Rules(unittest.TestCase):
    def setUp(self):
        with tempfile.NamedTemporaryFile("w", suffix=".md", delete=False) as f:
            f.write(PAGE)
        self.examples = rx.examples_of(pathlib.Path(f.name), "page.md")
        self.by_command = {e.command: e for e in self.examples}

    def runs(self, command):
        e = self.by_command[command]
        return not (rx.is_synopsis(e.command) or rx.is_mention(e)
                    or rx.NOT_RUN_MARKER.match(e.comment))

    def test_a_complete_command_in_a_block_is_an_example(self):
        self.assertTrue(self.runs(
            "usina gen pocket --rect 60,40 --depth 3 --stepover 2 --post grbl -o p.ngc"))

    def test_continued_lines_are_one_command(self):
        self.assertTrue(self.runs(
            "usina gen profile --dxf plate.dxf --layer OUTLINE --depth 6 --post rs274ngc"))

    def test_synopses_and_placeholders_are_skipped(self):
        for c in ("usina check FILE", "usina draw FILE -o OUT.{dxf,svg} [--view part|toolpath]",
                  "usina trace --dialect fanuc PART.nc", "usina stats --stock-top Z p.ngc"):
            self.assertFalse(self.runs(c), c)

    def test_a_capital_value_of_an_option_is_not_a_placeholder(self):
        self.assertFalse(rx.is_synopsis("usina gen pocket --dxf c.dxf --layer POCKET"))

    def test_markers(self):
        bad = self.by_command["usina check bad.ngc"]
        self.assertEqual(rx.EXIT_MARKER.match(bad.comment).group(1), "1")
        self.assertFalse(self.runs("usina gen from-dxf --dxf sketch.dxf --post grbl"))

    def test_chains_and_indented_blocks(self):
        self.assertTrue(self.runs("build/usina draw a.ngc -o a.svg"))
        self.assertTrue(self.runs("build/usina draw a.ngc -o a.dxf"))

    def test_inline_spans_need_two_options(self):
        self.assertFalse(self.runs("usina gen pocket"))
        self.assertFalse(self.runs("usina trace --format jsonl"))
        self.assertTrue(self.runs("usina calc open-loop --pitch 6 --gear-ratio 5 --steps 48"))

    def test_other_languages_are_not_shell(self):
        self.assertNotIn('usina = "not shell"', self.by_command)


if __name__ == "__main__":
    unittest.main()
