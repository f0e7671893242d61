#!/usr/bin/env python3
"""Writes docs/errors.md, the catalogue of usina's diagnostic codes, from
src/core/diagnostic_codes.hpp (the X-macro list: the stable names and their
order) and the explanations below (what a code means, what to do). Where a
code is reported, and the messages it is reported with, are read from src/.

    scripts/gen_errors_doc.py [--root ROOT]     writes ROOT/docs/errors.md
    scripts/gen_errors_doc.py --check           exit 1 when docs/errors.md lacks a code
                                                or a code has no explanation (a ctest)

A new code in diagnostic_codes.hpp needs an entry in EXPLAIN here; --check
says which.
"""
import argparse
import pathlib
import re
import sys

# Stable name -> (what it means, what to do). Written from where each code is
# reported in src/ (grep the enumerator).
EXPLAIN = {
    # input and limits
    "E_FILE_NOT_FOUND": (
        "A file usina was asked to read (the program, a tool table, a parameter file or a "
        "subroutine file) does not exist or cannot be read.",
        "Check the path and the file's permissions; a subroutine file must be `<name>.ngc` "
        "in a folder of `--subroutine-path` or the program's own folder."),
    "E_FILE_TOO_LARGE": (
        "A file is larger than usina accepts, a limit that keeps hostile input finite.",
        "Split the program into a main program and subroutine files."),
    "W_NO_PROGRAM_END": (
        "The program ends without `M2`, `M30` or a closing `%`. usina takes the end of the "
        "file as the end of the program (most CAM and Grbl files do this); LinuxCNC reports "
        "an error instead.",
        "Add `M2` or `M30` as the last block if the program is to run on LinuxCNC."),
    "W_BYTE_ORDER_MARK": (
        "The file starts with a UTF-8 byte-order mark (written by some Windows editors). "
        "usina skips it in every dialect, with this warning (one rule: the program's meaning is "
        "plain); LinuxCNC rejects such a file and a Fanuc control may alarm on the bytes, while "
        "Grbl drops them.",
        "Save the file as plain ASCII or UTF-8 without a byte-order mark."),
    "W_TEXT_AFTER_END": (
        "There is text after the end of the program (`M2`, `M30` or the closing `%`); it is "
        "never run.",
        "Delete it, or move it before the program's end if it was meant to run."),
    # lexer and parser
    "E_UNEXPECTED_CHARACTER": (
        "A character that cannot stand where it is: a letter that is not a word of the "
        "dialect, punctuation outside a comment, or a byte that is not printable ASCII "
        "(often a typographic quote, a degree sign or a tab pasted from a word processor).",
        "Correct the typo, or put the text inside a `( )` comment."),
    "E_BAD_NUMBER": (
        "A number without digits (`X.`, `X-`), or an `N` word with no line number after it.",
        "Write the digits: `X0.`, `X-1`, `N10`."),
    "E_UNCLOSED_COMMENT": (
        "A `(` comment is not closed with `)` on the same line; an RS274NGC comment cannot "
        "span lines and cannot nest.",
        "Close the comment before the end of the line, or use `;` for a comment that runs to "
        "the end of the line."),
    "E_UNCLOSED_BRACKET": (
        "An expression's `[` has no matching `]`, or something other than an operator "
        "follows a value inside the brackets (`[1 2]`).",
        "Balance the brackets and put a binary operator (`+ - * / ** MOD AND OR XOR EQ NE "
        "GT GE LT LE`) between values."),
    "E_EXPECTED_EXPRESSION": (
        "A value is missing where one is needed: a word letter at the end of the block, an "
        "operator with nothing after it, `EXISTS` without a parameter; or expressions nest "
        "more than 64 deep.",
        "Give the value (`X10`, `[#1 + 2]`); simplify an expression nested too deep by "
        "assigning parts to parameters."),
    "E_UNKNOWN_FUNCTION": (
        "Letters before `[` (or where a value should be) that are not one of RS274NGC's "
        "functions: `ABS ACOS ASIN ATAN COS EXISTS EXP FIX FUP LN ROUND SIN SQRT TAN`.",
        "Correct the spelling; `ATAN` takes two arguments, `ATAN[y]/[x]`; a value needs "
        "digits or `#`."),
    "E_BAD_PARAMETER_NAME": (
        "A named parameter `#<...>` is empty, not closed with `>`, or holds a character "
        "names may not contain.",
        "Write it as `#<name>` with letters, digits and `_` (a leading `_` makes it global)."),
    "E_BAD_O_WORD": (
        "An O-word statement that cannot be read: `o` with neither a number nor `<name>`, "
        "a missing or unknown keyword, a call with more than 30 arguments, or an O-word "
        "statement after other text on the line.",
        "Write one statement a line, e.g. `o100 if [#1 GT 0]`, `o<pocket> call [10] [2]`; "
        "the keywords are sub, endsub, call, return, if, elseif, else, endif, while, "
        "endwhile, do, repeat, endrepeat, break, continue."),
    "E_MISPLACED_O_WORD": (
        "An O-word statement that does not start its block, or that has other words "
        "(G, M, axes) in the same block.",
        "Put the O-word statement at the start of its own line, with only its expression "
        "or arguments and comments."),
    "E_UNKNOWN_WORD": (
        "A word the dialect does not have, or one in a place it may not be: a line number "
        "`N` must start the block.",
        "Move `N` to the start of the block, or remove the word."),
    # expressions and parameters
    "E_DIVISION_BY_ZERO": (
        "An expression divides by zero, with `/` or `MOD`.",
        "Check the divisor; an unset numbered parameter reads as 0, so a typo in its number "
        "is the usual cause."),
    "E_DOMAIN_ERROR": (
        "A function's argument is outside its domain: `ASIN`/`ACOS` of a value beyond -1..1, "
        "`LN` of a value that is not positive, `SQRT` of a negative value, or a negative "
        "base raised to a non-integer power with `**`.",
        "Check the computed argument (the message gives it); a value just beyond 1 from "
        "rounding can be clamped with a comparison first."),
    "E_PARAMETER_OUT_OF_RANGE": (
        "A numbered parameter `#n` whose number is not an integer from 1 to 5602.",
        "Use a number within 1..5602, or a named parameter `#<name>`."),
    "E_READ_ONLY_PARAMETER": (
        "An assignment to a predefined parameter the interpreter maintains, such as "
        "`#<_x>` (the current position) or the other read-only `#<_...>` names.",
        "Assign to a parameter of your own instead (`#<x_saved> = #<_x>`)."),
    "E_UNDEFINED_PARAMETER": (
        "A named parameter is read before any value was assigned to it (named parameters, "
        "unlike numbered ones, have no default).",
        "Assign it first, or test it with `EXISTS[#<name>]`; a local name set in one "
        "subroutine is not visible in another: use a global `#<_name>`."),
    "E_NUMBER_OUT_OF_RANGE": (
        "A value is infinite or not a number (overflow in an expression, `EXP` of a large "
        "value, a number too long to represent), or a number is written with an exponent "
        "beyond what a double holds (`1e400`, `1e-400`; no dialect has exponents, so `1e3` "
        "reads as 1 and a word `E3`).",
        "Check the arithmetic that produced it; the message gives the value."),
    "E_BAD_VAR_FILE": (
        "A line of the parameter file given with `--var-file` cannot be used: the number is "
        "not an integer or out of range, the value is not a finite number, a parameter "
        "appears twice, or the numbers do not ascend as LinuxCNC requires. Lines LinuxCNC "
        "skips are warnings of their own (`W_VAR_FILE_LINE_SKIPPED`, `W_VAR_FILE_EXTRA_TEXT`).",
        "Correct the line shown; each line is `<number> <value>`, in ascending order of "
        "number."),
    # control flow
    "E_UNKNOWN_SUBROUTINE": (
        "`o<name> call` names a subroutine that is neither defined in the program (`o<name> "
        "sub`) nor found as `<name>.ngc` on the subroutine path; or `M98 P` names a program "
        "number with no `O` block in the file.",
        "Define the subroutine, or give its folder with `--subroutine-path DIR:DIR`. A name "
        "that cannot be a file name at all is `E_BAD_SUBROUTINE_NAME`."),
    "E_UNCLOSED_CONTROL_BLOCK": (
        "A control block is not closed: `sub` without `endsub`, `if` without `endif`, "
        "`while` without `endwhile`, `repeat` without `endrepeat`, `do` without its "
        "`while`, `break`/`continue` outside a loop, or the end of the file inside a called "
        "subroutine.",
        "Add the closing statement with the same O-number or name (`o100 endif` closes "
        "`o100 if`)."),
    "E_UNMATCHED_CONTROL": (
        "A closing or middle statement (`endwhile`, `endrepeat`, `else`, `endsub`, "
        "`return`) with no matching opening statement, or `return`/`endsub` reached "
        "outside a subroutine call.",
        "Check that the O-numbers of the opening and closing statements agree, and that "
        "the main program does not run into a subroutine's body."),
    "E_RECURSION_TOO_DEEP": (
        "Subroutine calls (`o<name> call` or `M98`) nest deeper than the control allows: "
        "9 calls in rs274ngc (LinuxCNC's ten levels, the main program counted: \"Too many "
        "subroutine levels\"), 4 macro levels or 10 calls in fanuc, 200 elsewhere; most "
        "often a recursion that never stops.",
        "Give the recursion a condition that ends it, or unroll levels into a loop."),
    "E_TOO_MANY_ITERATIONS": (
        "A loop ran more times than `--max-iterations` allows (10,000,000 by default), or a "
        "canned cycle would repeat (`L`) or peck (`Q`) more times than usina accepts, or "
        "`G76` would make too many passes: the limits that keep a runaway program finite.",
        "Check that the loop's condition changes inside the loop; if the program really "
        "needs more, raise the limit with `--max-iterations N`; for a cycle, increase the "
        "peck depth or lower `L`."),
    "E_BAD_SUBROUTINE_NAME": (
        "A subroutine called by name (`o<name> call`) is not in the program, and its name "
        "cannot be the file `<name>.ngc` on the subroutine path: it contains a path separator "
        "(`/`, or `\\` as on Windows), starts with `.` (`..`, hidden files), holds a control "
        "byte such as NUL, or is longer than a file name may be. usina never expands names "
        "through a shell, as LinuxCNC's `wordexp` does.",
        "Use a plain name of letters, digits and `_`."),
    "E_DUPLICATE_SUBROUTINE": (
        "Two subroutines of one program have the same name.",
        "Rename one of them; names are compared in lower case without blanks."),
    # block checks
    "E_MODAL_GROUP_CONFLICT": (
        "Two codes of the same modal group in one block, e.g. `G0 G1`, `G90 G91` or `M3 M4` "
        "(RS274NGC allows one code a group a block), or too many user M codes in one block.",
        "Keep one of them, or split the block in two in the order you meant."),
    "E_REPEATED_WORD": (
        "The same word letter twice in one block, e.g. `X1 X2`.",
        "Keep one of them."),
    "E_UNKNOWN_G_CODE": (
        "A G number that is not a code of the dialect, is negative, or is not a multiple of "
        "0.1.",
        "Check the number against the dialect's G codes (for rs274ngc, LinuxCNC's "
        "G-code reference)."),
    "E_UNKNOWN_M_CODE": (
        "An M number that is not a code of the dialect, or is not an integer.",
        "Check the number; user M codes M100-M199 are accepted and traced as comments."),
    "E_UNUSED_WORD": (
        "A word that no code of the block uses, e.g. `R` with `G1` or `P` with `G0`. "
        "LinuxCNC refuses such a block rather than ignoring the word, and so does usina.",
        "Remove the word, or add the code that was meant to use it (the message lists "
        "which codes use it)."),
    "E_MISSING_WORD": (
        "A code lacks a word it needs: `G4` without `P`, `G10` without `L` or `P`, `G92` "
        "without an axis word, `M61` without `Q`, `M6` with no tool selected by `T`, "
        "`M98` without `P`.",
        "Add the word the message names."),
    "E_BAD_WORD_VALUE": (
        "A word's value is not allowed: a negative feed `F` or speed `S`, a `T` that is not "
        "a tool number, arc turns `P` that are not a positive integer, a `G10` `L`/`P` out "
        "of range.",
        "Correct the value; the message gives it."),
    "E_AXIS_WORDS_CONFLICT": (
        "Axis words that two codes of the block both want (e.g. `G0` with `G92`, `G10` or "
        "`G28`), axis words with `G80` and no motion, or polar words `@ ^` with `X`/`Y`.",
        "Split the block so each code has its own axis words, or give a motion code."),
    "E_NO_FEED_RATE": (
        "A feed move (`G1`, `G2`, `G3`, a canned cycle, a spline, a probe) with no feed rate "
        "set; or, in inverse-time mode `G93`, a feed move without its own `F`.",
        "Give `F` in the block or before it; in `G93` every feed move needs `F`."),
    "E_NOT_ALLOWED_IN_MODE": (
        "A code that the current modal state forbids: polar words or splines outside the "
        "XY plane `G17`, a spline with cutter compensation on, `M72` with no state saved by "
        "`M70`, `M73` outside a subroutine.",
        "Change the mode first (`G17`, `G40`), or move the code where it is allowed."),
    # arcs
    "E_ARC_RADIUS_MISMATCH": (
        "An arc given by its centre (`I J K`) whose end point is not on the circle: the "
        "distances from the centre to the start and to the end differ by more than "
        "LinuxCNC's tolerance (about 0.028 mm, or 0.1 % of the radius).",
        "Correct `I`/`J`/`K` or the end point (remember `I J K` are incremental from the "
        "start unless `G90.1`), or give the arc by its radius `R`."),
    "E_ARC_RADIUS_TOO_SMALL": (
        "An `R` arc whose radius is smaller than half the distance from its start to its "
        "end, so no such circle exists. In rs274ngc, as in LinuxCNC, half the chord may "
        "exceed the radius by 0.00005 in (0.00127 mm): the arc is then a half circle.",
        "Increase `R` or correct the end point; the message gives the half chord."),
    "E_ARC_MISSING_CENTER": (
        "`G2`/`G3` with neither `R` nor a centre word of the plane (`I J` in G17, `I K` in "
        "G18, `J K` in G19), or with both `R` and centre words.",
        "Give either `R` or the centre words of the active plane."),
    "E_ARC_ZERO_LENGTH": (
        "An `R` arc that ends where it starts (a full circle cannot be given by `R`), or "
        "an arc whose centre is at its start point (zero radius). In rs274ngc, as in "
        "LinuxCNC, an `I J K` arc whose centre is within 0.00005 in (0.00127 mm) of its "
        "start or its end.",
        "Give a full circle with `I`/`J`/`K`; check the centre words."),
    # cutter compensation and tools
    "E_CUTTER_GOUGE": (
        "With cutter radius compensation (`G41`/`G42`) the tool does not fit a concave "
        "corner or a move of the contour: following it would cut into the part.",
        "Use a smaller tool (or tool radius `D`), or change the contour so the tool fits."),
    "E_COMP_ENTRY_MOVE": (
        "The first move after `G41`/`G42` (the entry move) is not longer than the tool "
        "radius, so the compensated path cannot be built.",
        "Start the entry move farther from the contour than the tool radius."),
    "E_COMP_TOOL_TOO_BIG": (
        "Under cutter compensation, an arc whose radius is not larger than the tool radius "
        "with the tool on its inside.",
        "Use a smaller tool or a larger arc."),
    "E_COMP_NOT_ALLOWED": (
        "`G41`/`G42` while compensation is already on, in the YZ plane `G19`, or with a "
        "side that is neither left nor right.",
        "Program `G40` before changing the side; use `G17` or `G18`."),
    "E_UNKNOWN_TOOL": (
        "A tool number (`H` for `G43`, `D` for `G41`/`G42`, or the loaded tool) is not in "
        "the tool table given with `--tool-table`. Without `--tool-table` every tool number "
        "is a tool of unknown length and diameter, taken as 0 (docs/rs274ngc.md, \"Tools\").",
        "Add the tool to the table given with `--tool-table`, or correct `H`/`D`."),
    "E_BAD_MACHINE_PROFILE": (
        "The machine profile given with `--machine` cannot be used: it is not valid TOML, a "
        "required key is missing, a value has the wrong type, or a number is out of range "
        "(a negative rapid rate, min above max, units other than mm or inch).",
        "Correct the key named in the message; `examples/machines/` has complete profiles to "
        "start from."),
    # cam generators
    "E_DXF_UNREADABLE": (
        "The drawing given to `usina gen` cannot be opened or read (a missing file, a folder, "
        "no permission), is larger than 64 MiB, is empty, or is not a text file (a NUL byte, "
        "a binary DXF).",
        "Check the path; save the drawing from the CAD program as ASCII DXF (R12 or later)."),
    "E_MISPLACED_PERCENT": (
        "A `%` line where the rs274ngc dialect cannot take it. As in LinuxCNC, `%` alone on "
        "the program's first line (blank lines before it allowed) opens the program and the "
        "next `%` line ends it; a `%` anywhere else — in the middle of a program that did not "
        "open with `%`, in a subroutine, or with other text on its line (`%(name)`, `/%`) — "
        "is an error where it stands, after the blocks before it have run. A program that "
        "ran on for thousands of lines no longer stops there silently.",
        "Remove the `%` line if it was pasted in by mistake (two files joined), or put a `%` "
        "on the first line if the program is meant to stop there; give `%` a line of its own."),
    "W_UNOPENED_PERCENT": (
        "The program's last line with anything on it is a `%`, but the program did not open "
        "with one. usina takes it as the end of the program (nothing follows it); LinuxCNC "
        "runs the program, then reports an error (\"Bad character '%' used\").",
        "Add a `%` as the first line, or remove the last one, if the program is to run on "
        "LinuxCNC."),
    # apt (issue 15): APT part programs (docs/apt.md)
    "E_APT_SYNTAX": (
        "An APT statement is not written the way APT writes statements: a character APT does "
        "not have, a missing `,` or `)`, a statement that does not begin with a word, a "
        "vocabulary word used as a name, or a malformed `SYN`. The statement is left out and "
        "the processor goes on with the next one, so one run reports every error.",
        "Correct the statement at the caret; docs/apt.md shows the statement forms."),
    "E_APT_UNDEFINED_SYMBOL": (
        "A name that nothing defined before this statement, or a function APT does not have "
        "(IBM APT's error 101, undefined symbol).",
        "Define the name (a scalar `A=3` or a geometry `P1=POINT/1,2`) before the statement "
        "that uses it, or correct its spelling; the message lists the functions."),
    "E_APT_UNKNOWN_FORM": (
        "A POINT, LINE, CIRCLE, PLANE or VECTOR definition whose arguments match none of the "
        "forms of that word (IBM APT's error 1000, method of definition unknown): a LINE from "
        "a point and a circle without LEFT/RIGHT and TANTO, a CIRCLE with two numbers, ... The "
        "message lists the kinds of the arguments given.",
        "Write the definition in one of the forms of docs/apt.md (the IBM manual's forms)."),
    "E_APT_NO_SOLUTION": (
        "A definition has the right form but no solution (IBM APT's error 1005, calculation "
        "failed): lines that do not meet, a line that misses the circle it should cut, a "
        "circle through three points on one line, a tangent from a point inside the circle, "
        "a radius of 0 or less, a selector (XLARGE, YSMALL...) along which the line has no "
        "side.",
        "Check the geometry the definition refers to; the message says which condition fails."),
    "E_APT_ARITHMETIC": (
        "An expression has no finite value: a division by zero, SQRTF of a negative number, "
        "LOGF of 0, ASINF of a number beyond 1, a power that overflows.",
        "Correct the expression or the scalars in it."),
    "E_APT_BAD_ARGUMENT": (
        "A statement has the wrong kind or number of arguments: GOTO without a point, "
        "CUTTER with a word, a geometry name in an expression or a post-processor word, a "
        "function given too many values, a modal word (TLLFT, NOPS) with arguments.",
        "Give the statement the arguments the message names."),
    "E_APT_NOT_SUPPORTED": (
        "The statement is APT, but usina's APT does not run it yet: contouring on 3D surfaces "
        "(a part surface that is not horizontal, a drive or check surface that is not a line, "
        "circle or vertical plane), GOUP/GODOWN with PAST, several check surfaces with branch "
        "labels, a few definition forms (PATERN GRID, CONST), the geometry functions "
        "(DISTF...), a feed rate after a GOTO's point, and statements of the language usina "
        "does not know (MACRO, LOOPST, ...). The statement is left out, never skipped in "
        "silence.",
        "See docs/apt.md for what this version runs; write the motion in the 2.5D forms it "
        "lists, or with GOTO points."),
    "W_APT_NO_FINI": (
        "The APT program has no FINI statement; the processor takes its end as FINI and "
        "writes no FINI record.",
        "End the program with FINI."),
    # CL files (issue 15): binary CLDATA, NX CLSF, APT CL (docs/apt.md)
    "E_CL_BAD_RECORD": (
        "A binary CLDATA file breaks the record layout of docs/apt.md: it ends inside a record, "
        "a record is numbered out of order, holds more than 4,096 words, or a real word is "
        "not finite or beyond 1e12. The location's line is the record's number. Reading stops "
        "there; what came before is used. In an NX CLSF or APT CL text file, a statement whose "
        "record would hold more than 4,096 words (a `PARTNO/`, `PPRINT/` or `INSERT/` text of "
        "more than 24,576 characters) is this error at its line, since CLDATA could not hold "
        "it: the statement is left out and reading goes on.",
        "Check that the file is CLDATA as usina writes it (`usina apt --format cldata`) and was "
        "copied whole, as bytes."),
    "E_CL_BAD_ARGUMENT": (
        "A CL statement has the wrong kind or number of arguments: GOTO without x,y,z, "
        "CIRCLE without its centre and axis, GODLTA before any position, a CYCLE with no feed "
        "rate, UNITS that is not MM or INCHES, a LOADTL whose tool number is not a whole "
        "number from 0 to 999999. The statement is left out and reading goes on.",
        "Give the statement the arguments the message names."),
    "E_CL_BAD_ARC": (
        "A CIRCLE of a CL file cannot be cut: the GOTO after it ends off the circle, the "
        "start is off it (beyond 0.002 or 0.1 % of the radius), the circle comes before any "
        "position, or no GOTO follows it. The move is taken straight (or the circle left out), "
        "so the path goes on.",
        "Check the CL file against the CAM system's output and the dialect: `--from clsf` for "
        "NX (a +k axis runs clockwise), `--from aptcl` for SolidWorks CAM and Creo."),
    "E_CL_NOT_SUPPORTED": (
        "The CL statement is one usina does not turn into motion: a multi-axis GOTO (a tool "
        "axis other than +Z), a NURBS spline. The statement is left out, never skipped in "
        "silence.",
        "Post the operation as 3-axis, or with lines and circles instead of splines."),
    "E_CL_TOO_LARGE": (
        "A CL statement is beyond the limits that keep hostile input finite: longer than "
        "64 KiB with its continuations, more than 1,024 arguments, a number beyond 1e12 or out "
        "of range.",
        "Split the statement; check the file is a CL file."),
    "W_CL_IGNORED": (
        "A CL file's statement whose major word usina does not know (neither a motion nor "
        "a word of the IBM vocabulary nor one of the display words it skips). It is left out.",
        "Nothing, if the word does not move the tool; otherwise report it with a sample."),
    "E_DXF_MALFORMED": (
        "The drawing's lines are not a DXF file's groups: a group code that is not a whole "
        "number, a value line missing at the end, a line longer than 1,023 characters, no "
        "`0`/`EOF` group at the end (the file is cut short), or a count that does not match "
        "what follows it (LWPOLYLINE vertices, group 90; SPLINE knots, control points and fit "
        "points, groups 72, 73 and 74; LEADER vertices, group 76). The message gives the line.",
        "Save the drawing again from the CAD program as ASCII DXF; if it was copied or "
        "downloaded, check that the copy is complete."),
    "E_DXF_NO_ENTITIES": (
        "The drawing has no LINE, ARC, CIRCLE, POLYLINE, LWPOLYLINE or SPLINE to cut, on the "
        "layer chosen with `--layer` or at all (only text, hatches, blocks or ellipses).",
        "Check the layer's name (`--layer`), or draw the contour with lines, arcs or "
        "polylines; explode blocks before saving."),
    "W_DXF_UNSUPPORTED": (
        "An entity of the drawing is not a contour usina can cut (POINT, ELLIPSE, TEXT, MTEXT, "
        "INSERT, HATCH, SOLID, ...), or a SPLINE or polyline whose data do not make a curve; it "
        "is left out of the program. A SPLINE given by fit points only is cut through them as "
        "straight segments.",
        "Convert the entity to polylines or arcs in the CAD program, explode block "
        "references, or move it to a layer the program does not read."),
    "E_GEN_BAD_VALUE": (
        "A value given to a generator is outside its documented range (docs/gen.md, "
        "\"Ranges\": a length above 0 and at most 100,000 mm, a tool diameter from 0.001 to "
        "1000 mm, a feed or a spindle speed above 0 and at most 1,000,000, a resolution or "
        "tolerance from 0.0001 mm), or values that do not go together: a stepover above the "
        "tool diameter, tabs as high as the cut is deep or too many for the contour, a lead arc "
        "that does not fit inside the contour, an R plane above the safe Z, a grid spacing of 0, "
        "a text of spaces only.",
        "Give the value the message asks for; it says the range."),
    "E_GEN_TOOL_TOO_BIG": (
        "The tool does not fit: a pocket narrower than the tool, or a contour whose offset by "
        "the tool radius vanishes on the side asked for.",
        "Use a smaller tool, or cut the contour on the other side."),
    "E_GEN_OPEN_OUTLINE": (
        "A pocket's outline or island, or a contour to be cut inside or outside, is not closed: "
        "its ends are more than 0.01 mm apart after chaining.",
        "Close the contour in the drawing (join its ends), or cut an open contour with `--side "
        "left` or `right`."),
    "E_FONT_UNREADABLE": (
        "The Hershey font for `usina gen engrave` cannot be opened or is not in the .jhf "
        "format (5-column glyph number, 3-column pair count, the pairs).",
        "Install hershey-fonts-data, or name a font of /usr/share/hershey-fonts (`--font "
        "rowmans`) or a .jhf file."),
    "E_TEXT_NOT_IN_FONT": (
        "The text to engrave is empty or has a character the font has no glyph for: the fonts "
        "draw printable ASCII, from the space to `~` (no accented letters, tabs or line ends).",
        "Write the text in plain ASCII (\"Sao Paulo\" for \"São Paulo\")."),
    "E_BAD_TOOL_TABLE": (
        "A line of the tool table given with `--tool-table` cannot be used (no `T` word, a "
        "value that is not a number or too large, an unknown letter), or a value is out of its "
        "range: the diameter `D` from 0 (not known) to 1000 mm, the offsets `X Y Z U V W` "
        "within ±10000 mm, the angles `A B C I J` within ±360°, the orientation `Q` 0 to 9 "
        "(NaN and infinity are never numbers). The line is skipped. Defects usina can read "
        "past are warnings of their own (`W_TOOL_WITHOUT_POCKET`, `W_TOOL_REDEFINED`).",
        "Correct the line shown; the format is LinuxCNC's, e.g. `T1 P1 D6.0 Z+10.0 ;end "
        "mill`."),
    # canned cycles and probing
    "E_CYCLE_BAD_VALUE": (
        "A canned cycle value that cannot work: a peck depth `Q` of 0 or less, a retract "
        "plane `R` below the bottom of the hole, `G76` with `I0`, an incremental polar step "
        "from the origin.",
        "Correct the value the message names."),
    "E_PROBE_BAD_MOVE": (
        "A probing move `G38.2`-`G38.5` that is not allowed, e.g. with cutter compensation "
        "on.",
        "Turn compensation off (`G40`) before probing."),
    "E_SPLINE_BAD_VALUE": (
        "A spline block `G5`, `G5.1` or `G5.2` with values that do not define a curve: "
        "control points or weights missing or out of range, an order `L` the points do not "
        "support, knots that decrease, or axis words other than X and Y.",
        "Correct the words the message names (see LinuxCNC's G5 reference)."),
    # operator messages
    "N_MESSAGE": (
        "An operator message from a `(MSG, ...)` comment, shown as a note. Not a problem.",
        "Nothing; it is what the program tells the operator."),
    "E_UNSUPPORTED": (
        "The program uses a feature usina does not implement yet (e.g. LinuxCNC's lathe "
        "roughing cycles `G71`/`G72`).",
        "Rewrite the part without it, or report the program so the feature gets priority."),
    # program checks (usina stats)
    "W_OVERTRAVEL": (
        "`usina stats`: a move takes an axis beyond the travel limits of the machine profile "
        "(`min`/`max` of `[axes.x]` ...), by the amount the message gives. Arcs are checked "
        "by their true extent, not only their end points. The program is placed on the "
        "machine by `--work-zero X,Y,Z` (machine coordinates of program zero) or by the "
        "offsets of `--var-file`; with neither, the message says instead that an axis's moves "
        "span more than its travel (reported once per axis). Reported at the first move of "
        "each excursion.",
        "Check the work zero, the machine profile, or move the part."),
    "W_FEED_WITHOUT_RATE": (
        "`usina stats`: a feed move has no feed rate: feed per revolution `G95` with the "
        "spindle stopped (a `G93` move's rate is its length over its time, and a `G95` "
        "move's is F × rpm). It is timed at the axes' max feed, which makes the cycle time a "
        "lower bound.",
        "Nothing, when the program is meant so; the time reported is the least it can take."),
    "W_FEED_SPINDLE_STOPPED": (
        "`usina stats`: a feed move (`G1`, `G2`, `G3`, a spline or a cycle's feed) runs with "
        "the spindle stopped: no `M3`/`M4` since the start, or after `M5` or `M6` (which "
        "stops the spindle). A cutter would rub or break.",
        "Start the spindle (`S... M3`) before cutting; ignore for a plotter, laser or drag "
        "knife."),
    "W_RAPID_INTO_STOCK": (
        "`usina stats --stock-top Z`: a rapid move (`G0`) ends below the top of the stock, "
        "or moves across X/Y while below it, so it would cut material at rapid speed. A "
        "retract straight up from inside the cut is not reported.",
        "Feed (`G1`) into the material, or rapid to a clearance height first; check "
        "`--stock-top`."),
    "W_ARC_FEED_REDUCED": (
        "`usina stats`: an arc is too tight for its feed: at the profile's acceleration `a` "
        "the centripetal acceleration v²/r allows at most v = sqrt(a r), so the control runs "
        "the arc slower than programmed, by the percentage the message gives.",
        "Nothing, if the slower feed suits the cut; otherwise a larger radius or a lower "
        "feed keeps the chip load the programmer meant."),
    "W_FEED_CLAMPED": (
        "`usina stats`: the programmed feed is above what the axes allow along the move "
        "(each axis's `max_feed` of the machine profile, projected on the move's direction). "
        "The control clamps it; the time is computed at the clamped feed.",
        "Lower the feed, or check the profile's `max_feed`."),
    # the romi dialect (docs/romi.md)
    "W_TYPOGRAPHIC_DASH": (
        "A typographic dash (U+2013 en dash, U+2014 em dash or U+2212 minus sign) stands "
        "before a number, as when a program is copied from a document (the seed's `Y–250.`). "
        "usina reads it as a minus sign.",
        "Replace it with `-`; `--dialect-option typographic_dash=error` makes it an error."),
    "E_POLAR_WITH_XY": (
        "A romi block gives a polar word (`R`, `A`, `C`) of a straight move together with `X` "
        "or `Y`: the end point would be given twice.",
        "Give the end point either in Cartesian words or in polar words."),
    "E_NO_TANGENT_DIRECTION": (
        "A romi tangent arc (`G02`/`G03` with `R C`, `R A` or `R` alone) starts tangent to the "
        "direction of the previous move, and there is no previous move.",
        "Move first, or give the start direction with `R A C`, or the centre with `C I J`."),
    "E_BLEND_NEEDS_MOVE": (
        "A romi arc with only `R` blends the previous move into the next one, so the next block "
        "must be a straight move whose end point does not depend on where the arc ends "
        "(absolute `X` and `Y`).",
        "Follow the arc with a `G00`/`G01` block with absolute `X` and `Y`, or give the arc's "
        "sweep (`R C`) or end direction (`R A`)."),
    "E_SCALE_OUT_OF_RANGE": (
        "A romi `G72` scale factor is outside 0.05 to 20, the control's range.",
        "Give a factor within 0.05 and 20; `G72 K1` cancels the scale."),
    "E_UNEQUAL_SCALE_ARC": (
        "An arc is programmed while `G72` scales X and Y by different factors: the result "
        "would be an ellipse, which no arc can draw.",
        "Scale both axes alike (`G72 K`), or cancel the scale around the arc."),
    "E_UNKNOWN_TOOL_DIAMETER": (
        "A romi tool change (`T<n> M06`) names a tool whose diameter usina cannot find: not in "
        "the tool table and no `d<number>` in the block's comment. The diameter is needed for "
        "the holes and pockets the tool makes and for cutter compensation.",
        "Give a tool table with `--tool-table`, or write the diameter in the block's comment "
        "(`T02 M06;broca d20mm`)."),
    "E_POCKET_TOO_SMALL": (
        "A romi `G26` pocket cannot be cut with the tool: its corner radius `R` is smaller than "
        "the tool's radius, the pocket is narrower than the tool, or the finishing allowances "
        "leave nothing to rough.",
        "Use a smaller tool, a larger corner radius or a smaller allowance."),
    "E_UNKNOWN_BLOCK_NUMBER": (
        "A romi parametric statement (`GOTO`, `IF .. GOTO`, `RPT`) names a block number `N` "
        "that no block of the program has, or `CALL` names a subroutine with no `(SUB n)`.",
        "Correct the number, or add the block or the subroutine."),
    "N_DEPTH_SIGN_IGNORED": (
        "A romi cycle's depth `Z` (G81, G26) is a distance below the work surface; its sign "
        "is ignored. The seed writes `Z40.` in one program and `Z-25.` in another.",
        "Nothing; the note says which depth was used."),
    "E_GRBL": (
        "Grbl 1.1 would refuse the line (`--dialect grbl`): the message starts with the number "
        "the machine prints, `grbl error:N (Grbl's text)`, then what usina found. The line "
        "changes nothing and the next line is read, as on the firmware "
        "(`--dialect-option after_error=stop` ends there). The numbers are in docs/grbl.md.",
        "Fix the line for Grbl: the number's table in docs/grbl.md says what Grbl wants."),
    "W_GRBL": (
        "Something in a Grbl file that the firmware takes as a command outside the program: a "
        "real-time character (`?` `~` `!` Ctrl-X, even inside a comment) or a `$C`, `$SLP` "
        "line, which usina leaves out of the trace; or a `$RST=` line, which usina applies (a "
        "soft reset: Grbl's power-on modes, and zero offsets or default settings); or a "
        "control character (a NUL, ...) inside a line, which Grbl drops as it drops blanks, so "
        "the characters around it join (`X1`, NUL, `20` reads `X120`), as usina reads it too.",
        "Take the character out of the comment, or the line out of the file, unless it is "
        "meant for the machine."),
    "W_INTEGER_COORDINATE": (
        "A fanuc program writes a distance or an angle without a decimal point (`X1000`) and "
        "the dialect reads it as the pocket calculator does (`decimal_point=calculator`, the "
        "default): 1000 mm. A Fanuc control with parameter 3401 DPI = 0 reads 1 mm (least "
        "input increment). Said once per run, on the first such word.",
        "Write the point (`X1000.`), or run with `--dialect-option decimal_point=fanuc`."),
    "E_MACRO_ALARM": (
        "A fanuc macro wrote `#3000 = n (MESSAGE)`: the program raises alarm 3000 + n with its "
        "message and stops, as the control does. Macros use it to reject missing or bad "
        "arguments.",
        "Give the macro what its alarm asks for (often a G65 argument)."),
    "E_MACRO_FORMAT": (
        "A fanuc Custom Macro B statement is malformed: a macro statement (`#1 = ..`, `IF`, "
        "`WHILE`, `GOTO`) mixed with NC words in one block (Fanuc alarm 114), a relation "
        "stored in a variable, `IF` without `GOTO` or `THEN`, or a G code among G65's "
        "arguments.",
        "Put the statement in a block of its own and follow the forms of docs/fanuc.md §5."),
    "E_BAD_LOOP": (
        "A fanuc `WHILE [..] DO m` / `END m` loop is wrong: m not 1, 2 or 3 (alarm 126), loops "
        "nested deeper than 3, `DO` without its `END` or ranges that overlap (alarm 124), or "
        "`GOTO` into a loop from outside it (alarm 128).",
        "Match each `DO m` with its `END m`, nest at most three loops, jump only out of loops."),
    "N_DIALECT_GUESS": (
        "`--dialect auto` looked at the program's text and chose a dialect; the note says which "
        "and the rule that decided (`%` and `O` numbers: fanuc; `$` lines: grbl; `#` block "
        "ends: romi; `o<name>` or `o123 sub`: rs274ngc; otherwise rs274ngc).",
        "Nothing; give `--dialect NAME` to choose yourself."),
    "E_GRBL_ALARM": (
        "A move of a Grbl file ends beyond the machine's travel while soft limits are on "
        "(`$20=1`): Grbl 1.1 raises `ALARM:2` (Soft limit), stops, and refuses every line "
        "until a reset and `$X` or `$H`. The travel is machine space from -`$130`..`$132` to 0; "
        "the machine position is the programmed one plus the work offset, G92 and G43.1. usina "
        "reports it and ends the run at that line, whatever `after_error` says.",
        "Move the work offset (G10 L2/L20, G92) or the program so every move stays in the "
        "travel, or correct `$130`-`$132`."),
    "E_FORBIDDEN_AREA": (
        "A fanuc program armed stored stroke check 2 (`G22 X Y Z I J K`) and a later move enters "
        "the forbidden side of that box: its inside, or its outside with parameter 1300 bit 0 "
        "OUT = 1 (`--dialect-option stroke_area=outside`). The message has the control's alarm: "
        "OT0502 (+ direction) or OT0503 (- direction) and the axis. Straight moves are checked "
        "exactly, arcs by chords within 0.001 mm. Also when `G22` arms an area the tool is "
        "already in. The run stops at that block, as the control stops there.",
        "Move around the area, or change the G22 corners (they are in the trace's coordinates: "
        "docs/fanuc.md)."),
    "W_PARAMETER_NOT_MODELED": (
        "A fanuc `G10 L50` block sets a parameter usina does not model (it models 5114 and 5115, "
        "the G73/G83 peck distances; 3401 bit 0 DPI; 1300 bit 0 OUT; 5101 bits 4-5 RD1 RD2, the "
        "G76/G87 shift), or other bits of 3401/1300/5101. The value is ignored: the run goes on "
        "as if the block were not there, which may differ from what the control does.",
        "Check that the parameter does not change the part; set what usina models with its own "
        "options."),
    "W_INCREMENTAL_AFTER_G69": (
        "A fanuc program cancels a coordinate rotation with `G69` and the first move after it "
        "that names an axis of the rotation plane is incremental (`G91`). The Fanuc manual "
        "(16/18-MC B-62764EN p. 354) says the first move command after G69 must be absolute: "
        "the control may take the increment from the rotated point and end elsewhere. usina "
        "moves by the increment from where the tool is. G28, G30 and G53 end the check without "
        "a warning.",
        "Make the first move after `G69` absolute (`G90 X.. Y..`)."),
    "E_POLAR_THROUGH_CENTRE": (
        "In fanuc polar coordinate interpolation (`G12.1`), a line or arc of the virtual plane "
        "passes within 0.001 mm of the centre (X0 C0). There the angle is undefined: the rotary "
        "axis would have to turn half a turn in no time. The manual limits the feed to "
        "F < L x R x pi/180 (L the least distance to the centre, R the rotary axis's maximum "
        "feed), so L = 0 is the control's excessive-speed alarm (OT0512). Also when the mode "
        "starts with the tool at the centre and the first move leaves it.",
        "Keep the contour off the centre (e.g. 0.01 mm beside it), or move through the centre "
        "outside G12.1."),
    # gen: limits, material left, option names
    "E_GEN_TOO_MUCH_WORK": (
        "A generator would make more moves than the limit (`--max-moves`, 20,000,000 by "
        "default, about 360 MB of G-code): the work is estimated from the parameters before "
        "anything is generated, so a resolution of 1e-12 mm or a stepover of 1 µm over a large "
        "pocket is refused at once instead of exhausting the memory. The message gives the "
        "estimate, the size of G-code it means and the limit.",
        "Give a coarser `--resolution`, a larger `--stepover` or `--step-down`, fewer holes or "
        "pecks; or raise the limit with `--max-moves N` when the job is real."),
    "E_GEN_MATERIAL_LEFT": (
        "`usina gen pocket` would leave material standing that no pass reaches: the finishing "
        "pass clears a tool diameter from the walls, and the roughing rings start the finish "
        "allowance plus a tool radius from them. When the allowance is larger than the tool "
        "radius, the part of the pocket deeper than a tool diameter from the walls is left "
        "where the pocket is too narrow for a roughing ring (the core of a small pocket, a "
        "channel), or everywhere when the allowance is above the tool diameter. The message "
        "gives the extent of the material left.",
        "Give a finish allowance of at most the tool radius (then nothing is left), or a "
        "smaller tool."),
    "W_GEN_NO_EFFECT": (
        "A value given to a generator changes nothing: a peck (`--peck`) as deep as the hole "
        "or deeper drills each hole in one feed, as without pecking; `--tab-width` or "
        "`--tab-height` without `--tabs`; `--corner-radius` without `--rect`; `--center` with "
        "`--dxf`; `--layer` or `--spline-tolerance` without `--dxf`. The program is written.",
        "Check the value and its units; leave the option out when it is not needed."),
    "W_DEPRECATED_OPTION": (
        "An option of `usina gen` or `usina calc` was given by its old name (`--ae`, `--ap`, "
        "`--ae-finish`, `--ap-finish`, `--diameter`, `--speed`, `--teeth`, the drawing of "
        "`gen from-dxf` as a positional argument). It still works for this release; the table "
        "of names is in docs/gen.md.",
        "Use the new name the message gives."),
    "W_UNKNOWN_PROFILE_KEY": (
        "A machine profile (`--machine`) has a key usina does not read, e.g. `per_hours` for "
        "`per_hour`: its value is not used. The message gives the key's line and the nearest "
        "valid name.",
        "Correct the key's spelling (the message suggests one), or remove it; docs/stats.md "
        "lists the keys."),
    # limits: blocks, operations
    "E_BLOCK_TOO_LONG": (
        "A block (a line, or in fanuc a part of a line up to `;`) is longer than 4096 "
        "characters, comments included; the same limit in every dialect. Controls hold a few "
        "hundred characters (LinuxCNC 256, Grbl 80 after blanks and comments are removed), so "
        "no real program comes near it; a file whose lines end with CR alone (classic Mac OS) "
        "reads as one long line, and the message says so. Also a block with more than 4096 "
        "values and operators.",
        "Split the block, or shorten its comment; convert CR line ends to LF."),
    "E_TOO_MANY_OPERATIONS": (
        "The run produced more canonical operations (moves, arcs, tool changes, comments, ...) "
        "than its budget, 100,000,000 unless `--max-ops` says otherwise; the run stops at the "
        "block that made the first one beyond, and what came before is written (a trace, a "
        "drawing). Usually a loop that does not end; a real program of tens of millions of moves "
        "stays within the default.",
        "Check the loop's condition; for a program meant to be this long, give a larger "
        "`--max-ops`."),
    # limits: numbers (docs/rs274ngc.md, "Numbers")
    "E_VALUE_OUT_OF_RANGE": (
        "A value is beyond usina's range (docs/rs274ngc.md, \"Numbers\"): a word's value beyond "
        "±1e9 (or an `F` below 1e-6), an arc centre, an offset (`G92`, `G52`, `G10`, a tool "
        "length) or a position beyond ±1e9 mm, a feed beyond 1e9, a dwell or spindle speed "
        "beyond 1e9, or an arc whose radius is more than a billion times its chord (it could "
        "not be told from a full circle). The diagnostic points at the word when one word "
        "makes the value, otherwise at the block whose move leaves the range (increments "
        "summed, offsets and scale factors applied). Nothing of the block is sent on: no back "
        "end ever receives a number out of range, an infinity or NaN.",
        "Correct the value; for a position built up over many blocks, check the increments "
        "(`G91`), offsets and scale factors that lead to it. A straight move is `G1`, not an "
        "arc of huge radius."),
    "W_UNKNOWN_OFFSET_REGISTER": (
        "fanuc: an `H` or `D` offset register the program uses is not in the offset file "
        "given with `--offsets` (or no file was given); usina takes its value as 0, as a "
        "control with a cleared register would.",
        "Add the register to the offset file (docs/fanuc.md), or correct `H`/`D`."),
    "W_VAR_FILE_LINE_SKIPPED": (
        "A line of the parameter file given with `--var-file` is not `NUMBER VALUE`; LinuxCNC "
        "skips such lines, and so does usina.",
        "Remove the line, or write it as `<number> <value>`."),
    "W_VAR_FILE_EXTRA_TEXT": (
        "A line of the parameter file has text after the value; it is ignored, as LinuxCNC "
        "ignores it.",
        "Remove the text after the value."),
    "W_TOOL_WITHOUT_POCKET": (
        "A line of the tool table has no `P` word (pocket), which LinuxCNC requires; usina "
        "takes pocket 0.",
        "Add a `P` word, e.g. `T1 P1 D6.0`."),
    "W_TOOL_REDEFINED": (
        "A tool number appears on two lines of the tool table; the later line replaces the "
        "earlier one.",
        "Keep one line per tool."),
    # dnc: links, tape codes, transfers
    "E_DNC_CONFIG": (
        "A `[[machine]]` table of the DNC configuration (`usina-serve.toml`) has a value usina "
        "cannot use: a baud rate outside 110-115200, 5 or 9 data bits, an unknown parity, flow "
        "control, tape code or end of block, a `skid` of 0, a missing `name` or `port`, two "
        "machines of one name, or a combination no link can carry (EIA needs 8 data bits and "
        "no parity: the code has its own parity on channel 5). The message gives the key and "
        "the values it takes.",
        "Correct the key named in the message; docs/dnc.md lists every key with its values."),
    "W_UNKNOWN_DNC_KEY": (
        "A `[[machine]]` table has a key usina does not read, e.g. `buad` for `baud`, or "
        "usina-serve.toml has a table or a key of `[server]`, `[web]`, `[mtconnect]` or `[mqtt]` "
        "it does not read (`max_uplaod`): its value is not used. The message gives the key's "
        "line and the nearest valid name.",
        "Correct the key's spelling (the message suggests one), or remove it; docs/dnc.md lists "
        "the keys."),
    "E_TAPE_NO_CODE": (
        "A character of the program has no code in the machine's tape code: EIA RS-244 has "
        "letters, digits, space and `+ - / . , ( ) %` only (no `=`, `#`, `[`, `*`...), and ISO "
        "and ASCII are 7-bit (no accented letters or other bytes above 127). Nothing is sent.",
        "Remove the character from the program, or set the machine's `code` to `iso` if the "
        "control reads ISO."),
    "E_TAPE_PARITY": (
        "A character received from the control fails the tape code's parity check (ISO: even "
        "parity on channel 8; EIA: odd parity on channel 5), or is no character of the code. "
        "The received program is kept with the position of each bad character, not stored as "
        "good.",
        "Check the link's settings (baud, data bits, parity, stop bits) against the control's, "
        "and the cable; then punch the program again."),
    "E_REMOTE_REQUEST": (
        "A program punched by the control looked like a remote request (its O number is the "
        "machine's `request_program`, or a comment holds `PRG=`, `/REQ`...) but it cannot be "
        "answered: no program named, a name with characters a program name may not have "
        "(`/`, `..`, spaces), or a start block, line or tool that is not a number. The control "
        "gets a response program whose comment says why.",
        "Punch the request again as `O9999 (PRG=NAME)`, with the program's name as the store "
        "knows it."),
    # simulate: the stock model, its tools, its checks
    "E_STOCK_GRID_TOO_LARGE": (
        "`usina simulate`: the stock's height map would have more cells than usina allows "
        "(2^27, 134,217,728 cells, 640 MiB with their marks): the stock's width over the "
        "resolution times its length over the resolution is too large. The message gives "
        "both numbers.",
        "Give a coarser `--resolution` (cells are resolution x resolution mm) or a smaller "
        "`--stock` box."),
    "E_RAPID_CUTS_STOCK": (
        "`usina simulate`: a rapid move (`G0`, or a canned cycle's rapid) removes material "
        "from the simulated stock, more than the tolerance (0.01 mm deep under one cell); "
        "the tool would enter the stock at rapid speed. The message gives the volume "
        "removed and the deepest cut.",
        "Feed (`G1`) into the material, or rapid to a clearance height first; check the "
        "stock's `--origin` and the work offset."),
    "E_CUT_BELOW_FLOOR": (
        "`usina simulate --floor Z`: a move takes the tool below the floor (the fixture, the "
        "table, the part's finished bottom) where it cuts the stock or passes through its "
        "bottom. "
        "The message gives the lowest Z reached.",
        "Check the move's Z, the tool length offset and the work offset; give the right "
        "`--floor`."),
    "W_SIM_TOOL_DEFAULTED": (
        "`usina simulate`: the program cuts with a tool whose diameter usina cannot find "
        "(no `--tool-table`, or the tool is not in it, or its diameter is 0); the "
        "simulation uses the default tool (a 6 mm flat end mill) and says so once per tool.",
        "Give a tool table with `--tool-table` holding the tool's diameter, and its shape "
        "with `--tool-shape T=ball` or a word in the table's comment (docs/simulate.md)."),
    "W_SIM_MOTION_NOT_MODELED": (
        "`usina simulate`: a move the height map cannot model (it moves a rotary axis A, B "
        "or C); the stock is not cut by it, so the result may show material the machine "
        "removes.",
        "Simulate 3-axis programs only (a vertical tool along Z); see docs/simulate.md."),
    "E_SHANK_RUBS_STOCK": (
        "`usina simulate`: a tool given its flute length (`flutes:L` in `--tool-shape` or the "
        "tool table's comment) enters stock that stands higher above its tip than the flutes "
        "reach: the shank above them, which does not cut, rubs the stock. The message gives "
        "how far the stock stands above the flutes. A tool without `flutes:` is not checked.",
        "Cut in steps no deeper than the flutes, or use a tool with longer flutes; check the "
        "flute length given."),
    "E_HOLDER_HITS_STOCK": (
        "`usina simulate`: a tool given its holder (`holder:D` and `stickout:L`) goes so deep "
        "that the holder, a cylinder of diameter D from L mm above the tip up, meets the stock "
        "(closer than 0.001 mm). The message gives how deep it goes into the stock. A tool "
        "without `holder:` is not checked.",
        "Give the tool a longer stick-out or a slimmer holder, or cut the deep feature with a "
        "longer tool."),
    "W_PLUNGE_NOT_CENTRE_CUTTING": (
        "`usina simulate`: a tool marked `no-plunge` (it does not cut at its centre; "
        "`no-plunge:A` its steepest ramp, 5 degrees unless given) goes down steeper than its "
        "ramp into stock that stands more than 0.01 mm above its tip under its axis.",
        "Ramp or helix into the material no steeper than the tool allows, drill a start hole "
        "first, or use a centre-cutting tool."),
    "W_MATERIAL_ABOVE_TARGET": (
        "`usina simulate`, given `--target-dxf FILE` and `--target LAYER=Z`: after the program, "
        "stock stands more than the target tolerance (`--target-tolerance`, 0.01 mm unless "
        "given) above the depth Z inside the closed contours of the drawing's layer: the "
        "program did not cut what the drawing asks. One warning a layer, with the area left, "
        "the most left and where. Corners narrower than the tool's radius count too: a round "
        "tool cannot reach them.",
        "Cut the area named (a pass more, a smaller tool for the corners, the last depth step "
        "down to Z), or check that the layer's depth is the one the drawing means."),
    # job: job files, tool libraries, materials, cutting data
    "E_BAD_JOB": (
        "The job file given to `usina job` cannot be used: it is not valid TOML, a required "
        "key is missing, a value has the wrong type or is out of range, or the drawing it "
        "names cannot be read. The message gives the key's line and column.",
        "Correct the key named in the message; docs/job.md gives the schema and "
        "`examples/jobs/` complete jobs to start from."),
    "E_UNKNOWN_JOB_KEY": (
        "A job file, tool library or materials file has a key usina does not read, e.g. "
        "`dept` for `depth`. A job's keys set what is cut, so a key that is not read is an "
        "error, not a warning: its value would otherwise be silently left at the default.",
        "Correct the key's spelling (the message suggests the nearest valid one) or remove "
        "it; docs/job.md lists the keys."),
    "E_JOB_UNKNOWN_TOOL": (
        "An operation names a tool number that the tool library does not have.",
        "Give the number of a tool in the library (the `[[tool]]` entries of the file named "
        "by `tools`), or add the tool to the library."),
    "E_JOB_UNKNOWN_MATERIAL": (
        "The stock's `material` is not one of the materials file's groups.",
        "Use one of the names the message lists (data/materials.toml), or add the material "
        "with its cutting data and their source."),
    "E_JOB_UNKNOWN_OPERATION": (
        "An operation's `type` is not one `usina job` makes in this version.",
        "Use one of the types the message lists (docs/job.md, \"Operations\")."),
    "E_JOB_MISSING_LAYER": (
        "An operation names a layer of the drawing that has no entity usina can machine (the "
        "layer is absent, empty, or holds only text, hatches or blocks).",
        "Correct the layer's name (DXF layer names are case-insensitive) or draw the "
        "contours on it."),
    "E_JOB_NO_TOOL_FITS": (
        "An operation asks the job to choose its tool (`tool = \"auto\"`) and no tool of the "
        "library fits: a pocket's end mill must be no larger than twice the smallest inside "
        "corner radius and must fit the pocket, a drill must have the hole's diameter, and "
        "the cutting length must reach the depth. The message says why the nearest candidate "
        "was refused.",
        "Add a suitable tool to the library, name a tool explicitly, or change the drawing "
        "(a larger corner radius)."),
    "E_JOB_NO_CUTTING_DATA": (
        "The materials file has no cutting speed or feed per tooth for the stock's material "
        "with the tool's material and the operation, so the job cannot compute the spindle "
        "speed and feed.",
        "Give `rpm` and `feed` in the operation, or add the row (with its source) to the "
        "materials file."),
    "E_BAD_TOOL_LIBRARY": (
        "The tool library (`tools` in the job) cannot be used: not valid TOML, a tool without "
        "a number, type or diameter, a type or tool material usina does not know, a number "
        "given twice, or a value out of range.",
        "Correct the entry named in the message; examples/tools/shop.toml is a complete "
        "library."),
    "E_BAD_MATERIALS": (
        "The materials file cannot be used: not valid TOML, a row without its cutting speed, "
        "feed per tooth or source, or a value out of range.",
        "Correct the row named in the message; data/materials.toml is the reference."),
    "N_JOB_CUTTING_LIMITED": (
        "The spindle speed or feed the cutting data gives is above what the machine profile "
        "allows (`[spindle] max_rpm`, the axes' `max_feed`), so the job uses the machine's "
        "limit; the feed per tooth is kept, so the feed drops with the speed.",
        "Nothing to do; a machine with a faster spindle would cut sooner."),
    # job: the operations checked against the stock
    "E_JOB_OUTSIDE_STOCK": (
        "An operation's geometry is off the stock's top face (the box's rectangle or the "
        "cylinder's circle, placed by `[stock] origin`): a hole's centre, a pocket's or an "
        "ellipse pocket's outline, an engraving's letters, or a profile's contour that lies "
        "wholly outside the stock or wholly around it (the part larger than the blank). "
        "Nothing is written: the operation would cut air where the part should be.",
        "Check the stock's `size` (or `diameter`) and `origin` against the drawing, the "
        "operation's layer, or its `center` / `at`."),
    "W_JOB_PARTLY_OUTSIDE_STOCK": (
        "A profile's contour runs partly off the stock's top face: the tool cuts air there "
        "(usual when an oversize blank is trimmed to its outline). Or a hole's circle "
        "breaks out of the stock's side (its centre on the stock): the drill cuts partly in "
        "air there and is pushed off its line. The program is written.",
        "Nothing, if the blank is meant to be trimmed or the hole to break out; else check "
        "the stock's size and origin."),
    "E_JOB_DEEPER_THAN_STOCK": (
        "A facing as deep as the stock or deeper (nothing would be left of the part), or a "
        "tapping deeper than the stock's height and the tap's lead (5.5 pitches, DIN 2197 "
        "form B's longest: a through thread is full once the lead has passed the bottom; deeper the tap cuts no thread "
        "and meets the parallels or the fixture).",
        "Give a smaller `depth` (the message gives the largest), or check the stock's height."),
    "W_JOB_CUTS_THROUGH_STOCK": (
        "A pocket, an ellipse pocket or an engraving as deep as the stock or deeper: it cuts "
        "through, so what it surrounds comes loose (a cut-out, sometimes meant). The "
        "program is written.",
        "Nothing, if a cut-out is meant (hold the slug); else a smaller `depth`."),
    "W_JOB_CUTS_BELOW_STOCK": (
        "A drill (spot drill) whose tip goes more than its point and 1 mm below the stock's "
        "bottom, or a profile more than 1 mm below it: past a breakthrough it cuts what the "
        "stock stands on (parallels, the vice, the fixture, the table). The program is "
        "written.",
        "A smaller `depth` (the message gives the deepest), or a sacrificial plate under "
        "the stock."),
    "W_JOB_HOLE_NOT_THROUGH": (
        "A drill's tip breaks through the stock's bottom but its full diameter does not: "
        "the hole is narrower at the bottom (the message gives its diameter there) and "
        "leaves a burr. Point length: a 118° drill's, 0.3 times its diameter.",
        "A through hole: `depth` at least the stock's height and the point (the message "
        "gives it); a blind one: at most the height."),
    "E_JOB_PILOT_HOLE": (
        "A bore whose holes no earlier operation of the job drilled (a boring bar finishes a "
        "hole, it does not cut from solid), or whose pilot hole is as wide as the bore "
        "(nothing to bore) or whose full diameter ends above the bore's depth (the bar's end "
        "would cut solid below it). The job checks the earlier drill and bore operations' "
        "holes at the same centres (within 0.01 mm); a drill's full diameter ends its 118° "
        "point above its depth.",
        "Drill the pilot holes first (a drill operation on a layer of the pilot circles at the "
        "same centres, deep enough), or give `predrilled = true` when the holes are there "
        "before the job (cast, or drilled in another setup)."),
}

SECTION = re.compile(r"/\*\s*(.*?)\s*\*/")
ENTRY = re.compile(r"X\((\w+),\s*(\w+)\)")
LITERAL = re.compile(r'"((?:[^"\\]|\\.)*)"')


def read_codes(header):
    """[(section, enumerator, stable name)] in the header's order."""
    codes, section, inside = [], "", False
    for line in header.read_text(encoding="utf-8").splitlines():
        if "#define" in line:
            inside = True
            continue
        if not inside or line.lstrip().startswith("//"):
            continue
        m = SECTION.search(line)
        if m and "X(" not in line:
            section = m.group(1)
        m = ENTRY.search(line)
        if m:
            codes.append((section, m.group(1), m.group(2)))
    return codes


def usages(src, enumerator):
    """Files reporting `Code::<enumerator>` and the messages they report it with."""
    pattern = re.compile(r"Code::" + enumerator + r"\b")
    files, messages = [], []
    for path in sorted(src.rglob("*.cpp")):
        text = path.read_text(encoding="utf-8", errors="replace")
        hits = list(pattern.finditer(text))
        if not hits:
            continue
        files.append(path.relative_to(src.parent).as_posix())
        for hit in hits:
            for message in literal_groups(rest_of_call(text, hit.end())):
                message = re.sub(r"\{[^{}]*\}", "…", message).replace('\\"', '"')
                message = re.sub("…+", "…", message)
                if message not in messages:
                    messages.append(message)
    return files, messages


def literal_groups(code):
    """The messages in a call's text: runs of adjacent string literals (C++
    joins them), each run one message; short words (format arguments) dropped."""
    groups, last_end = [], None
    for m in LITERAL.finditer(code):
        if last_end is not None and code[last_end:m.start()].strip() == "":
            groups[-1] += m.group(1)
        else:
            groups.append(m.group(1))
        last_end = m.end()
    return [g for g in groups if " " in g and len(g.strip()) >= 3]


def rest_of_call(text, start):
    """The text from `start` to the end of the call (or braced initializer) it is in."""
    depth, i, quote = 0, start, None
    while i < len(text):
        c = text[i]
        if quote:
            if c == "\\":
                i += 1
            elif c == quote:
                quote = None
        elif c in "\"'":
            quote = c
        elif c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
            if depth < 0:
                return text[start:i]
        elif c == ";" and depth <= 0:
            return text[start:i]
        i += 1
    return text[start:]


def severity(name):
    return {"E": "error", "W": "warning", "N": "note"}.get(name[0], "error")


def render(root):
    src = root / "src"
    codes = read_codes(src / "core" / "diagnostic_codes.hpp")
    out = [
        "# Diagnostic codes",
        "",
        "<!-- Generated by scripts/gen_errors_doc.py from src/core/diagnostic_codes.hpp;",
        "     edit the explanations in the script, not this file. -->",
        "",
        "Every diagnostic usina prints ends with a stable code in brackets:",
        "",
        "```",
        "part.ngc:2:13: error: arc radius 10.0000 mm is smaller than half the chord 12.6500 mm "
        "[E_ARC_RADIUS_TOO_SMALL]",
        "  G2 X25.3 Y0 R10 F100",
        "              ^",
        "```",
        "",
        "The names never change meaning, so scripts may match on them. `E_` codes are errors "
        "(the run stops at the first one; all syntax errors are reported), `W_` codes are "
        "warnings (the run goes on), `N_` codes are notes.",
        "",
    ]
    missing = []
    current = None
    index = []
    body = []
    for section, enumerator, name in codes:
        if section != current:
            current = section
            body += [f"## {section.capitalize() if section else 'Other'}", ""]
            index.append(f"- {section or 'other'}: " + ", ".join(
                f"[`{n}`](#{n.lower()})" for s, _, n in codes if s == section))
        meaning, todo = EXPLAIN.get(name, (None, None))
        if meaning is None:
            missing.append(name)
            meaning, todo = "*Not documented yet.*", "*Not documented yet.*"
        files, messages = usages(src, enumerator)
        body += [f"### {name}", "", f"*{severity(name)}* · {meaning}", "", f"**What to do:** {todo}", ""]
        if messages:
            body.append("Reported as: " + "; ".join(f"“{m}”" for m in messages[:5]) + ".")
            body.append("")
        if files:
            body.append("Reported by: " + ", ".join(f"`{f}`" for f in files) + ".")
        else:
            body.append("Not reported by this version: the code is reserved.")
        body.append("")
    return "\n".join(out + index + [""] + body), missing


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--root", default=pathlib.Path(__file__).resolve().parent.parent, type=pathlib.Path)
    ap.add_argument("--check", action="store_true",
                    help="fail if docs/errors.md is out of date or a code is undocumented")
    args = ap.parse_args()
    text, missing = render(args.root)
    target = args.root / "docs" / "errors.md"
    for name in missing:
        print(f"gen_errors_doc: {name} has no explanation; add it to EXPLAIN in "
              f"scripts/gen_errors_doc.py", file=sys.stderr)
    unknown = sorted(set(EXPLAIN) - {n for _, _, n in read_codes(args.root / "src/core/diagnostic_codes.hpp")})
    for name in unknown:
        print(f"gen_errors_doc: {name} is explained but no longer in diagnostic_codes.hpp",
              file=sys.stderr)
    if args.check:
        # Fails when a code is missing or undocumented; stale message samples
        # ("Reported as") only get a note, so editing a message breaks no build.
        current = target.read_text(encoding="utf-8") if target.exists() else ""
        headings = re.compile(r"^### (\S+)", re.M)
        if headings.findall(current) != headings.findall(text) or \
                "Not documented yet" in current:
            print("gen_errors_doc: docs/errors.md does not list the codes of diagnostic_codes.hpp;"
                  " run scripts/gen_errors_doc.py", file=sys.stderr)
            return 1
        if current != text:
            print("gen_errors_doc: note: docs/errors.md's message samples are stale; "
                  "run scripts/gen_errors_doc.py", file=sys.stderr)
        return 1 if missing else 0
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_text(text, encoding="utf-8")
    print(f"wrote {target} ({len(text.splitlines())} lines)")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
