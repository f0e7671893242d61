#include "gcode/romi/services.hpp"

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
  o.plain_move_shortcut = values.find("whole_road") == values.end();
  return o;
}

}  // namespace usina::gcode::romi
