// Cutter radius compensation: the state machine, straight moves and the
// held-move queue. Arcs and the concave-corner geometry are in
// cutter_comp_arc.cpp. Rules cite LinuxCNC 2.10 src/emc/rs274ngc/.
#include "gcode/interp/cutter_comp.hpp"

#include <cmath>
#include <cstdlib>
#include <utility>

#include <fmt/format.h>

#include "core/tolerance.hpp"
#include "core/units.hpp"

namespace usina::gcode {
namespace {

using core::Code;
using core::kPi;

// interp_internal.hh TOLERANCE_CONCAVE_CORNER: corners within this many
// radians of tangent get neither an arc nor an intersection.
constexpr double kTangent = 0.05;
// interp_queue.cc move_endpoint_and_flush: a held arc whose end is moved may
// sweep this much more (radians) before it counts as gouging. LinuxCNC
// compares the turns with a length: .001 under G20, .0254 under G21.
constexpr double kSweepSlack = 0.001;
constexpr double kSweepSlackMetric = 0.0254;

double angle_of(Vec2 v) {
  return std::atan2(v.y, v.x);
}

tl::unexpected<InterpError> error(Code code, std::string message) {
  return interp_error(code, std::move(message));
}

}  // namespace

InterpResult CutterComp::start(CompSide side, double radius, core::Plane plane, int orientation,
                               bool metric) {
  // interp_convert.cc convert_cutter_compensation_on.
  if (side == CompSide::Off) {
    return error(Code::CompNotAllowed,
                 "cutter compensation side must be left (G41) or right (G42)");
  }
  if (active()) {
    return error(Code::CompNotAllowed,
                 "cutter radius compensation is already on; program G40 before G41/G42");
  }
  if (plane != core::Plane::XY && plane != core::Plane::ZX) {
    return error(Code::CompNotAllowed,
                 "cutter radius compensation works only in the XY (G17) or XZ (G18) plane; "
                 "select G17 or G18 first");
  }
  if (plane != core::Plane::ZX && orientation != 0 && orientation != 9) {
    return error(
        Code::CompNotAllowed,
        fmt::format("a lathe tool (orientation {}) can be compensated only in G18", orientation));
  }
  // A negative radius swaps the side (same function, "switch side & make
  // radius positive").
  if (radius < 0.0) side = side == CompSide::Left ? CompSide::Right : CompSide::Left;
  side_ = side;
  radius_ = std::fabs(radius);
  plane_ = plane;
  orientation_ = orientation;
  metric_ = metric;
  first_move_ = true;
  return {};
}

std::optional<Vec3> CutterComp::programmed_position() const {
  if (!compensating() || first_move_) return std::nullopt;
  return core::from_plane(programmed_, axial_, plane_);
}

InterpResult CutterComp::straight(const Vec3& programmed_end, bool rapid,
                                  const core::SourceLoc& loc, MotionTarget& target) {
  // convert_straight: any straight move allows arcs again.
  if (!compensating()) return pass_straight(programmed_end, rapid, loc, target);
  arc_not_allowed_ = false;
  const Vec2 end = core::in_plane(programmed_end, plane_);
  const double axial = programmed_end[core::axes_of(plane_).axial];
  if (first_move_) return entry_straight(end, axial, rapid, loc, target);
  return next_straight(end, axial, rapid, loc, target);
}

InterpResult CutterComp::pass_straight(const Vec3& end, bool rapid, const core::SourceLoc& loc,
                                       MotionTarget& target) {
  arc_not_allowed_ = false;
  target.set_source(loc);
  if (rapid) {
    target.traverse(end);
  } else {
    target.feed(end);
  }
  return {};
}

// interp_convert.cc convert_straight_comp1: the entry move ends a tool
// radius from the programmed end, perpendicular to the entry move.
InterpResult CutterComp::entry_straight(Vec2 end, double axial, bool rapid,
                                        const core::SourceLoc& loc, const MotionTarget& target) {
  const Vec2 from = core::in_plane(target.position(), plane_);
  const double length = distance(from, end);
  if (not_beyond_radius(length)) {
    return error(Code::CompEntryMove,
                 fmt::format("cutter compensation entry move is {:.4g} mm long, not longer than "
                             "the tool radius {:.4g} mm; start farther from the contour",
                             length, radius_));
  }
  const Vec2 normal = core::perp((end - from) / length) * side_sign();
  const Vec2 tool = end + normal * radius_;
  queue_start_ = from;
  // LinuxCNC records the entry move's direction as the offset normal.
  hold(straight_move(rapid ? Kind::Traverse : Kind::Feed, loc, tool, axial, normal));
  first_move_ = false;
  tool_ = tool;
  programmed_ = end;
  axial_ = axial;
  return {};
}

// interp_convert.cc convert_straight_comp2.
InterpResult CutterComp::next_straight(Vec2 end, double axial, bool rapid,
                                       const core::SourceLoc& loc, MotionTarget& target) {
  const Kind kind = rapid ? Kind::Traverse : Kind::Feed;
  if (end == programmed_) {
    // No motion in the plane: held with the move before it, so it happens
    // at that move's (possibly moved) end.
    hold(straight_move(kind, loc, tool_, axial));
    axial_ = axial;
    return {};
  }
  const Vec2 along = end - programmed_;
  const double out_of = angle_of(along);
  const double into = angle_of(tool_ - programmed_) - side_sign() * kPi / 2;
  const double beta = corner_turn(into, out_of);
  const Vec2 normal = core::perp(along / norm(along)) * side_sign();
  // An "h" shape: coming over a round top with the tool outside it, then
  // turning back along a straight side; LinuxCNC keeps the tool above it.
  const bool h_shape = beta > kPi - kTangent && !queue_.empty() &&
                       queue_.front().kind == Kind::Arc && !tool_inside(queue_.front().turn);
  if (beta < -kTangent || beta > kPi + kTangent || h_shape) {
    if (!queue_.empty()) {
      const bool after_arc = queue_.front().kind == Kind::Arc;
      const std::optional<Vec2> corner = after_arc ? arc_line_corner(end) : line_line_corner(beta);
      const char* what = after_arc ? "arc to straight" : "straight to straight";
      if (auto e = trim_concave(corner, what, target); !e) return e;
    }
  } else if (beta > kTangent) {
    // Convex: the held move keeps its end; an arc round the corner.
    if (auto e = move_end_and_release(tool_, target); !e) return e;
    emit_corner(programmed_ + normal * radius_, programmed_, rapid, loc, target);
  } else {
    release(target);
    queue_start_ = tool_;
  }
  const Vec2 tool = end + normal * radius_;
  hold(straight_move(kind, loc, tool, axial, along));
  tool_ = tool;
  programmed_ = end;
  axial_ = axial;
  return {};
}

// The retreat along the held straight move from its end, half the inside
// corner's angle (convert_straight_comp2, "line->line").
std::optional<Vec2> CutterComp::line_line_corner(double beta) const {
  const double into = angle_of(tool_ - programmed_) - side_sign() * kPi / 2;
  const double retreat = radius_ / std::tan((beta + kPi) / 2);
  return tool_ - Vec2{std::cos(into), std::sin(into)} * retreat;
}

void CutterComp::emit_corner(Vec2 to, Vec2 about, bool rapid, const core::SourceLoc& loc,
                             MotionTarget& target) {
  // The corner has no axial motion: that is all on the programmed move. G0
  // has no arc: LinuxCNC goes straight to the next move's start.
  const int turn = side_ == CompSide::Left ? -1 : 1;
  emit(rapid ? straight_move(Kind::Traverse, loc, to, axial_)
             : arc_move(loc, to, axial_, {about, axial_, turn}, 0.0),
       target);
  queue_start_ = to;
}

// interp_convert.cc convert_cutter_compensation_off.
InterpResult CutterComp::stop(MotionTarget& target) {
  if (compensating() && !first_move_) {
    if (auto e = move_end_and_release(tool_, target); !e) return e;
    queue_start_.reset();
    arc_not_allowed_ = true;
  }
  side_ = CompSide::Off;
  first_move_ = true;
  return {};
}

// interp_convert.cc convert_stop.
InterpResult CutterComp::flush(MotionTarget& target) {
  if (auto e = move_end_and_release(tool_, target); !e) return e;
  release(target);
  return {};
}

void CutterComp::defer(const core::SourceLoc& loc, Deferred op, MotionTarget& target) {
  // interp_queue.cc enqueue_*: immediate when nothing is held.
  if (queue_.empty()) {
    target.set_source(loc);
    op(target);
    return;
  }
  Held h;
  h.kind = Kind::Deferred;
  h.loc = loc;
  h.op = std::move(op);
  hold(std::move(h));
}

CutterComp::Held CutterComp::straight_move(Kind kind, const core::SourceLoc& loc, Vec2 end,
                                           double axial, Vec2 direction) {
  Held h;
  h.kind = kind;
  h.loc = loc;
  h.end = end;
  h.axial = axial;
  h.direction = direction;
  return h;
}

CutterComp::Held CutterComp::arc_move(const core::SourceLoc& loc, Vec2 end, double axial,
                                      const About& about, double sweep) {
  Held h = straight_move(Kind::Arc, loc, end, axial);
  h.center = about.center;
  h.center_axial = about.axial;
  h.turn = about.turn;
  h.sweep = sweep;
  return h;
}

// LinuxCNC's "not greater than the tool radius" (length <= radius), except
// that a length equal to the radius within rounding passes: LinuxCNC's own
// radius comes out a hair smaller then, and the reference trace of
// nc_files/useful-subroutines.ngc (entry move and arc radius both exactly
// the tool radius) shows no error.
bool CutterComp::not_beyond_radius(double length) const {
  return length <= radius_ && !core::nearly_equal(length, radius_, 1e-9);
}

bool CutterComp::tool_inside(int turn) const {
  // interp_convert.cc TOOL_INSIDE_ARC: left of a counter-clockwise arc.
  return (side_ == CompSide::Left && turn > 0) || (side_ == CompSide::Right && turn < 0);
}

// How far the path turns at a corner from the direction `into` to `out_of`,
// positive away from the tool (convex), in [-π/2, 3π/2): LinuxCNC's β.
double CutterComp::corner_turn(double into, double out_of) const {
  const double t = std::fmod(side_sign() * (into - out_of) + kPi / 2, 2 * kPi);
  return (t < 0.0 ? t + 2 * kPi : t) - kPi / 2;
}

Vec3 CutterComp::to_program(Vec2 p, double axial) const {
  Vec3 v = core::from_plane(p, axial, plane_);
  if (plane_ != core::Plane::ZX) return v;
  // interp_queue.cc latheorigin_x/z: from the nose-radius centre to the
  // lathe tool's origin.
  const int o = orientation_;
  if (o == 1 || o == 2 || o == 6) v.x -= radius_;
  if (o == 3 || o == 4 || o == 8) v.x += radius_;
  if (o == 2 || o == 3 || o == 7) v.z -= radius_;
  if (o == 1 || o == 4 || o == 5) v.z += radius_;
  return v;
}

void CutterComp::emit(const Held& h, MotionTarget& target) const {
  target.set_source(h.loc);
  switch (h.kind) {
  case Kind::Traverse: target.traverse(to_program(h.end, h.axial)); break;
  case Kind::Feed: target.feed(to_program(h.end, h.axial)); break;
  case Kind::Arc:
    target.arc(to_program(h.end, h.axial), to_program(h.center, h.center_axial), h.turn);
    break;
  case Kind::Deferred: h.op(target); break;
  }
}

// interp_queue.cc dequeue_canons: everything held goes out as it is, and
// where the next held move starts is not known until told.
void CutterComp::release(MotionTarget& target) {
  // emit() does not touch the queue; clear() keeps its storage for the next
  // block.
  for (const Held& h : queue_)
    emit(h, target);
  queue_.clear();
  queue_start_.reset();
}

// interp_queue.cc move_endpoint_and_flush: every held move now ends at
// `to`; an error, and nothing changed, if that reverses a straight move or
// lengthens an arc.
InterpResult CutterComp::move_end_and_release(Vec2 to, MotionTarget& target) {
  if (queue_.empty()) return {};
  for (const Held& h : queue_) {
    if (auto e = check_move_end(h, to); !e) return e;
  }
  for (Held& h : queue_) {
    if (h.kind != Kind::Deferred) h.end = to;
  }
  release(target);
  queue_start_ = to;
  return {};
}

InterpResult CutterComp::check_move_end(const Held& h, Vec2 to) const {
  if (!queue_start_ || h.kind == Kind::Deferred) return {};
  const Vec2 from = *queue_start_;
  if (h.kind == Kind::Arc) {
    const double sweep = core::arc_sweep(from, to, h.center, h.turn > 0, std::abs(h.turn));
    const double slack = metric_ ? kSweepSlackMetric : kSweepSlack;
    if (h.sweep == 0.0 || std::fabs(sweep) <= std::fabs(h.sweep) + slack) return {};
    return error(Code::CutterGouge,
                 fmt::format("cutter gouging: the tool (radius {:.4g} mm) does not fit the "
                             "concave corner after the previous arc; that arc would have to end "
                             "before it starts; use a smaller tool or a longer arc",
                             radius_));
  }
  if (dot(h.direction, to - from) >= 0.0) return {};
  return error(Code::CutterGouge,
               fmt::format("cutter gouging: the tool (radius {:.4g} mm) does not fit the concave "
                           "corner after the previous straight move; that move would have to run "
                           "backwards; use a smaller tool or a longer move",
                           radius_));
}

InterpResult CutterComp::trim_concave(std::optional<Vec2> corner, const char* what,
                                      MotionTarget& target) {
  if (!corner) {
    return error(Code::CutterGouge,
                 fmt::format("cutter gouging: the tool (radius {:.4g} mm) does not fit this "
                             "concave {} corner; the offset paths do not meet; use a smaller tool",
                             radius_, what));
  }
  return move_end_and_release(*corner, target);
}

}  // namespace usina::gcode
