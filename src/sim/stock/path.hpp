// A straight move of the tool's tip in the frame of its XY projection, as the
// sweep (sweep.cpp) and the holder's check (holder.cpp) both see it.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/vec3.hpp"

namespace usina::sim::stock {

// A cell at `along` mm from the start along the path and `e` mm beside it is
// under the tool's axis at s = along + u when u² + e² <= R²; the tip is then
// at z0 + k s (Z relative to the stock's top).
struct Path {
  double ax = 0.0, ay = 0.0, z0 = 0.0;
  double ux = 1.0, uy = 0.0;  // unit XY direction (any, for a plunge)
  double length = 0.0;        // mm of XY
  double k = 0.0;             // dz per mm of XY (0 for a plunge, z0 the lower end)
  bool rises = false;         // the tip ends higher than it starts
  double drop = 0.0;          // a plunge's Z travel, mm (0 for any other move)

  double tip(double s) const { return z0 + k * s; }

  // The tip's lowest over [s1, s2] (a line: one of its ends).
  double tip_lowest(double s1, double s2) const { return k > 0.0 ? tip(s1) : tip(s2); }
};

inline Path path_of(const core::Vec3& a, const core::Vec3& b, double top) {
  Path p;
  p.ax = a.x;
  p.ay = a.y;
  p.rises = b.z > a.z;
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  p.length = std::hypot(dx, dy);
  // Below a nanometre of XY a move is a plunge: its tool stands at one place.
  if (p.length < 1e-9) {
    p.length = 0.0;
    p.z0 = std::min(a.z, b.z) - top;
    p.drop = std::fabs(a.z - b.z);
    return p;
  }
  p.ux = dx / p.length;
  p.uy = dy / p.length;
  p.z0 = a.z - top;
  p.k = (b.z - a.z) / p.length;
  return p;
}

// The square of the cell's distance from the path's XY projection.
inline double distance2(const Path& p, double along, double e) {
  const double past = along < 0.0 ? along : (along > p.length ? along - p.length : 0.0);
  return e * e + past * past;
}

// The stretch [first, last] of the path, in s, during which a disc of radius
// `w` mm along the path (w = √(R² − e²) for a cell e mm beside it) covers a
// cell at `along`; empty (first > last) when it does not.
struct Stretch {
  double first = 0.0, last = -1.0;

  bool empty() const { return first > last; }
};

inline Stretch covering(const Path& p, double along, double w) {
  return {std::max(0.0, along - w), std::min(p.length, along + w)};
}

}  // namespace usina::sim::stock
