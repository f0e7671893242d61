// Rules of a program's text that every dialect's runner applies before its
// own syntax, so one rule has one limit and one message (STYLE.md: no
// service copied into each runner): the longest block, and the UTF-8
// byte-order mark.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include <tl/expected.hpp>

#include "core/diagnostic.hpp"

namespace usina::gcode {

// The longest block usina reads, in bytes from its first character to its
// end of block, comments included. Controls hold a few hundred characters
// (LinuxCNC 256, Grbl 80 without comments and blanks); 4096 leaves room for
// the longest real blocks (a CAM header comment, a Macro B expression) many
// times over while bounding the work one block can cause: the expression
// parsers make at most one value or operator per character.
inline constexpr std::size_t kMaxBlockLength = 4096;

// `block` is at most kMaxBlockLength long; else its error is
// E_BLOCK_TOO_LONG. `start` is where the block starts (file, line, column of
// its first character, line offset). The caret goes to the first character
// beyond the limit.
// Inline, the error built out of line: every block of every dialect asks,
// and a call returning the expected cost ~25 instructions a block (issue 19).
core::Diagnostic block_too_long(std::string_view block, const core::SourceLoc& start);

inline tl::expected<void, core::Diagnostic> check_block_length(std::string_view block,
                                                               const core::SourceLoc& start) {
  if (block.size() <= kMaxBlockLength) [[likely]]
    return {};
  return tl::unexpected(block_too_long(block, start));
}

// The UTF-8 byte-order mark some Windows editors write: skipped with
// W_BYTE_ORDER_MARK in every dialect (the program's meaning is plain; the
// warning says a control may refuse it). Returns the bytes to skip, 0 or 3.
std::size_t skip_byte_order_mark(std::string_view text, std::uint32_t file,
                                 core::DiagnosticSink& diags);
// The same without a word: where the text after a mark starts (0 or 3).
std::size_t byte_order_mark_length(std::string_view text);

}  // namespace usina::gcode
