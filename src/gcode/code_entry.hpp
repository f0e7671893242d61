// One row of a dialect's G/M table (Dialect::codes).
#pragma once

#include <string_view>

namespace usina::gcode {

// One G or M code: code in tenths (G38.2 → 382, M6 → 60), its modal group
// (the dialect's numbering; groups run in ascending order within a block)
// and the name of the handler that runs it. `what` says what the code is,
// for the messages about a code the dialect has but usina cannot run.
struct CodeEntry {
  char letter = 'G';
  int code = 0;
  int group = 0;
  std::string_view handler;
  std::string_view what = {};
};

}  // namespace usina::gcode
