#include "gcode/run_services.hpp"

#include <fmt/format.h>

namespace usina::gcode {

bool RunServices::error(core::Code code, std::uint32_t col, std::string message) {
  core::SourceLoc loc = loc_;
  if (col > 0) {
    loc.col = col;
    loc.length = 1;
  }
  diags_.report({code, core::Severity::Error, loc, std::move(message)});
  failed_ = true;
  return false;
}

void RunServices::note(core::Code code, core::Severity sev, std::uint32_t col,
                       std::string message) {
  core::SourceLoc loc = loc_;
  if (col > 0) loc.col = col;
  diags_.report({code, sev, loc, std::move(message)});
}

bool RunServices::count_jump(std::string_view what) {
  if (++jumps_ <= max_iterations_) return true;
  return error(core::Code::TooManyIterations, 0,
               fmt::format("the program's {} came to more than {}; raise the limit with "
                           "--max-total-iterations",
                           what, max_iterations_));
}

}  // namespace usina::gcode
