#include "job/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cam/pocket.hpp"

namespace usina::job {
namespace {

using cam::Vec2;

bool same(Vec2 a, Vec2 b) {
  return std::hypot(a.x - b.x, a.y - b.y) < 1e-9;
}

// The unit direction of travel of segment `s` from `from`, at its start
// (`at_end` false) or its end.
Vec2 tangent(Vec2 from, const cam::PathSegment& s, bool at_end) {
  Vec2 d{s.to.x - from.x, s.to.y - from.y};
  if (s.center) {
    const Vec2 p = at_end ? s.to : from;
    const Vec2 r{p.x - s.center->x, p.y - s.center->y};
    d = s.turn > 0 ? Vec2{-r.y, r.x} : Vec2{r.y, -r.x};
  }
  const double n = std::hypot(d.x, d.y);
  return n > 0 ? Vec2{d.x / n, d.y / n} : Vec2{0, 0};
}

}  // namespace

std::vector<HoleGroup> holes_of(const std::vector<cam::Path>& paths, std::size_t& others) {
  std::vector<HoleGroup> groups;
  others = 0;
  for (const cam::Path& p : paths) {
    const bool circle = p.segs.size() == 1 && p.segs[0].center && same(p.segs[0].to, p.start);
    if (!circle) {
      ++others;
      continue;
    }
    const Vec2 c = *p.segs[0].center;
    const double d = 2 * std::hypot(p.start.x - c.x, p.start.y - c.y);
    auto g = std::find_if(groups.begin(), groups.end(),
                          [&](const HoleGroup& h) { return std::abs(h.diameter - d) < 1e-3; });
    if (g == groups.end()) {
      groups.push_back({d, {}});
      g = groups.end() - 1;
    }
    g->centers.push_back(c);
  }
  std::sort(groups.begin(), groups.end(),
            [](const HoleGroup& a, const HoleGroup& b) { return a.diameter < b.diameter; });
  return groups;
}

double smallest_inside_radius(const cam::Path& contour, bool tool_inside) {
  const double area = cam::signed_area2(cam::linearize(contour, 0.01));
  // The way the boundary turns around a corner the tool sits in.
  const int inward = (area >= 0 ? 1 : -1) * (tool_inside ? 1 : -1);
  double smallest = std::numeric_limits<double>::infinity();
  const std::size_t n = contour.segs.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 from = cam::segment_start(contour, i);
    const cam::PathSegment& s = contour.segs[i];
    if (s.center && s.turn == inward) {
      smallest = std::min(smallest, std::hypot(from.x - s.center->x, from.y - s.center->y));
    }
    // The corner at the segment's start, after the previous one (the last
    // for the first: the contour is closed).
    const std::size_t prev = i == 0 ? n - 1 : i - 1;
    const Vec2 in = tangent(cam::segment_start(contour, prev), contour.segs[prev], true);
    const Vec2 out = tangent(from, s, false);
    const double cross = in.x * out.y - in.y * out.x;
    // A kink under about 1° is a drawing's rounding, not a corner.
    if (cross * inward > 0.02) smallest = 0;  // sharp: no round tool reaches into it
  }
  return smallest;
}

double pocket_corner(const cam::PocketShape& shape) {
  double corner = smallest_inside_radius(shape.outline, true);
  for (const cam::Path& island : shape.islands)
    corner = std::min(corner, smallest_inside_radius(island, false));
  return corner;
}

double ellipse_smallest_radius(double rx, double ry) {
  const double a = std::max(rx, ry);
  const double b = std::min(rx, ry);
  return b * b / a;
}

}  // namespace usina::job
