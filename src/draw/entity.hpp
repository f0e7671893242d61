// The plane entities of a drawing (LINE, ARC, CIRCLE, POLYLINE) in the XY
// plane, in mm.
#pragma once

#include <variant>
#include <vector>

#include "core/vec3.hpp"

namespace usina::draw {

using core::Vec2;

struct Line {
  Vec2 from;
  Vec2 to;

  bool operator==(const Line&) const = default;
};

// A true arc: from `start_angle` to `end_angle` (radians, in (-π, π]) about
// `center`, counter-clockwise when `ccw`, clockwise otherwise; never a full
// circle (that is a Circle).
struct Arc {
  Vec2 center;
  double radius = 0.0;
  double start_angle = 0.0;
  double end_angle = 0.0;
  bool ccw = true;

  bool operator==(const Arc&) const = default;
};

struct Circle {
  Vec2 center;
  double radius = 0.0;

  bool operator==(const Circle&) const = default;
};

struct Polyline {
  std::vector<Vec2> points;
  bool closed = false;

  bool operator==(const Polyline&) const = default;
};

using Entity = std::variant<Line, Arc, Circle, Polyline>;

}  // namespace usina::draw
