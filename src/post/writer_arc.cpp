// Arcs and helices: G2/G3 in the plane of the arc's normal, the centre as
// I J K (from the start point, or absolute where the control reads that),
// extra helix turns as P or as full circles.
#include <cmath>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "core/arc.hpp"
#include "post/writer.hpp"

namespace usina::post {

using core::Vec3;

namespace {

// 17, 18 or 19 for a normal along Z, Y or X; 0 for any other.
int plane_of(const Vec3& n) {
  if (std::abs(std::abs(n.z) - 1.0) < 1e-9) return 17;
  if (std::abs(std::abs(n.y) - 1.0) < 1e-9) return 18;
  if (std::abs(std::abs(n.x) - 1.0) < 1e-9) return 19;
  return 0;
}

core::Plane core_plane(int plane) {
  return plane == 17 ? core::Plane::XY : (plane == 18 ? core::Plane::ZX : core::Plane::YZ);
}

}  // namespace

void Writer::arc(const canon::Arc& a, const canon::Op& op) {
  cancel_cycle();
  const int plane = plane_of(a.normal);
  if (plane == 0) return unsupported(op, "an arc whose axis is not X, Y or Z");
  if (!pos_known_) return unsupported(op, "an arc before the first positioning move");
  if (!control_.rotary_axes && moves_rotary(a.abc)) return unsupported(op, "a rotary axis move");
  const core::Plane p = core_plane(plane);
  const int axial = core::axes_of(p).axial;
  // turn > 0 is counter-clockwise seen from the normal's tip; G3 is
  // counter-clockwise seen from the plane's positive axis.
  const bool ccw = (a.turn > 0) == (a.normal[axial] > 0);
  const int turns = std::abs(a.turn);
  if (plane != plane_) {
    out_.block(code('G', plane));
    plane_ = plane;
  }
  const Vec3 start = pos_;
  const double sweep = std::abs(core::arc_sweep(core::in_plane(start, p), core::in_plane(a.to, p),
                                                core::in_plane(a.center, p), ccw, turns));
  const double radius = core::norm(core::in_plane(start, p) - core::in_plane(a.center, p));
  const double length = core::helix_length(radius, sweep, a.to[axial] - start[axial]);
  const bool rotary = moves_rotary(a.abc);
  RateWords f = rate_words({a.f, a.programmed, length, rotary}, op);
  if (feed_mode_ == 93 && turns > 1 && !control_.turns_word) {
    // G93's F is the time of one block; a split arc would need one of its own.
    return unsupported(op, "an inverse-time (G93) arc of a rotary axis split into blocks");
  }
  if (turns > 1 && !control_.turns_word) {
    // A helix of several turns as full circles, then the last part.
    const double per_turn = (a.to[axial] - start[axial]) * 2.0 * std::numbers::pi / sweep;
    for (int k = 1; k < turns; ++k) {
      Vec3 to = start;
      to[axial] = start[axial] + per_turn * k;
      arc_block(a, to, ccw, 1, plane, f);
    }
    arc_block(a, a.to, ccw, 1, plane, f);
    return;
  }
  arc_block(a, a.to, ccw, turns, plane, f);
}

void Writer::arc_block(const canon::Arc& a, const Vec3& to, bool ccw, int turns, int plane,
                       RateWords& rate) {
  static constexpr char kCentre[] = {'I', 'J', 'K'};
  const core::PlaneAxes ax = core::axes_of(core_plane(plane));
  if (turns == 1 && control_.full_circle_halves &&
      out_.rounded(to[ax.first]) == axes_[static_cast<std::size_t>(ax.first)] &&
      out_.rounded(to[ax.second]) == axes_[static_cast<std::size_t>(ax.second)]) {
    // Through the point opposite the start, half the helix's drop there.
    Vec3 mid = a.center * 2.0 - pos_;
    mid[ax.axial] = (pos_[ax.axial] + to[ax.axial]) / 2;
    arc_block(a, mid, ccw, 1, plane, rate);
    arc_block(a, to, ccw, 1, plane, rate);
    return;
  }
  std::string w = std::move(rate.mode);  // the feed mode leads the first block
  rate.mode.clear();
  append(w, motion_word(code('G', ccw ? 3 : 2).c_str()));
  // The start as the reader has it, so that its centre is the rounded centre.
  const Vec3 start{axes_[0].value_or(pos_.x), axes_[1].value_or(pos_.y), axes_[2].value_or(pos_.z)};
  std::string axes = axis_words(to, a.abc, canon::Op{});
  if (axes.empty()) {
    // A full circle: its end point is the start; write one axis so the block moves.
    const int first = ax.first;
    axes = fmt::format("{}{}", "XYZ"[first], out_.number(to[first]));
  }
  append(w, axes);
  for (const int i : {0, 1, 2}) {
    if (i == ax.axial) continue;
    const double c = out_.rounded(a.center[i]);
    const double v = control_.absolute_arc_center ? c : c - out_.rounded(start[i]);
    out_.append_word(w, kCentre[i], v);
  }
  if (turns > 1) append(w, fmt::format("P{}", turns));
  append(w, rate.f);
  rate.f.clear();
  pos_ = to;
  out_.block(w);
}

}  // namespace usina::post
