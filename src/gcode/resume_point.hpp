// Where a restart may begin, and the modal state there (issue 13, "start
// from block N / tool T"). The program is read in its dialect: the blocks
// before the start run through the dialect's runner into a canon stream
// (tool, spindle, coolant, feed, the point reached, the highest Z), and a
// scan of their words gives what the canon stream does not carry (units,
// plane, G90/G91, work offset, length offset, feed mode, motion mode). A
// start the state cannot be restored at is refused with the reason.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <tl/expected.hpp>

#include "canon/resume_state.hpp"

namespace usina::gcode {

// Where to start: a line of the file (1-based), the block with an N word,
// or the first change to a tool.
struct ResumeStart {
  enum class Kind { Line, NWord, Tool };
  Kind kind = Kind::Line;
  long value = 0;
};

// "120" is line 120, "N120" the block N120 (either case).
std::optional<ResumeStart> parse_start_block(std::string_view text);

// The restart's parts: the state, the lines of subroutine definitions
// before the start (a restart still needs them), the byte where the start
// block begins, and the leading `%` / program-number lines of the file.
struct ResumePoint {
  canon::ResumeState state;
  std::string head;         // "%" and "O1234" lines the program opens with
  std::string definitions;  // subroutine bodies defined before the start
  std::size_t offset = 0;   // where the start block's line begins in the text
};

tl::expected<ResumePoint, std::string> find_resume_point(std::string_view text,
                                                         std::string_view dialect,
                                                         const ResumeStart& start);

}  // namespace usina::gcode
