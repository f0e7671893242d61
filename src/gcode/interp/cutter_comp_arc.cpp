// Cutter radius compensation: arcs, and where a held move ends at a concave
// corner. Rules cite LinuxCNC 2.10 src/emc/rs274ngc/interp_convert.cc.
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "core/units.hpp"
#include "gcode/interp/cutter_comp.hpp"

namespace usina::gcode {
namespace {

using core::Code;
using core::kPi;

// interp_internal.hh TOLERANCE_CONCAVE_CORNER, as in cutter_comp.cpp.
constexpr double kTangent = 0.05;
// interp_internal.hh TOLERANCE_EQUAL.
constexpr double kEqual = 1e-6;

double angle_of(Vec2 v) {
  return std::atan2(v.y, v.x);
}

Vec2 unit_at(double angle) {
  return {std::cos(angle), std::sin(angle)};
}

Vec2 unit(Vec2 v) {
  return v / norm(v);
}

tl::unexpected<InterpError> tool_too_big(double arc_radius, double tool_radius) {
  return interp_error(
      Code::CompToolTooBig,
      fmt::format("the arc's radius {:.4g} mm is not larger than the tool radius {:.4g} mm, "
                  "and the tool is inside it; use a smaller tool or a larger arc",
                  arc_radius, tool_radius));
}

// Where the line `from` + λ·`along` (a unit vector) meets the circle about
// `center` of `radius`: the point with the larger λ when `far`.
std::optional<Vec2> line_meets_circle(Vec2 from, Vec2 along, Vec2 center, double radius, bool far) {
  const Vec2 d = from - center;
  const double b = dot(d, along);
  const double disc = b * b - (dot(d, d) - radius * radius);
  if (disc < 0.0) return std::nullopt;
  const double root = std::sqrt(disc);
  return from + along * (far ? -b + root : -b - root);
}

}  // namespace

InterpResult CutterComp::arc(const Vec3& programmed_end, const Vec3& programmed_center, int turn,
                             const core::SourceLoc& loc, MotionTarget& target) {
  // interp_convert.cc convert_arc.
  if (arc_not_allowed_) {
    return interp_error(Code::CompNotAllowed,
                        "the move just after G40 must be straight, not an arc; add a straight "
                        "exit move");
  }
  if (!compensating()) {
    target.set_source(loc);
    target.arc(programmed_end, programmed_center, turn);
    return {};
  }
  const ArcIn in{.end = core::in_plane(programmed_end, plane_),
                 .center = core::in_plane(programmed_center, plane_),
                 .axial = programmed_end[core::axes_of(plane_).axial],
                 .turn = turn};
  return first_move_ ? entry_arc(in, loc, target) : next_arc(in, loc, target);
}

// interp_convert.cc convert_arc_comp1: the entry arc ends a tool radius from
// the programmed end along the arc's radius; it starts where the tool is, on
// a circle whose centre is on the line from that end to the programmed centre.
InterpResult CutterComp::entry_arc(const ArcIn& in, const core::SourceLoc& loc,
                                   const MotionTarget& target) {
  const Vec3 at = target.position();
  const Vec2 from = core::in_plane(at, plane_);
  const double from_axial = at[core::axes_of(plane_).axial];
  const double chord = distance(from, in.end);
  if (not_beyond_radius(chord)) {
    return interp_error(Code::CompEntryMove,
                        fmt::format("cutter compensation entry arc ends {:.4g} mm from its start, "
                                    "not farther than the tool radius {:.4g} mm; start farther "
                                    "from the contour",
                                    chord, radius_));
  }
  const bool inside = tool_inside(in.turn);
  // interp_arc.cc arc_data_comp_ijk measures the radius at the start.
  const double arc_radius = distance(in.center, from);
  if (inside && not_beyond_radius(arc_radius)) return tool_too_big(arc_radius, radius_);
  const Vec2 out = inside ? unit(in.center - in.end) : unit(in.end - in.center);
  const Vec2 tool = in.end + out * radius_;
  const Vec2 back = from - tool;
  const Vec2 to_center = unit(in.center - tool);
  const double cos_a = norm(back) > 0.0 ? dot(unit(back), to_center) : 0.0;
  if (std::fabs(cos_a) < kEqual) return tool_too_big(arc_radius, radius_);
  const Vec2 center = tool + to_center * (norm(back) / 2.0 / cos_a);
  if (orientation_ != 0 && orientation_ != 9) {
    // A lathe tool first moves its origin to where the arc starts.
    queue_start_ = from;
    hold(straight_move(Kind::Feed, loc, from, from_axial));
  }
  hold(arc_move(loc, tool, in.axial, {center, from_axial, in.turn},
                core::arc_sweep(from, tool, center, in.turn > 0, std::abs(in.turn))));
  first_move_ = false;
  tool_ = tool;
  programmed_ = in.end;
  axial_ = in.axial;
  return {};
}

// interp_convert.cc convert_arc_comp2: the arc keeps its centre and changes
// its radius by the tool radius.
InterpResult CutterComp::next_arc(const ArcIn& in, const core::SourceLoc& loc,
                                  MotionTarget& target) {
  const bool inside = tool_inside(in.turn);
  const double arc_radius = distance(in.center, in.end);
  if (inside && not_beyond_radius(arc_radius)) return tool_too_big(arc_radius, radius_);
  const double into = angle_of(tool_ - programmed_) - side_sign() * kPi / 2;
  const double out_of = angle_of(in.center - programmed_) - (in.turn > 0 ? kPi / 2 : -kPi / 2);
  const double beta = corner_turn(into, out_of);
  const Vec2 out = inside ? unit(in.center - in.end) : unit(in.end - in.center);
  const Held move =
      arc_move(loc, in.end + out * radius_, in.axial, {in.center, axial_, in.turn},
               core::arc_sweep(programmed_, in.end, in.center, in.turn > 0, std::abs(in.turn)));
  // Turning back onto an arc the tool is outside of is taken as concave
  // (the top of an "m" or an "h").
  if (beta < -kTangent || beta > kPi + kTangent || (std::fabs(beta - kPi) < kTangent && !inside)) {
    if (!queue_.empty()) {
      const bool after_arc = queue_.front().kind == Kind::Arc;
      const std::optional<Vec2> corner = after_arc ? arc_arc_corner(in) : line_arc_corner(in, into);
      const char* what = after_arc ? "arc to arc" : "straight to arc";
      if (auto e = trim_concave(corner, what, target); !e) return e;
    }
  } else if (beta > kTangent) {
    // Convex: round the corner to where the offset arc starts.
    release(target);
    const Vec2 start = inside ? unit(in.center - programmed_) : unit(programmed_ - in.center);
    emit_corner(programmed_ + start * radius_, programmed_, false, loc, target);
  } else {
    release(target);
    queue_start_ = tool_;
  }
  tool_ = move.end;
  programmed_ = in.end;
  axial_ = in.axial;
  hold(move);
  return {};
}

// Straight then arc: the held straight move ends where its offset line meets
// the offset circle, leaving it (tool inside the arc) or entering it.
std::optional<Vec2> CutterComp::line_arc_corner(const ArcIn& in, double into) const {
  const bool inside = tool_inside(in.turn);
  const double arc_radius = distance(in.center, in.end);
  // LinuxCNC measures the corner with the arc's end radius, so the
  // programmed corner is taken on that circle.
  const Vec2 corner = in.center + unit(programmed_ - in.center) * arc_radius;
  const Vec2 on_line = corner + unit(tool_ - programmed_) * radius_;
  const double offset_radius = inside ? arc_radius - radius_ : arc_radius + radius_;
  return line_meets_circle(on_line, unit_at(into), in.center, offset_radius, inside);
}

// Arc then straight: the held arc ends where it meets the straight move's
// offset line, the first meeting along the line when the tool is inside
// the arc, else the second.
std::optional<Vec2> CutterComp::arc_line_corner(Vec2 end) const {
  const Held& prev = queue_.front();
  const bool inside = tool_inside(prev.turn);
  const double old_radius = distance(prev.center, prev.end);
  const double programmed_radius = inside ? old_radius + radius_ : old_radius - radius_;
  const Vec2 along = unit(end - programmed_);
  const Vec2 normal = core::perp(along) * side_sign();
  // As above, the programmed corner is taken on the programmed circle.
  const Vec2 corner = prev.center + unit(programmed_ - prev.center) * programmed_radius;
  return line_meets_circle(corner + normal * radius_, along, prev.center, old_radius, !inside);
}

// Arc then arc: the held arc ends where the two offset circles meet, on the
// side of the line between the centres LinuxCNC picks.
std::optional<Vec2> CutterComp::arc_arc_corner(const ArcIn& in) const {
  const Held& prev = queue_.front();
  const double old_radius = distance(prev.center, prev.end);
  const double arc_radius = distance(in.center, in.end);
  const double new_radius = tool_inside(in.turn) ? arc_radius - radius_ : arc_radius + radius_;
  const Vec2 between = in.center - prev.center;
  const double d = norm(between);
  if (old_radius == 0.0 || d == 0.0) return std::nullopt;
  const double a =
      (old_radius * old_radius + d * d - new_radius * new_radius) / (2 * old_radius * d);
  if (a > 1.0 || a < -1.0) return std::nullopt;
  const double pullback = std::acos(a);
  const bool counter_clockwise = tool_inside(prev.turn) == (in.turn > 0);
  const double dir = angle_of(between) + (counter_clockwise ? pullback : -pullback);
  return prev.center + unit_at(dir) * old_radius;
}

}  // namespace usina::gcode
