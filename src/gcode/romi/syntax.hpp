// The syntax of the romi dialect (spec/romi.md, "Lexical" and "Parametric
// programming"): a block ends at '#' or a newline, ';' comments run to the
// block end, a '%' line is ignored, words are a letter (upper or lower case,
// which matters) and a number, a P parameter or nothing (0), and
// parenthesised Fagor statements: (P1 = expr), (IF .. GOTO N..), (GOTO N..),
// (RPT N.., N.., n), (CALL n), (SUB n), (RET). Syntax only.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "core/diagnostic.hpp"
#include "gcode/block.hpp"
#include "gcode/parser.hpp"

namespace usina::gcode::romi {

inline constexpr int kMaxParam = 999;

struct RomiWord {
  char letter = 0;          // upper case
  bool lower = false;       // written in lower case
  ExprRef value = kNoExpr;  // the expression, or kPlainNumber: then `number`
  std::uint32_t col = 0;
  double number = 0.0;
};

enum class StmtKind : std::uint8_t { Assign, IfGoto, Goto, Repeat, Call, Sub, Return };

struct Statement {
  StmtKind kind = StmtKind::Assign;
  int param = 0;           // Assign: P index
  ExprRef expr = kNoExpr;  // Assign: value; IfGoto: condition; Repeat: count
  double label = 0;        // Goto, IfGoto: N; Repeat: first N; Call, Sub: number
  double label_end = 0;    // Repeat: last N
  std::uint32_t col = 0;
};

struct RomiBlock {
  Block base;  // location, N, comments, '%', and the expression arena
  std::vector<RomiWord> words;
  std::vector<Statement> statements;
  std::vector<std::uint32_t> dashes;  // columns of typographic dashes read as '-'

  void clear();

  bool empty() const { return words.empty() && statements.empty(); }
};

// The text of the block starting at `offset`, and where the next one starts.
struct BlockText {
  std::string_view text;
  std::uint64_t next = 0;
  bool ends_line = false;  // ended by a newline or the end of the file (not '#')
};

// A stretch of text known to hold no newline, [from, end), with the
// newline or the text's end at `end`: where a line of several blocks ends,
// kept between calls so that the line is scanned once.
struct LineEnd {
  std::uint64_t from = 0;
  std::uint64_t end = 0;
  bool known = false;
};

BlockText block_at(std::string_view text, std::uint64_t offset, LineEnd& line);

inline BlockText block_at(std::string_view text, std::uint64_t offset) {
  LineEnd unknown;
  return block_at(text, offset, unknown);
}

// The shortcut parse_romi_block takes for most blocks: an optional N
// number, then upper-case words of plain numbers apart or with blanks
// between them ("G1 X112.75 Y16.5 Z-0.8597"), from `first`, the first
// character that is no blank. Their words and line number added to
// `block` as the whole parser makes them, but each value kept in its word
// (kPlainNumber) where the whole parser makes a node; false for any other
// block, with `block.words` and `block.base.line_number` left to be
// cleared.
bool parse_plain_romi_block(std::string_view text, std::uint32_t first_col, std::size_t first,
                            RomiBlock& block);

// Parses a block whose first character is at column `first_col` of its line.
// Returns false after reporting a syntax error.
bool parse_romi_block(std::string_view text, const LinePos& where, std::uint32_t first_col,
                      RomiBlock& block, core::DiagnosticSink& diags);

}  // namespace usina::gcode::romi
