// --dialect auto: which dialect a program's text is written in
// (docs/dialects.md, "Guessing the dialect"). A mark only one dialect
// carries decides alone; else clues (named controls, codes, habits, the
// end, the file's extension) are weighed. The reason says which decided.
#pragma once

#include <string>
#include <string_view>

namespace usina::gcode {

struct DialectGuess {
  std::string_view dialect;
  std::string reason;
};

// `file_name` gives the extension as a hint; empty for standard input.
DialectGuess guess_dialect(std::string_view text, std::string_view file_name = {});

}  // namespace usina::gcode
