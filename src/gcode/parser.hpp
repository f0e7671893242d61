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

}  // namespace usina::gcode
