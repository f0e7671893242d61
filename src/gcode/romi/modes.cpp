// The romi dialect's handlers of modes and machine functions: plane,
// distance, units, retract, motion, cutter compensation, the
// transformations (G30/G31 mirror, G72 scale, G73 rotation), tool change,
// spindle, coolant, stop and end (spec/romi.md). Each works on the block's
// copy of the modal state.
#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "gcode/romi/translate.hpp"

namespace usina::gcode::romi {

Vec2 Transform::apply(Vec2 p) const {
  Vec2 q = p;
  if (rotation_deg != 0.0) {
    const Vec2 r = core::rotate(Vec2{q.x - rotation_at.x, q.y - rotation_at.y},
                                core::deg_to_rad(rotation_deg));
    q = {r.x + rotation_at.x, r.y + rotation_at.y};
  }
  q = {q.x * scale_x, q.y * scale_y};
  if (mirror_x) q.x = 2.0 * mirror_at.x - q.x;
  if (mirror_y) q.y = 2.0 * mirror_at.y - q.y;
  return q;
}

// G17 only: the table has no G18/G19. A member, as every handler is.
bool Translator::h_plane(int) {  // NOLINT(readability-convert-member-functions-to-static)
  return true;
}

bool Translator::h_distance(int code) {
  work_.machine.incremental = code == 910;
  return true;
}

bool Translator::h_units(int code) {
  work_.machine.units = code == 700 ? core::LengthUnit::Inch : core::LengthUnit::Mm;
  return true;
}

bool Translator::h_retract(int code) {
  work_.machine.retract = code == 990 ? RetractMode::RPlane : RetractMode::OldZ;
  return true;
}

bool Translator::h_motion(int code) {
  work_.machine.motion = code;
  if (dialect_options_.motion_cancels_cycle) work_.drill.active = false;
  return true;
}

bool Translator::h_comp(int code) {
  if (code == 400) {
    give('G', 40);
    work_.comp_on = false;
    return true;
  }
  if (work_.comp_on) {
    return error(core::Code::CompNotAllowed, 0, "cutter compensation is already on: G40 first");
  }
  double diameter = work_.tool_diameter;
  if (dialect_options_.comp_radius_from_register && work_.offset_register > 0) {
    if (const ToolEntry* t = options_.tools.find(work_.offset_register)) diameter = t->diameter;
  }
  // With one axis mirrored the part is drawn the other way round: the
  // side swaps (spec/romi.md, "Transformations").
  const bool left = (code == 410) != work_.tf.flips();
  give('G', left ? 41.1 : 42.1);
  give('D', diameter);
  work_.comp_on = true;
  return true;
}

bool Translator::h_mirror(int code) {
  if (code == 300) {
    work_.tf.mirror_x = work_.tf.mirror_y = false;
    return true;
  }
  const auto x = words_.take('X');
  const auto y = words_.take('Y');
  if (!x && !y) return error(core::Code::MissingWord, 0, "G31 needs X and/or Y: the mirror line");
  work_.tf.mirror_x = x.has_value();
  work_.tf.mirror_y = y.has_value();
  work_.tf.mirror_at = {x ? mm(*x) : 0.0, y ? mm(*y) : 0.0};
  return true;
}

bool Translator::h_scale(int) {
  const auto k = words_.take('K');
  const auto x = words_.take('X');
  const auto y = words_.take('Y');
  if (!k && !x && !y) return error(core::Code::MissingWord, 0, "G72 needs K, or X and/or Y");
  for (const char c : {'K', 'X', 'Y'}) {
    if (!words_.has(c)) continue;
    const double f = words_.get(c);
    if (!(f >= 0.05 && f <= 20.0)) {
      return error(core::Code::ScaleOutOfRange, words_.col(c),
                   fmt::format("scale factor {}{} is outside 0.05 to 20", c, f));
    }
  }
  if (k) {
    work_.tf.scale_x = work_.tf.scale_y = *k;
  } else {
    work_.tf.scale_x = x ? *x : 1.0;
    work_.tf.scale_y = y ? *y : 1.0;
  }
  return true;
}

bool Translator::h_rotate(int) {
  const auto c = words_.take('C');
  if (!c) return error(core::Code::MissingWord, 0, "G73 needs C: the angle (C0 cancels)");
  const auto i = words_.take('I');
  const auto j = words_.take('J');
  work_.tf.rotation_deg = *c;
  work_.tf.rotation_at = {i ? mm(*i) : 0.0, j ? mm(*j) : 0.0};
  return true;
}

std::optional<double> Translator::tool_diameter_from_comments() const {
  for (const CommentText& c : comments_) {
    const std::string_view t = c.text;
    for (std::size_t i = 0; i + 1 < t.size(); ++i) {
      const bool start = i == 0 || t[i - 1] == ' ' || t[i - 1] == '\t';
      if (!start || (t[i] != 'd' && t[i] != 'D')) continue;
      std::size_t j = i + 1;
      double v = 0.0;
      const auto r = std::from_chars(t.data() + j, t.data() + t.size(), v);
      if (r.ec == std::errc() && v > 0 && std::isfinite(v)) return v;
    }
  }
  return std::nullopt;
}

bool Translator::h_tool_change(int) {
  if (work_.comp_on) {
    return error(core::Code::CompNotAllowed, 0,
                 "a tool change with cutter radius compensation on: G40 first");
  }
  if (work_.machine.selected_tool < 0) {
    return error(core::Code::MissingWord, 0, "M06 with no T: give T<n>");
  }
  const int tool = work_.machine.selected_tool;
  std::optional<double> d;
  bool from_comment = false;
  if (const ToolEntry* t = options_.tools.find(tool); t != nullptr && t->diameter > 0) {
    d = t->diameter;
  } else {
    d = tool_diameter_from_comments();
    from_comment = true;
  }
  if (!d) {
    return error(core::Code::UnknownToolDiameter, 0,
                 fmt::format("the diameter of tool T{:02} is unknown: give a tool table "
                             "(--tool-table) or write d<diameter> in the block's comment",
                             tool));
  }
  const auto x = words_.take('X');
  const auto y = words_.take('Y');
  if (!hand()) return false;  // T and what came before it
  const Vec3 back = machine_position();
  // The tool-change position is the machine's, not a programmed point:
  // no transformation, and the program goes on from where it was.
  const OpOrigin origin(interp_, canon::Origin::ToolChange);
  if ((x || y) && !hand_move(0, {x ? mm(*x) : back.x, y ? mm(*y) : back.y, back.z})) return false;
  if (from_comment) {
    // The comment's d<diameter> is the tool's as a G10 L1 would set it.
    give('G', 10);
    give('L', 1);
    give('P', tool);
    give('R', *d / 2.0);
    if (!hand()) return false;
  }
  give('M', 6);
  if (!hand()) return false;
  work_.machine.tool = tool;
  work_.tool_diameter = *d;
  return !(x || y) || hand_move(0, back);
}

bool Translator::h_spindle(int code) {
  give('M', code / 10);
  return true;
}

bool Translator::h_coolant(int code) {
  give('M', code / 10);
  return true;
}

bool Translator::h_stop(int code) {
  give('M', code / 10);
  return true;
}

bool Translator::h_end(int code) {
  if (work_.blend) {
    return error(core::Code::BlendNeedsMove, 0,
                 "an arc with only R blends into the next move, and the program ends");
  }
  give('M', code / 10);
  return true;
}

}  // namespace usina::gcode::romi
