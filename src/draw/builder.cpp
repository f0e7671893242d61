#include "draw/builder.hpp"

#include <cmath>
#include <cstdlib>
#include <type_traits>

#include "core/arc.hpp"
#include "draw/layer_style.hpp"

namespace usina::draw {
namespace {

using core::Vec3;

Vec2 xy(const Vec3& v) {
  return {v.x, v.y};
}

// The plane an arc turns in, from its normal (the axis it is closest to).
core::Plane plane_of(const Vec3& normal) {
  const double ax = std::fabs(normal.x);
  const double ay = std::fabs(normal.y);
  const double az = std::fabs(normal.z);
  if (az >= ax && az >= ay) return core::Plane::XY;
  return ax >= ay ? core::Plane::YZ : core::Plane::ZX;
}

// A hole whose tool diameter is unknown: a cross of this half-size (mm).
constexpr double kHoleMarker = 1.0;
// Points closer than this are one point (a full circle's start and end).
constexpr double kSamePoint = 1e-6;

}  // namespace

DrawingBuilder::DrawingBuilder(Drawing& drawing, View view, core::Vec3 start)
    : drawing_(drawing), view_(view), pos_(start) {
  // The standard layers exist even when empty, so that every drawing of a
  // view has the same layer table.
  if (view_ == View::Part) {
    contour_ = &drawing_.layer(kContourLayer);
    holes_ = &drawing_.layer(kHolesLayer);
    pockets_ = &drawing_.layer(kPocketsLayer);
  }
  rapid_ = &drawing_.layer(kRapidLayer);
}

void DrawingBuilder::on(const canon::Op& op) {
  std::visit(
      [&](const auto& k) {
        using T = std::decay_t<decltype(k)>;
        if constexpr (std::is_same_v<T, canon::Traverse>) {
          traverse(k.to, op.origin);
        } else if constexpr (std::is_same_v<T, canon::Feed> || std::is_same_v<T, canon::Probe>) {
          feed(k.to, op.origin);
        } else if constexpr (std::is_same_v<T, canon::Arc>) {
          arc(k, op.origin);
        } else if constexpr (std::is_same_v<T, canon::Spline>) {
          spline(k, op.origin);
        } else if constexpr (std::is_same_v<T, canon::ToolChange>) {
          if (k.tool != tool_) tool_layer_ = nullptr;
          tool_ = k.tool;
        } else if constexpr (std::is_same_v<T, canon::Hole>) {
          hole(k);
        } else if constexpr (std::is_same_v<T, canon::Pocket>) {
          pocket(k);
        }
      },
      op.kind);
}

Layer* DrawingBuilder::feed_layer(canon::Origin origin) {
  if (view_ == View::Part) {
    if (origin != canon::Origin::Program) return nullptr;
    auto& runs = contour_->tool_runs;
    if (runs.empty() || runs.back().tool != tool_)
      runs.push_back({contour_->entities.size(), tool_});
    return contour_;
  }
  if (tool_layer_ == nullptr) tool_layer_ = &drawing_.layer(toolpath_layer(tool_));
  return tool_layer_;
}

void DrawingBuilder::traverse(const Vec3& to, canon::Origin origin) {
  // A cycle's rapids in the plane are its moves from hole to hole (its own
  // are along the drill's axis, which the plan view does not show): the part
  // view keeps them, as the seed's drawing does; a tool-change excursion not.
  if (view_ == View::Toolpath || origin != canon::Origin::ToolChange)
    drawing_.add_line(*rapid_, xy(pos_), xy(to));
  pos_ = to;
}

void DrawingBuilder::feed(const Vec3& to, canon::Origin origin) {
  if (Layer* layer = feed_layer(origin)) drawing_.add_line(*layer, xy(pos_), xy(to));
  pos_ = to;
}

void DrawingBuilder::arc(const canon::Arc& a, canon::Origin origin) {
  Layer* layer = feed_layer(origin);
  const Vec3 from = pos_;
  pos_ = a.to;
  if (layer == nullptr) return;
  const core::Plane plane = plane_of(a.normal);
  const double axial = a.normal[core::axes_of(plane).axial];
  const bool ccw = (a.turn > 0) == (axial > 0);
  if (plane != core::Plane::XY) {
    // An arc in a vertical plane projects to a path along a line (with a
    // helix's drift): drawn as its linearisation.
    const double sweep = core::arc_sweep(core::in_plane(from, plane), core::in_plane(a.to, plane),
                                         core::in_plane(a.center, plane), ccw, std::abs(a.turn));
    std::vector<Vec2> points{xy(from)};
    for (const Vec3& p : core::linearize_arc(from, a.to, a.center, plane, sweep, kArcTolerance))
      points.push_back(xy(p));
    drawing_.add_polyline(*layer, std::move(points));
    return;
  }
  // A helix projects to its arc; one that turns more than once, or closes
  // on itself, to the full circle.
  const Vec2 c = xy(a.center);
  const Vec2 s = xy(from) - c;
  const Vec2 e = xy(a.to) - c;
  const double radius = core::norm(s);
  if (std::abs(a.turn) > 1 || core::distance(xy(from), xy(a.to)) < kSamePoint) {
    drawing_.add_circle(*layer, {c, radius});
    return;
  }
  drawing_.add_arc(*layer, {c, radius, std::atan2(s.y, s.x), std::atan2(e.y, e.x), ccw});
}

void DrawingBuilder::spline(const canon::Spline& s, canon::Origin origin) {
  Layer* layer = feed_layer(origin);
  const Vec3 from = pos_;
  pos_ = s.to;
  if (layer == nullptr) return;
  std::vector<Vec2> points{xy(from)};
  points.reserve(s.points.size() + 1);
  for (const Vec3& p : s.points)
    points.push_back(xy(p));
  drawing_.add_polyline(*layer, std::move(points));
}

void DrawingBuilder::hole(const canon::Hole& h) {
  if (view_ != View::Part) return;
  Layer& layer = *holes_;
  const Vec2 c = xy(h.at);
  if (h.diameter > 0.0) {
    drawing_.add_circle(layer, {c, h.diameter / 2.0});
    return;
  }
  // No tool diameter known (no tool table, no D): a cross marks the centre.
  drawing_.add_line(layer, c - Vec2{kHoleMarker, 0.0}, c + Vec2{kHoleMarker, 0.0});
  drawing_.add_line(layer, c - Vec2{0.0, kHoleMarker}, c + Vec2{0.0, kHoleMarker});
}

void DrawingBuilder::pocket(const canon::Pocket& p) {
  if (view_ != View::Part) return;
  Layer& layer = *pockets_;
  Vec2 at = p.outline.start;
  for (const canon::OutlineSegment& seg : p.outline.segs) {
    if (!seg.center || seg.turn == 0) {
      drawing_.add_line(layer, at, seg.to);
    } else {
      const Vec2 c = *seg.center;
      const Vec2 s = at - c;
      const Vec2 e = seg.to - c;
      if (core::distance(at, seg.to) < kSamePoint) {
        drawing_.add_circle(layer, {c, core::norm(s)});
      } else {
        drawing_.add_arc(
            layer, {c, core::norm(s), std::atan2(s.y, s.x), std::atan2(e.y, e.x), seg.turn > 0});
      }
    }
    at = seg.to;
  }
}

}  // namespace usina::draw
