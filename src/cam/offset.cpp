#include "cam/offset.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

#include <polyclipping/clipper.hpp>

namespace usina::cam {
namespace {

namespace cl = ClipperLib;

cl::IntPoint to_int(Vec2 p) {
  return {static_cast<cl::cInt>(std::llround(p.x * kClipperScale)),
          static_cast<cl::cInt>(std::llround(p.y * kClipperScale))};
}

Vec2 to_mm(const cl::IntPoint& p) {
  return {static_cast<double>(p.X) / kClipperScale, static_cast<double>(p.Y) / kClipperScale};
}

cl::Path to_clipper(const std::vector<Vec2>& pts) {
  cl::Path out;
  out.reserve(pts.size());
  for (const Vec2& p : pts)
    out.push_back(to_int(p));
  return out;
}

Ring to_mm(const cl::Path& p) {
  Ring out;
  out.reserve(p.size());
  for (const cl::IntPoint& q : p)
    out.push_back(to_mm(q));
  return out;
}

cl::ClipperOffset make_offset(double tolerance) {
  cl::ClipperOffset o;
  o.ArcTolerance = std::max(tolerance * kClipperScale, 1.0);
  return o;
}

// The point of segment a-b nearest p.
Vec2 nearest_on(Vec2 a, Vec2 b, Vec2 p) {
  const Vec2 d = b - a;
  const double len2 = core::dot(d, d);
  const double t = len2 > 0.0 ? std::clamp(core::dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
  return a + d * t;
}

// Which side of the polyline `pts` a point of its offset band is on: +1
// left, −1 right, judged at the polyline's point nearest it. The band's points
// are at most `reach` from the polyline, so only the segments in the grid
// cells within `reach` are looked at: linear, not quadratic, in the points.
class SideFinder {
 public:
  SideFinder(const std::vector<Vec2>& pts, double reach)
      : pts_(pts), cell_(std::max(reach, 1e-6)), reach_(reach) {
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
      const auto [x0, y0] =
          cell_of({std::min(pts[i].x, pts[i + 1].x), std::min(pts[i].y, pts[i + 1].y)});
      const auto [x1, y1] =
          cell_of({std::max(pts[i].x, pts[i + 1].x), std::max(pts[i].y, pts[i + 1].y)});
      for (std::int64_t x = x0; x <= x1; ++x) {
        for (std::int64_t y = y0; y <= y1; ++y)
          cells_[key(x, y)].push_back(i);
      }
    }
  }

  int side(Vec2 p) const {
    double best = std::numeric_limits<double>::infinity();
    int side = 0;
    const auto [x0, y0] = cell_of(p - Vec2{reach_, reach_});
    const auto [x1, y1] = cell_of(p + Vec2{reach_, reach_});
    for (std::int64_t x = x0; x <= x1; ++x) {
      for (std::int64_t y = y0; y <= y1; ++y) {
        const auto it = cells_.find(key(x, y));
        if (it == cells_.end()) continue;
        for (const std::size_t i : it->second) {
          const Vec2 q = nearest_on(pts_[i], pts_[i + 1], p);
          const double d = core::distance(p, q);
          if (d < best) {
            best = d;
            side = core::cross(pts_[i + 1] - pts_[i], p - q) >= 0.0 ? 1 : -1;
          }
        }
      }
    }
    return side;
  }

 private:
  std::pair<std::int64_t, std::int64_t> cell_of(Vec2 p) const {
    return {static_cast<std::int64_t>(std::floor(p.x / cell_)),
            static_cast<std::int64_t>(std::floor(p.y / cell_))};
  }

  static std::uint64_t key(std::int64_t x, std::int64_t y) {
    return static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ULL ^ static_cast<std::uint64_t>(y);
  }

  const std::vector<Vec2>& pts_;
  double cell_;
  double reach_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
};

// The longest cyclic run of ring points on the wanted side.
std::vector<Vec2> longest_run(const Ring& ring, const std::vector<bool>& wanted) {
  const std::size_t n = ring.size();
  std::size_t best_start = 0;
  std::size_t best_len = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!wanted[i] || wanted[(i + n - 1) % n]) continue;  // runs start after an unwanted point
    std::size_t len = 0;
    while (len < n && wanted[(i + len) % n])
      ++len;
    if (len > best_len) best_start = i, best_len = len;
  }
  if (best_len == 0 && !wanted.empty() && wanted[0]) best_len = n;  // every point wanted
  std::vector<Vec2> run;
  for (std::size_t k = 0; k < best_len; ++k)
    run.push_back(ring[(best_start + k) % n]);
  return run;
}

}  // namespace

std::vector<Ring> offset_rings(const std::vector<Ring>& rings, double delta, double tolerance) {
  cl::ClipperOffset o = make_offset(tolerance);
  for (const Ring& r : rings)
    o.AddPath(to_clipper(r), cl::jtRound, cl::etClosedPolygon);
  cl::Paths solution;
  o.Execute(solution, delta * kClipperScale);
  std::vector<Ring> out;
  for (const cl::Path& p : solution) {
    if (p.size() >= 3) out.push_back(to_mm(p));
  }
  return out;
}

std::vector<Ring> difference(const std::vector<Ring>& subject, const std::vector<Ring>& clip) {
  cl::Clipper c;
  for (const Ring& r : subject)
    c.AddPath(to_clipper(r), cl::ptSubject, true);
  for (const Ring& r : clip)
    c.AddPath(to_clipper(r), cl::ptClip, true);
  cl::Paths solution;
  c.Execute(cl::ctDifference, solution, cl::pftEvenOdd, cl::pftEvenOdd);
  std::vector<Ring> out;
  for (const cl::Path& p : solution) {
    if (p.size() >= 3) out.push_back(to_mm(p));
  }
  return out;
}

Ring to_ring(const Path& p, double tolerance, bool ccw) {
  Ring r = linearize(p, tolerance);
  if (r.size() > 1 && core::distance(r.front(), r.back()) < 1.0 / kClipperScale) r.pop_back();
  if ((signed_area2(r) > 0.0) != ccw) std::reverse(r.begin(), r.end());
  return r;
}

Path ring_to_path(const Ring& ring, Vec2 near) {
  // Starts at the ring's point nearest `near`, which may be inside an edge:
  // that edge is split there (unless the point is one of its ends).
  std::size_t edge = 0;
  Vec2 at = ring.front();
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 q = nearest_on(ring[i], ring[(i + 1) % ring.size()], near);
    if (core::distance(q, near) < core::distance(at, near)) edge = i, at = q;
  }
  const std::size_t n = ring.size();
  Path path{at, {}, true};
  for (std::size_t k = 1; k <= n; ++k) {
    const Vec2 v = ring[(edge + k) % n];
    if (!(v == end_point(path))) path.segs.push_back({v, std::nullopt, 0});
  }
  if (!(at == end_point(path))) path.segs.push_back({at, std::nullopt, 0});
  return path;
}

std::vector<Path> offset_closed(const Path& p, double radius, bool left, double tolerance) {
  const Ring ring = linearize(p, tolerance);
  const bool ccw = signed_area2(ring) > 0.0;
  // The left of a counter-clockwise contour is its inside.
  const double delta = (left == ccw) ? -radius : radius;
  std::vector<Path> out;
  for (const Ring& r : offset_rings({to_ring(p, tolerance, true)}, delta, tolerance)) {
    Ring oriented = r;
    if ((signed_area2(oriented) > 0.0) != ccw) std::reverse(oriented.begin(), oriented.end());
    out.push_back(ring_to_path(oriented, p.start));
  }
  return out;
}

std::optional<Path> offset_open(const Path& p, double radius, bool left, double tolerance) {
  // Clipper offsets an open path on both sides at once (a closed band with
  // butt ends); the wanted side is the band's points on that side of the path.
  const std::vector<Vec2> pts = linearize(p, tolerance);
  cl::ClipperOffset o = make_offset(tolerance);
  o.AddPath(to_clipper(pts), cl::jtRound, cl::etOpenButt);
  cl::Paths solution;
  o.Execute(solution, radius * kClipperScale);
  const cl::Path* outer = nullptr;
  for (const cl::Path& s : solution) {
    if (outer == nullptr || std::fabs(cl::Area(s)) > std::fabs(cl::Area(*outer))) outer = &s;
  }
  if (outer == nullptr) return std::nullopt;
  const Ring band = to_mm(*outer);
  // Clipper's integer rounding may put a band point a little beyond the radius.
  const SideFinder sides(pts, radius + tolerance + 2.0 / kClipperScale);
  std::vector<bool> wanted;
  for (const Vec2& q : band)
    wanted.push_back(sides.side(q) == (left ? 1 : -1));
  std::vector<Vec2> run = longest_run(band, wanted);
  if (run.size() < 2) return std::nullopt;
  if (core::distance(run.front(), pts.front()) > core::distance(run.back(), pts.front())) {
    std::reverse(run.begin(), run.end());
  }
  Path out{run.front(), {}, false};
  for (std::size_t i = 1; i < run.size(); ++i)
    out.segs.push_back({run[i], std::nullopt, 0});
  return out;
}

bool inside(const Ring& ring, Vec2 p) {
  bool in = false;
  if (ring.empty()) return false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Vec2 a = ring[i];
    const Vec2 b = ring[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) {
      in = !in;
    }
  }
  return in;
}

}  // namespace usina::cam
