// --dialect auto: which dialect a program's text is written in
// (docs/fanuc.md §12). The first rule that fires over the first 200 lines,
// outside comments, decides; the reason says which rule it was.
#pragma once

#include <string>
#include <string_view>

namespace usina::gcode {

struct DialectGuess {
  std::string_view dialect;
  std::string reason;
};

DialectGuess guess_dialect(std::string_view text);

}  // namespace usina::gcode
