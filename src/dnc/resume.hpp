// The restart program (issue 13, "start from block N / tool T"): the
// program's opening `%` and O number, the subroutines it defined before
// the start, the preamble that restores the modal state and approaches
// safely (post/resume_preamble), then the program's own bytes from the
// start block on. The same text goes to `usina resume -o` and, through the
// machine's tape code, onto the wire.
#pragma once

#include <string>
#include <string_view>

#include <tl/expected.hpp>

#include "gcode/resume_point.hpp"

namespace usina::dnc {

// The restart program, or why there is none (refused start, unknown dialect).
tl::expected<std::string, std::string> resume_program(std::string_view text,
                                                      std::string_view dialect,
                                                      const gcode::ResumeStart& start);

}  // namespace usina::dnc
