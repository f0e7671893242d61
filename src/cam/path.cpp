#include "cam/path.hpp"

#include <cmath>
#include <numbers>

#include "core/arc.hpp"

namespace usina::cam {

Vec2 end_point(const Path& p) {
  return p.segs.empty() ? p.start : p.segs.back().to;
}

Vec2 segment_start(const Path& p, std::size_t i) {
  return i == 0 ? p.start : p.segs[i - 1].to;
}

Path reversed(const Path& p) {
  Path r;
  r.closed = p.closed;
  r.start = end_point(p);
  for (std::size_t i = p.segs.size(); i-- > 0;) {
    const PathSegment& s = p.segs[i];
    r.segs.push_back({segment_start(p, i), s.center, -s.turn});
  }
  return r;
}

double segment_sweep(Vec2 from, const PathSegment& s) {
  if (!s.center) return 0.0;
  return core::arc_sweep(from, s.to, *s.center, s.turn > 0);
}

double segment_length(Vec2 from, const PathSegment& s) {
  if (!s.center) return core::distance(from, s.to);
  return std::fabs(segment_sweep(from, s)) * core::distance(from, *s.center);
}

double path_length(const Path& p) {
  double total = 0.0;
  for (std::size_t i = 0; i < p.segs.size(); ++i) {
    total += segment_length(segment_start(p, i), p.segs[i]);
  }
  return total;
}

std::vector<Vec2> linearize(const Path& p, double tolerance) {
  std::vector<Vec2> pts{p.start};
  for (std::size_t i = 0; i < p.segs.size(); ++i) {
    const PathSegment& s = p.segs[i];
    const Vec2 from = segment_start(p, i);
    if (!s.center) {
      pts.push_back(s.to);
      continue;
    }
    const double sweep = segment_sweep(from, s);
    const double radius = core::distance(from, *s.center);
    const int n = core::segments_for_tolerance(radius, std::fabs(sweep), tolerance);
    for (int k = 1; k < n; ++k) {
      pts.push_back(*s.center + core::rotate(from - *s.center, sweep * k / n));
    }
    pts.push_back(s.to);
  }
  return pts;
}

double linearized_points(const Path& p, double tolerance) {
  double n = 1.0;
  for (std::size_t i = 0; i < p.segs.size(); ++i) {
    const PathSegment& s = p.segs[i];
    if (!s.center) {
      n += 1.0;
      continue;
    }
    const Vec2 from = segment_start(p, i);
    n += core::segments_for_tolerance(core::distance(from, *s.center),
                                      std::fabs(segment_sweep(from, s)), tolerance);
  }
  return n;
}

PathSegment bulge_segment(Vec2 from, Vec2 to, double bulge) {
  const double chord = core::distance(from, to);
  if (bulge == 0.0 || chord == 0.0) return {to, std::nullopt, 0};
  // Included angle θ = 4 atan(bulge); the centre lies on the chord's
  // bisector at (chord/2) / tan(θ/2) from its midpoint, on the left of the
  // chord for a counter-clockwise (positive) bulge.
  const double theta = 4.0 * std::atan(bulge);
  const Vec2 mid = (from + to) * 0.5;
  const Vec2 left = core::perp(to - from) / chord;
  const double h = (chord / 2.0) / std::tan(theta / 2.0);
  return {to, mid + left * h, bulge > 0 ? 1 : -1};
}

double signed_area2(const std::vector<Vec2>& ring) {
  double a = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    a += core::cross(ring[i], ring[(i + 1) % ring.size()]);
  }
  return a;
}

canon::Outline to_outline(const Path& p) {
  canon::Outline o;
  o.start = p.start;
  for (const PathSegment& s : p.segs)
    o.segs.push_back({s.to, s.center, s.turn});
  return o;
}

}  // namespace usina::cam
