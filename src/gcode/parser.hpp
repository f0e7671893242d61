// The parser: one line of text into a Block (syntax only). A syntax error
// is reported and the rest of the line is skipped, so every syntax error of
// a program is reported in one run.
#pragma once

#include <string_view>

#include "core/diagnostic.hpp"
#include "gcode/block.hpp"

namespace usina::gcode {

struct LinePos {
  std::uint32_t file = 0;
  std::uint32_t line = 0;
  std::uint64_t offset = 0;  // of the line's first byte in its file
};

// Parses `line` (without its end of line) into `block` (cleared first).
// Returns false after reporting a syntax error.
bool parse_block(std::string_view line, const LinePos& where, Block& block,
                 core::DiagnosticSink& diags);

// The shortcut parse_block takes for most blocks of a program: an optional
// N number, then upper-case words of plain numbers apart or with blanks
// between them ("N20 G1 X45.75 Y4 Z-1.4104"), from `first`, the first
// character that is no blank. Their words (and line number) added to
// `block`, as the whole parser reads them; false for any other line, with
// `block.words` and `block.line_number` left to be cleared.
bool parse_plain_block(std::string_view line, std::size_t first, Block& block);

}  // namespace usina::gcode
