// What the normalised diff compares: a program's blocks with what a transfer
// or a renumbering changes taken out (docs/dnc.md, "Diff"):
// - block ends: LF, CR LF, CR, the dialect's own (ROMI `#`) and a trailing
//   `;` (the EOB as listings print it) all end a block the same way;
// - blank lines and blocks of only `%` (tape framing) are dropped;
// - tape leader and transfer characters (NUL, DEL, DC1-DC4) are dropped
//   wherever they are, and spaces at both ends of a block;
// - the sequence number (`N123`, after a block delete `/`) is dropped, so a
//   renumbered program compares equal to the original.
// Nothing else changes: case, spaces between words, comments and values all
// count.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace usina::dnc {

struct Block {
  std::string text;        // normalised
  std::uint32_t line = 0;  // the 1-based line it came from
};

struct NormaliseRules {
  std::string_view block_ends = "\n";  // besides LF: the dialect's (gcode::LexicalRules)
  bool lower_case_meaning = false;     // then `n` is not a sequence number
};

std::vector<Block> normalise_program(std::string_view text, const NormaliseRules& rules = {});

// The rules of a dialect by name (rs274ngc's when unknown).
NormaliseRules normalise_rules(std::string_view dialect);

}  // namespace usina::dnc
