// The writers' guard against numbers that are not finite. Canon's range
// (canon/limits.hpp) keeps every number a drawing is built from finite and
// within ±1e9 mm, so this never leaves anything out; should one ever slip
// through, a writer leaves that entity out rather than hand cairo a NaN
// (which aborts inside cairo_arc) or write "nan" into a DXF or an SVG.
#pragma once

#include <cmath>
#include <variant>

#include "draw/drawing.hpp"

namespace usina::draw {

inline bool is_finite(Vec2 p) {
  return std::isfinite(p.x) && std::isfinite(p.y);
}

inline bool is_finite(const Entity& e) {
  if (const auto* l = std::get_if<Line>(&e)) return is_finite(l->from) && is_finite(l->to);
  if (const auto* a = std::get_if<Arc>(&e)) {
    return is_finite(a->center) && std::isfinite(a->radius) && std::isfinite(a->start_angle) &&
           std::isfinite(a->end_angle);
  }
  if (const auto* c = std::get_if<Circle>(&e))
    return is_finite(c->center) && std::isfinite(c->radius);
  for (const Vec2& p : std::get<Polyline>(e).points) {
    if (!is_finite(p)) return false;
  }
  return true;
}

// The part of the plane a picture shows (view_box), or the empty drawing's
// when the bounds are not finite.
inline Box finite_view_box(const Drawing& drawing) {
  const Box box = view_box(drawing.bounds());
  return is_finite(box.min) && is_finite(box.max) ? box : view_box(Box{});
}

}  // namespace usina::draw
