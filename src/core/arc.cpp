#include "core/arc.hpp"

#include <algorithm>
#include <cmath>

#include "core/units.hpp"

namespace usina::core {

double arc_sweep(Vec2 start, Vec2 end, Vec2 center, bool ccw, int turns) {
  const double a0 = std::atan2(start.y - center.y, start.x - center.x);
  const double a1 = std::atan2(end.y - center.y, end.x - center.x);
  double sweep = a1 - a0;
  // Within a hair of a full circle counts as a full circle (RS274NGC closes
  // an arc whose end equals its start into a full turn).
  constexpr double kFullTolerance = 1e-12;
  if (ccw) {
    while (sweep <= kFullTolerance)
      sweep += 2.0 * kPi;
  } else {
    while (sweep >= -kFullTolerance)
      sweep -= 2.0 * kPi;
  }
  const double extra = 2.0 * kPi * static_cast<double>(std::max(turns, 1) - 1);
  return ccw ? sweep + extra : sweep - extra;
}

std::optional<Vec2> arc_center_from_radius(Vec2 start, Vec2 end, double r, bool ccw, double tol) {
  const Vec2 chord = end - start;
  const double half = norm(chord) / 2.0;
  const double radius = std::fabs(r);
  if (half == 0.0 || half > radius + tol) return std::nullopt;
  const Vec2 mid = (start + end) / 2.0;
  const double h = half >= radius ? 0.0 : std::sqrt(radius * radius - half * half);
  const Vec2 left = perp(chord) / (2.0 * half);  // unit normal to the left of the chord
  // CCW with the short arc puts the centre left of the chord; each flip
  // (CW, or a long arc) moves it to the other side.
  const bool left_side = ccw == (r > 0);
  return left_side ? mid + left * h : mid - left * h;
}

double helix_length(double radius, double sweep, double axial) {
  return std::hypot(radius * sweep, axial);
}

int segments_for_tolerance(double radius, double sweep, double tolerance) {
  if (radius <= tolerance || tolerance <= 0.0) return 1;
  // Sagitta of a chord subtending angle θ is r(1 − cos(θ/2)).
  const double max_step = 2.0 * std::acos(1.0 - tolerance / radius);
  const double n = std::ceil(std::fabs(sweep) / max_step);
  return static_cast<int>(std::clamp(n, 1.0, 1e7));
}

std::vector<Vec3> linearize_arc(const Vec3& start, const Vec3& end, const Vec3& center, Plane plane,
                                double sweep, double tolerance) {
  const PlaneAxes ax = axes_of(plane);
  const Vec2 c = in_plane(center, plane);
  const Vec2 s = in_plane(start, plane) - c;
  const double radius = norm(s);
  const int n = segments_for_tolerance(radius, sweep, tolerance);
  std::vector<Vec3> pts;
  pts.reserve(static_cast<std::size_t>(n));
  for (int i = 1; i < n; ++i) {
    const double t = static_cast<double>(i) / n;
    const Vec2 p = c + rotate(s, sweep * t);
    const double axial = start[ax.axial] + (end[ax.axial] - start[ax.axial]) * t;
    pts.push_back(from_plane(p, axial, plane));
  }
  pts.push_back(end);
  return pts;
}

}  // namespace usina::core
