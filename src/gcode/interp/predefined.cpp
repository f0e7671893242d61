// Parameters the interpreter answers from its state: #5420-#5428 and the
// read-only named parameters (LinuxCNC manual, "Predefined Named Parameters").
#include <string>

#include "gcode/interp/interpreter.hpp"

namespace usina::gcode {
namespace {

struct NamedAxis {
  std::string_view name;
  int axis;
};

constexpr NamedAxis kAxisNames[] = {{"_x", 0}, {"_y", 1}, {"_z", 2}, {"_a", 3}, {"_b", 4},
                                    {"_c", 5}, {"_u", 6}, {"_v", 7}, {"_w", 8}};

constexpr NamedAxis kAbsAxisNames[] = {{"_abs_x", 0}, {"_abs_y", 1}, {"_abs_z", 2},
                                       {"_abs_a", 3}, {"_abs_b", 4}, {"_abs_c", 5}};

}  // namespace

double Interpreter::numbered(int index) const {
  // #5420-#5428: the current point in program units and coordinates.
  if (index >= 5420 && index <= 5428) {
    const auto axis = static_cast<std::size_t>(index - 5420);
    const double v = state_.pos[axis];
    return axis >= 3 && axis <= 5 ? v : v / core::mm_per(state_.units);
  }
  if (index == 5400) return state_.tool;
  if (index == 5410) return tool_diameter(state_.tool) / machine_mm();
  return params_.get(index);
}

std::optional<double> Interpreter::named(std::string_view name) const {
  if (!name.empty() && name.front() == '_') {
    if (auto v = predefined(name)) return v;
  }
  return params_.named(name);
}

std::optional<double> Interpreter::predefined(std::string_view name) const {
  const ModalState& s = state_;
  const double unit = core::mm_per(s.units);
  for (const NamedAxis& a : kAxisNames) {
    if (name == a.name) return numbered(5420 + a.axis);
  }
  for (const NamedAxis& a : kAbsAxisNames) {
    if (name != a.name) continue;
    const Vec3 abs = machine_.to_absolute(xyz(s.pos));
    return a.axis < 3 ? (abs[a.axis] + s.tool_offset[static_cast<std::size_t>(a.axis)]) / unit
                      : s.pos[static_cast<std::size_t>(a.axis)];
  }
  auto flag = [](bool b) { return b ? 1.0 : 0.0; };
  if (name == "_line") return run_.loc().line;
  if (name == "_motion_mode") return s.motion;
  if (name == "_plane")
    return s.plane == core::Plane::XY ? 170 : (s.plane == core::Plane::ZX ? 180 : 190);
  if (name == "_ccomp")
    return s.comp == CompSideState::Off ? 400 : (s.comp == CompSideState::Left ? 410 : 420);
  if (name == "_metric") return flag(s.units == core::LengthUnit::Mm);
  if (name == "_imperial") return flag(s.units == core::LengthUnit::Inch);
  if (name == "_absolute") return flag(!s.incremental);
  if (name == "_incremental") return flag(s.incremental);
  if (name == "_inverse_time") return flag(s.feed_mode == FeedMode::InverseTime);
  if (name == "_units_per_minute") return flag(s.feed_mode == FeedMode::UnitsPerMinute);
  if (name == "_units_per_rev") return flag(s.feed_mode == FeedMode::UnitsPerRev);
  if (name == "_coord_system")
    return s.coord_system <= 6 ? 530 + 10 * s.coord_system : 590 + s.coord_system - 6;
  if (name == "_tool_offset") return flag(s.tool_offset != Axes{});
  if (name == "_retract_r_plane") return flag(s.retract == RetractMode::RPlane);
  if (name == "_retract_old_z") return flag(s.retract == RetractMode::OldZ);
  if (name == "_spindle_rpm_mode") return flag(!s.css);
  if (name == "_spindle_css_mode") return flag(s.css);
  if (name == "_ijk_absolute_mode") return flag(s.arc_absolute);
  if (name == "_lathe_diameter_mode") return flag(s.lathe_diameter);
  if (name == "_lathe_radius_mode") return flag(!s.lathe_diameter);
  if (name == "_spindle_on") return flag(s.spindle != canon::SpindleDir::Off);
  if (name == "_spindle_cw") return flag(s.spindle == canon::SpindleDir::Cw);
  if (name == "_mist") return flag(s.mist);
  if (name == "_flood") return flag(s.flood);
  if (name == "_speed_override") return flag(s.speed_override);
  if (name == "_feed_override") return flag(s.feed_override);
  if (name == "_adaptive_feed" || name == "_feed_hold") return 0.0;
  if (name == "_feed") return s.feed / unit;
  if (name == "_rpm") return s.speed;
  if (name == "_current_tool") return s.tool;
  if (name == "_current_pocket") return s.tool;
  if (name == "_selected_tool") return s.selected_tool;
  if (name == "_selected_pocket") return s.selected_tool;
  if (name == "_value") return value_;
  if (name == "_value_returned") return flag(value_returned_);
  if (name == "_call_level") return static_cast<double>(frames_.size());
  if (name == "_remap_level") return 0.0;
  if (name == "_task") return 0.0;  // not running inside a machine's task
  if (name == "_vmajor") return 2.9;
  if (name == "_vminor") return 0.0;
  return std::nullopt;
}

}  // namespace usina::gcode
