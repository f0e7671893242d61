// The word scan behind resume_point: each line of a program with its N, G,
// M words, whether it moves an axis, and where it stands in the program's
// structure (a subroutine's definition, a loop, after the end). A scan, not
// a run: it finds the start block and what surrounds it; the modes in force
// there come from running the program (ProgramRunner::modes).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace usina::gcode {

struct ScanLine {
  std::size_t offset = 0;
  std::string_view raw;
  std::optional<long> n;
  std::vector<int> g;  // tenths: G59.1 is 591
  std::vector<int> m;
  bool axis = false;      // an X Y Z A B C U V W word (a move, or a cycle's next hole)
  bool in_sub = false;    // inside a subroutine's definition (its bounds included)
  std::string inside;     // the loop or condition around it ("" at the top level)
  bool past_end = false;  // after the main program's end (M2, M30, closing %)
};

std::vector<ScanLine> scan_program(std::string_view text, std::string_view dialect);

}  // namespace usina::gcode
