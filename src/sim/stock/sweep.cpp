#include "sim/stock/sweep.hpp"

#include <algorithm>
#include <cmath>

namespace usina::sim::stock {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The move in the frame of its XY projection: a cell at `along` mm from the
// start along the path and `e` mm beside it is under the tool's axis at
// s = along + u when u² + e² <= R²; the tip is then at z0 + k s.
struct Path {
  double ax = 0.0, ay = 0.0, z0 = 0.0;
  double ux = 1.0, uy = 0.0;  // unit XY direction (any, for a plunge)
  double length = 0.0;        // mm of XY
  double k = 0.0;             // dz per mm of XY (0 for a plunge, z0 the lower end)
};

Path path_of(const core::Vec3& a, const core::Vec3& b, double top) {
  Path p;
  p.ax = a.x;
  p.ay = a.y;
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  p.length = std::hypot(dx, dy);
  // Below a nanometre of XY a move is a plunge: its tool stands at one place.
  if (p.length < 1e-9) {
    p.length = 0.0;
    p.z0 = std::min(a.z, b.z) - top;
    return p;
  }
  p.ux = dx / p.length;
  p.uy = dy / p.length;
  p.z0 = a.z - top;
  p.k = (b.z - a.z) / p.length;
  return p;
}

// The lowest of g(u) = k u + lift(√(e² + u²)) over u in [ul, uh], for each
// shape; g is convex (a convex tool's lower surface along a line), so its
// minimum is at the stationary point clamped into the interval.
struct FlatLowest {
  double operator()(double k, double /*e2*/, double /*w*/, double ul, double uh) const {
    return k > 0.0 ? k * ul : k * uh;
  }
};

struct BallLowest {
  double radius = 0.0;

  double operator()(double k, double /*e2*/, double w, double ul, double uh) const {
    const double u = std::clamp(-k * w / std::sqrt(1.0 + k * k), ul, uh);
    return k * u + radius - std::sqrt(std::max(0.0, w * w - u * u));
  }
};

struct ConeLowest {
  double slope = 0.0;  // c: rise per mm of radius

  double operator()(double k, double e2, double /*w*/, double ul, double uh) const {
    double u = 0.0;
    if (std::abs(k) < slope) {
      u = -k * std::sqrt(e2) / std::sqrt(slope * slope - k * k);
    } else {
      u = k > 0.0 ? -kInf : kInf;
    }
    u = std::clamp(u, ul, uh);
    return k * u + slope * std::sqrt(e2 + u * u);
  }
};

// No closed form for a torus along a slope: bisection of g' (monotone, as g
// is convex) to well under a nanometre.
struct BullLowest {
  const ToolShape* tool = nullptr;

  double slope_at(double k, double e2, double u) const {
    const double r = std::sqrt(e2 + u * u);
    const double flat = tool->radius() - tool->corner_radius;
    if (r <= flat || r == 0.0) return k;
    const double d = r - flat;
    const double rc = tool->corner_radius;
    const double rise = d / std::sqrt(std::max(1e-300, rc * rc - d * d));
    return k + rise * u / r;
  }

  double operator()(double k, double e2, double /*w*/, double ul, double uh) const {
    double u = ul;
    if (slope_at(k, e2, ul) < 0.0) {
      if (slope_at(k, e2, uh) <= 0.0) {
        u = uh;
      } else {
        double lo = ul, hi = uh;
        for (int i = 0; i < 64 && hi - lo > 1e-10; ++i) {
          const double mid = 0.5 * (lo + hi);
          (slope_at(k, e2, mid) < 0.0 ? lo : hi) = mid;
        }
        u = 0.5 * (lo + hi);
      }
    }
    return k * u + tool->lift(std::sqrt(e2 + u * u));
  }
};

// The tool's lowest over the cell centre at (qx, qy) from the path's start,
// relative to the top; +inf when the tool does not pass over it.
template <class Lowest>
inline double lowest_at(const Path& p, double r2, double qx, double qy, const Lowest& lowest) {
  const double along = qx * p.ux + qy * p.uy;
  const double e = qx * p.uy - qy * p.ux;
  const double e2 = e * e;
  if (e2 > r2) return kInf;
  const double w = std::sqrt(r2 - e2);
  const double lo = std::max(0.0, along - w);
  const double hi = std::min(p.length, along + w);
  if (lo > hi) return kInf;
  return p.z0 + p.k * along + lowest(p.k, e2, w, lo - along, hi - along);
}

template <class Lowest>
Cut sweep_with(HeightMap& map, double radius, const Path& p, double xlo, double xhi, double ylo,
               double yhi, std::uint8_t mark, const Lowest& lowest) {
  Cut cut;
  std::size_t i0 = 0, i1 = 0, j0 = 0, j1 = 0;
  map.columns(xlo - radius, xhi + radius, i0, i1);
  map.rows(ylo - radius, yhi + radius, j0, j1);
  const double r2 = radius * radius;
  const float floor = static_cast<float>(-map.box().height);
  const auto zmin = static_cast<float>(p.z0 + std::min(0.0, p.k * p.length));
  double removed = 0.0;
  double lowest_z = kInf;
  float deepest = 0.0f;
  for (std::size_t j = j0; j < j1; ++j) {
    float* h = map.row(j);
    std::uint8_t* m = map.mark_row(j);
    const double qy = map.y(j) - p.ay;
    for (std::size_t i = i0; i < i1; ++i) {
      if (h[i] <= zmin) continue;  // already as low as this move can go
      const double z = lowest_at(p, r2, map.x(i) - p.ax, qy, lowest);
      if (!(z < static_cast<double>(h[i]))) continue;
      lowest_z = std::min(lowest_z, z);
      const float now = std::max(static_cast<float>(z), floor);
      if (now >= h[i]) continue;
      const float lost = h[i] - now;
      removed += static_cast<double>(lost);
      deepest = std::max(deepest, lost);
      h[i] = now;
      m[i] = mark;
    }
  }
  cut.removed_mm3 = removed * map.cell_area();
  cut.deepest = static_cast<double>(deepest);
  cut.lowest = lowest_z + map.top();
  return cut;
}

}  // namespace

void Cut::add(const Cut& c) {
  removed_mm3 += c.removed_mm3;
  deepest = std::max(deepest, c.deepest);
  lowest = std::min(lowest, c.lowest);
}

Cut sweep(HeightMap& map, const ToolShape& tool, const core::Vec3& a, const core::Vec3& b,
          std::uint8_t mark) {
  // Nothing below the top: no cell can be reached (every cell is at or below it).
  if (std::min(a.z, b.z) >= map.top()) return {};
  const Path p = path_of(a, b, map.top());
  const double xlo = std::min(a.x, b.x), xhi = std::max(a.x, b.x);
  const double ylo = std::min(a.y, b.y), yhi = std::max(a.y, b.y);
  const double r = tool.radius();
  switch (tool.kind) {
  case ToolKind::Flat: return sweep_with(map, r, p, xlo, xhi, ylo, yhi, mark, FlatLowest{});
  case ToolKind::Ball: return sweep_with(map, r, p, xlo, xhi, ylo, yhi, mark, BallLowest{r});
  case ToolKind::BullNose:
    return sweep_with(map, r, p, xlo, xhi, ylo, yhi, mark, BullLowest{&tool});
  case ToolKind::Drill:
  case ToolKind::Vee:
    return sweep_with(map, r, p, xlo, xhi, ylo, yhi, mark, ConeLowest{tool.cone_slope()});
  }
  return {};
}

double envelope(const ToolShape& tool, const core::Vec3& a, const core::Vec3& b, double cx,
                double cy) {
  const Path p = path_of(a, b, 0.0);
  const double r2 = tool.radius() * tool.radius();
  const double qx = cx - p.ax, qy = cy - p.ay;
  switch (tool.kind) {
  case ToolKind::Flat: return lowest_at(p, r2, qx, qy, FlatLowest{});
  case ToolKind::Ball: return lowest_at(p, r2, qx, qy, BallLowest{tool.radius()});
  case ToolKind::BullNose: return lowest_at(p, r2, qx, qy, BullLowest{&tool});
  case ToolKind::Drill:
  case ToolKind::Vee: return lowest_at(p, r2, qx, qy, ConeLowest{tool.cone_slope()});
  }
  return kInf;
}

}  // namespace usina::sim::stock
