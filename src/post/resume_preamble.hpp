// The blocks that restore a program's modal state before a restart (issue
// 13, "start from block N / tool T"), written by the control's own block
// writer (BlockOut: its numbers, N words, comments, block end): the modes,
// the tool, spindle and coolant, then the safe approach (Z up to the
// program's highest Z so far, XY over the start point, Z down in feed).
#pragma once

#include <string>
#include <string_view>

#include <tl/expected.hpp>

#include "canon/resume_state.hpp"

namespace usina::post {

// The preamble's text; the error says so for a control usina has no post for.
tl::expected<std::string, std::string> resume_preamble(std::string_view control,
                                                       const canon::ResumeState& s);

}  // namespace usina::post
