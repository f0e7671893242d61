#include "gcode/romi/services.hpp"

#include <fmt/format.h>

namespace usina::gcode::romi {
namespace {

std::string_view value_of(const Dialect& d, const OptionValues& values, std::string_view name) {
  if (auto it = values.find(name); it != values.end()) return it->second;
  for (const DialectOption& o : d.options) {
    if (o.name == name) return o.values.front();
  }
  return {};
}

}  // namespace

Options Options::from(const Dialect& dialect, const OptionValues& values) {
  Options o;
  o.lowercase_incremental = value_of(dialect, values, "lowercase_incremental") == "on";
  o.typographic_dash_is_error = value_of(dialect, values, "typographic_dash") == "error";
  o.motion_cancels_cycle = value_of(dialect, values, "motion_cancels_cycle") == "on";
  o.comp_radius_from_register = value_of(dialect, values, "comp_radius") == "register";
  return o;
}

bool Services::error(core::Code code, std::uint32_t col, std::string message) {
  core::SourceLoc loc = loc_;
  if (col > 0) {
    loc.col = col;
    loc.length = 1;
  }
  diags_.report({code, core::Severity::Error, loc, std::move(message)});
  failed_ = true;
  return false;
}

void Services::note(core::Code code, core::Severity sev, std::uint32_t col, std::string message) {
  core::SourceLoc loc = loc_;
  if (col > 0) loc.col = col;
  diags_.report({code, sev, loc, std::move(message)});
}

bool Services::count_jump() {
  if (++jumps_ <= max_iterations_) return true;
  return error(core::Code::TooManyIterations, 0,
               fmt::format("the program's backward jumps, calls and pattern points came to more "
                           "than {}; raise the limit with --max-total-iterations",
                           max_iterations_));
}

}  // namespace usina::gcode::romi
