// G5 cubic, G5.1 quadratic and G5.2/G5.3 NURBS moves (LinuxCNC G-code
// reference), linearised to spline_tolerance_mm as feed moves.
#include <fmt/format.h>

#include "core/spline.hpp"
#include "gcode/interp/block_words.hpp"
#include "gcode/interp/interpreter.hpp"

namespace usina::gcode {

void Interpreter::emit_polyline(const std::vector<Vec2>& pts) {
  const double axial = state_.pos[static_cast<std::size_t>(core::axes_of(state_.plane).axial)];
  std::vector<Vec3> points;
  points.reserve(pts.size());
  for (const Vec2& p : pts)
    points.push_back(core::from_plane(p, axial, state_.plane));
  machine_.spline(points);
}

// G6.2 (LinuxCNC 2.10): a NURBS with explicit knots, in the active plane.
// Each G6.2 block adds a control point (its axis words, R weight) with its K
// knot, or a knot alone; P is the order, Q the controller's interpolation
// method (no effect on the path). The curve is complete when it has as many
// knots as points plus the order.
bool Interpreter::nurbs_g6(BlockWords& w, const Axes& end) {
  if (g6_.points.empty() && g6_.knots.empty()) {
    if (!w.has('P'))
      return error(core::Code::MissingWord, 0, "the first G6.2 block needs P (the order)");
    const auto order = whole(w, 'P', 2, 64);
    if (!order) return false;
    g6_.order = *order;
  }
  if (w.has_axis()) {
    const double weight = w.has('R') ? w.get('R') : 1.0;
    if (auto valid = core::check_nurbs_weight(weight, g6_.points.size()); !valid) {
      return error(core::Code::SplineBadValue, w.col_of('R'), valid.error());
    }
    g6_.points.push_back(core::in_plane(xyz(end), state_.plane));
    g6_.weights.push_back(weight);
  }
  if (w.has('K')) g6_.knots.push_back(w.get('K'));
  if (g6_.knots.size() < g6_.points.size() + static_cast<std::size_t>(g6_.order)) return true;
  if (auto valid = core::check_nurbs(g6_.order, g6_.points, g6_.weights); !valid) {
    g6_ = {};
    return error(core::Code::SplineBadValue, 0, valid.error());
  }
  core::Nurbs curve{g6_.order, g6_.points, g6_.weights, g6_.knots};
  for (std::size_t i = 1; i < curve.knots.size(); ++i) {
    if (curve.knots[i] < curve.knots[i - 1]) {
      g6_ = {};
      return error(core::Code::SplineBadValue, 0, "G6.2 knots must not decrease");
    }
  }
  g6_ = {};
  emit_polyline(core::linearize(curve, options_.spline_tolerance_mm));
  return true;
}

bool Interpreter::spline(BlockWords& w, GCode g, const Axes& end) {
  if (g == 62) return require_feed(w) && nurbs_g6(w, end);
  if (state_.plane != core::Plane::XY) {
    return error(core::Code::NotAllowedInMode, 0,
                 fmt::format("{} works in the XY plane (G17) only", g_name(g).data()));
  }
  if (state_.comp != CompSideState::Off) {
    return error(core::Code::NotAllowedInMode, 0, "splines with cutter compensation on");
  }
  if (w.has('Z') || w.has('A') || w.has('B') || w.has('C')) {
    return error(core::Code::SplineBadValue, 0,
                 fmt::format("{} moves X and Y only", g_name(g).data()));
  }
  if (!require_feed(w)) return false;
  const Vec2 start{state_.pos[0], state_.pos[1]};
  const Vec2 stop{end[0], end[1]};
  const double tol = options_.spline_tolerance_mm;
  if (g == 50) {
    if (!w.has('P') || !w.has('Q'))
      return error(core::Code::MissingWord, 0, "G5 needs P and Q (the second control point)");
    if (w.has('I') != w.has('J'))
      return error(core::Code::MissingWord, 0, "G5 takes I and J together, or neither");
    Vec2 ij;
    if (w.has('I')) {
      ij = {mm(w.get('I')), mm(w.get('J'))};
    } else if (last_g5_ctrl_) {
      ij = *last_g5_ctrl_;  // continues the previous G5's tangent
    } else {
      return error(core::Code::MissingWord, 0, "G5 without I and J must follow another G5");
    }
    const Vec2 pq{mm(w.get('P')), mm(w.get('Q'))};
    emit_polyline(core::linearize(core::cubic_from_g5(start, stop, ij, pq), tol));
    last_g5_ctrl_ = -pq;
    return true;
  }
  last_g5_ctrl_.reset();
  if (g == 51) {
    if (!w.has('I') && !w.has('J'))
      return error(core::Code::MissingWord, 0, "G5.1 needs I and J (the control point)");
    const Vec2 ij{w.has('I') ? mm(w.get('I')) : 0.0, w.has('J') ? mm(w.get('J')) : 0.0};
    emit_polyline(core::linearize(core::quad_from_g5_1(start, stop, ij), tol));
    return true;
  }
  if (g == 52) {
    if (nurbs_points_.empty()) {
      nurbs_points_.push_back(start);
      nurbs_weights_.push_back(1.0);
      // LinuxCNC: order L when above 3, otherwise 3.
      std::optional<int> order;
      if (w.has('L') && !(order = whole(w, 'L', 0, 64))) return false;
      nurbs_order_ = order && *order > 3 ? *order : 3;
    }
    const double weight = w.has('P') ? w.get('P') : 1.0;
    if (auto valid = core::check_nurbs_weight(weight, nurbs_points_.size()); !valid) {
      return error(core::Code::SplineBadValue, w.col_of('P'), valid.error());
    }
    if (w.has('X') || w.has('Y')) {
      nurbs_points_.push_back(stop);
      nurbs_weights_.push_back(weight);
    } else {
      nurbs_weights_.back() = weight;
    }
    return true;
  }
  // G5.3: the NURBS block is complete.
  if (auto valid = core::check_nurbs(nurbs_order_, nurbs_points_, nurbs_weights_); !valid) {
    return error(core::Code::SplineBadValue, 0, valid.error());
  }
  const core::Nurbs curve = core::make_nurbs(nurbs_order_, nurbs_points_, nurbs_weights_);
  nurbs_points_.clear();
  nurbs_weights_.clear();
  emit_polyline(core::linearize(curve, tol));
  state_.motion = 800;
  return true;
}

}  // namespace usina::gcode
