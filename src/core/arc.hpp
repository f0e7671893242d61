// Arc geometry in a plane: centre from R, sweep, length, linearisation.
#pragma once

#include <optional>
#include <vector>

#include "core/vec3.hpp"

namespace usina::core {

// The selected plane and its axes as RS274NGC orders them (first, second,
// axial), so an arc is counter-clockwise when seen from the tip of the normal.
enum class Plane { XY, ZX, YZ };

struct PlaneAxes {
  int first;
  int second;
  int axial;
};

constexpr PlaneAxes axes_of(Plane p) {
  switch (p) {
  case Plane::XY: return {0, 1, 2};
  case Plane::ZX: return {2, 0, 1};
  case Plane::YZ: return {1, 2, 0};
  }
  return {0, 1, 2};
}

inline Vec3 normal_of(Plane p) {
  Vec3 n;
  n[axes_of(p).axial] = 1.0;
  return n;
}

inline Vec2 in_plane(const Vec3& v, Plane p) {
  const PlaneAxes a = axes_of(p);
  return {v[a.first], v[a.second]};
}

// Rebuilds a 3-D point from plane coordinates and an axial coordinate.
inline Vec3 from_plane(const Vec2& v, double axial, Plane p) {
  const PlaneAxes a = axes_of(p);
  Vec3 r;
  r[a.first] = v.x;
  r[a.second] = v.y;
  r[a.axial] = axial;
  return r;
}

// Angle swept from `start` to `end` about `center`: positive for
// counter-clockwise, in (0, 2π] (a full circle when start == end), plus
// 2π for each extra turn (`turns` ≥ 1; 1 = less than one revolution).
double arc_sweep(Vec2 start, Vec2 end, Vec2 center, bool ccw, int turns = 1);

// Centre of the arc of radius |r| from start to end (RS274NGC 3.5.3.1:
// r > 0 takes the shorter arc, r < 0 the longer). Nullopt when the chord is
// longer than the diameter by more than `tol`; a chord of up to 2|r| + tol
// gives the centre on the chord's midpoint.
std::optional<Vec2> arc_center_from_radius(Vec2 start, Vec2 end, double r, bool ccw,
                                           double tol = 1e-6);

// Length of a helix: sweep |angle| at radius r while moving `axial` along the axis.
double helix_length(double radius, double sweep, double axial);

// Number of straight segments that keep a chord of an arc of `radius`
// within `tolerance` of the arc over `sweep` radians (at least 1).
int segments_for_tolerance(double radius, double sweep, double tolerance);

// Points along an arc/helix from `start` (excluded) to its end (included),
// chordal error at most `tolerance`.
std::vector<Vec3> linearize_arc(const Vec3& start, const Vec3& end, const Vec3& center, Plane plane,
                                double sweep, double tolerance);

}  // namespace usina::core
