#include "sim/stock/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sim/stock/holder.hpp"
#include "sim/stock/path.hpp"

namespace usina::sim::stock {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Each shape: the lowest of g(u) = k u + lift(√(e² + u²)) over u in
// [ul, uh]; g is convex (a convex tool's lower surface along a line), so its
// minimum is the stationary point clamped into the interval. And a test
// without square roots that the move cannot lower a cell at height h, d² mm²
// from the path: h is at or below the tool's lowest point over the path's
// XY, min(z) + lift(d). Most cells under a tool were cut by the moves just
// before (a raster, a ring): the test passes them over cheaply.
struct FlatLowest {
  const Path* p;
  double radius;

  double operator()(double k, double /*e2*/, double /*w*/, double ul, double uh) const {
    return k > 0.0 ? k * ul : k * uh;
  }

  // The tip's lowest over the stretch within `reach` of `along` on the path.
  double floor_near(double along, double reach) const {
    const double s = p->k > 0.0 ? std::max(0.0, along - reach) : std::min(p->length, along + reach);
    return p->z0 + p->k * s;
  }

  bool cannot_cut(double /*d2*/, double along, double h) const {
    return h <= floor_near(along, radius);
  }

  // The lowest the move comes over a tile centred `along` on the path, `d` mm
  // from it at its nearest, `half` mm its half diagonal.
  double tile_floor(double /*d*/, double along, double half) const {
    return floor_near(along, radius + half);
  }
};

struct BallLowest {
  const Path* p;
  double radius;
  double zmin;
  double flatten;  // 1 / √(1 + k²)

  double operator()(double k, double /*e2*/, double w, double ul, double uh) const {
    const double u = std::clamp(-k * w * flatten, ul, uh);
    return k * u + radius - std::sqrt(std::max(0.0, w * w - u * u));
  }

  // h <= zmin + R − √(R² − d²)  ⇔  t = zmin + R − h >= 0 and R² − d² <= t².
  bool cannot_cut(double d2, double /*along*/, double h) const {
    const double t = zmin + radius - h;
    return t >= 0.0 && radius * radius - d2 <= t * t;
  }

  double tile_floor(double d, double /*along*/, double /*half*/) const {
    return zmin + radius - std::sqrt(std::max(0.0, radius * radius - d * d));
  }
};

struct ConeLowest {
  double slope;  // c: rise per mm of radius
  double zmin;

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

  // h <= zmin + c d  ⇔  h − zmin <= 0 or (h − zmin)² <= c² d².
  bool cannot_cut(double d2, double /*along*/, double h) const {
    const double t = h - zmin;
    return t <= 0.0 || t * t <= slope * slope * d2;
  }

  double tile_floor(double d, double /*along*/, double /*half*/) const { return zmin + slope * d; }
};

// No closed form for a torus along a slope: bisection of g' (monotone, as g
// is convex) to well under a nanometre.
struct BullLowest {
  const ToolShape* tool;
  double zmin;

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

  bool cannot_cut(double d2, double /*along*/, double h) const {
    return h <= zmin + tool->lift(std::sqrt(d2));
  }

  double tile_floor(double d, double /*along*/, double /*half*/) const {
    return zmin + tool->lift(std::min(d, tool->radius()));
  }
};

// The tool's lowest over the cell centre at (qx, qy) from the path's start,
// relative to the top; +inf when the tool does not pass over it.
// `enter`: where along the path the tool first covers the cell.
template <class Lowest>
inline double lowest_at(const Path& p, double r2, double along, double e, const Lowest& lowest,
                        double& enter) {
  const double e2 = e * e;
  if (e2 > r2) return kInf;
  const double w = std::sqrt(r2 - e2);
  const double lo = std::max(0.0, along - w);
  enter = lo;
  const double hi = std::min(p.length, along + w);
  if (lo > hi) return kInf;
  return p.z0 + p.k * along + lowest(p.k, e2, w, lo - along, hi - along);
}

// What one sweep watches above the tool's end (docs/simulate.md, "Shank,
// holder, plunge"): both looked at only in the cells the move cuts (a cell
// it does not cut has its stock below the whole tool).
struct Watch {
  double flutes = 0.0;  // mm; 0: the shank is not checked
  bool plunge = false;  // a no-plunge tool going down steeper than its ramp
  double axis2 = 0.0;   // mm²: a cell this near the axis's path is under the axis

  bool any() const { return flutes > 0.0 || plunge; }
};

// What one sweep adds up.
struct Tally {
  double removed = 0.0;
  double lowest = kInf;
  float deepest = 0.0f;
  double shank = 0.0;   // mm, the most stock stood above the flutes where the tool entered it
  double plunge = 0.0;  // mm, the most stock stood above the tip under the axis
  std::array<double, kCutParts> parts{};  // removed, by part of the move (Cut::parts_mm3)
};

// The part of the move during which the tool first covers a cell: `enter`
// mm along the path (`per_mm`: parts per mm of the path).
inline std::size_t part_of(double enter, double per_mm) {
  const double f = enter * per_mm;
  return f <= 0.0 ? 0 : std::min(static_cast<std::size_t>(f), kCutParts - 1);
}

// A plunge (no XY) takes a cell's stock from `from` down to `to` while its
// tip goes down through those heights less the tool's lower surface above
// the tip there (`lift`): `lost` spread over the parts of the plunge's drop.
inline void plunge_parts(const Path& p, double lift, double from, double to, double lost,
                         std::array<double, kCutParts>& parts) {
  if (p.rises || !(p.drop > 0.0)) {
    parts[0] += lost;
    return;
  }
  const double n = static_cast<double>(kCutParts);
  const double top = p.z0 + p.drop;  // the tip where the plunge starts
  const double f0 = std::clamp((top - (from - lift)) / p.drop, 0.0, 1.0) * n;
  const double f1 = std::clamp((top - (to - lift)) / p.drop, 0.0, 1.0) * n;
  if (!(f1 - f0 > 1e-9)) {
    parts[std::min(static_cast<std::size_t>(f0), kCutParts - 1)] += lost;
    return;
  }
  for (auto k = static_cast<std::size_t>(f0); k < kCutParts && static_cast<double>(k) < f1; ++k) {
    const double lo = std::max(f0, static_cast<double>(k));
    const double hi = std::min(f1, static_cast<double>(k + 1));
    if (hi > lo) parts[k] += lost * (hi - lo) / (f1 - f0);
  }
}

// The shank (above the flutes, as wide as the tool) meets the stock of a
// column only where the tool enters it: the flutes cut the column's side
// below their top; later in the move the column is below the tool's end.
// A column the tool covers from the move's start it entered before (or it is
// the program's first place: no entry). A non-centre-cutting tool going down
// steeply: the stock under its axis stood above its tip there.
inline void watch_cell(const Path& p, double r2, double along, double e, double d2, double h,
                       const Watch& w, Tally& t) {
  if (w.flutes > 0.0) {
    const double enter = along - std::sqrt(std::max(0.0, r2 - e * e));
    if (enter > 0.0) t.shank = std::max(t.shank, h - (p.tip(enter) + w.flutes));
  }
  if (w.plunge && d2 <= w.axis2) {
    t.plunge = std::max(t.plunge, h - p.tip(std::clamp(along, 0.0, p.length)));
  }
}

// The cells [i0, i1) x [j0, j1) of one tile; true when one was lowered.
template <class Lowest>
bool sweep_cells(HeightMap& map, const Path& p, double r2, std::size_t i0, std::size_t i1,
                 std::size_t j0, std::size_t j1, std::uint8_t mark, const Lowest& lowest,
                 const Watch& watch, Tally& t) {
  const float floor = static_cast<float>(-map.box().height);
  const double dalong = map.dx() * p.ux, de = map.dx() * p.uy;
  const double per_mm = p.length > 0.0 ? static_cast<double>(kCutParts) / p.length : 0.0;
  bool lowered = false;
  for (std::size_t j = j0; j < j1; ++j) {
    float* h = map.row(j);
    std::uint8_t* m = map.mark_row(j);
    const double qx = map.x(i0) - p.ax, qy = map.y(j) - p.ay;
    double along = qx * p.ux + qy * p.uy;
    double e = qx * p.uy - qy * p.ux;
    for (std::size_t i = i0; i < i1; ++i, along += dalong, e += de) {
      const double d2 = distance2(p, along, e);
      if (d2 > r2) continue;
      const auto hi = static_cast<double>(h[i]);
      if (lowest.cannot_cut(d2, along, hi)) continue;
      double enter = 0.0;
      const double z = lowest_at(p, r2, along, e, lowest, enter);
      if (!(z < hi)) continue;
      if (watch.any()) watch_cell(p, r2, along, e, d2, hi, watch, t);
      t.lowest = std::min(t.lowest, z);
      const float now = std::max(static_cast<float>(z), floor);
      if (now >= h[i]) continue;
      const float lost = h[i] - now;
      t.removed += static_cast<double>(lost);
      if (per_mm > 0.0) {
        t.parts[part_of(enter, per_mm)] += static_cast<double>(lost);
      } else {
        plunge_parts(p, z - p.z0, hi, static_cast<double>(now), static_cast<double>(lost), t.parts);
      }
      t.deepest = std::max(t.deepest, lost);
      h[i] = now;
      m[i] = mark;
      lowered = true;
    }
  }
  return lowered;
}

// Tile by tile over the path's bounding box grown by the radius: a tile the
// tool cannot reach, or whose highest cell is at or below the move's lowest
// point over it, is passed over whole.
template <class Lowest>
Cut sweep_with(HeightMap& map, double radius, const Path& p, std::uint8_t mark,
               const Lowest& lowest, const Watch& watch) {
  const double bx = p.ax + p.ux * p.length, by = p.ay + p.uy * p.length;
  std::size_t i0 = 0, i1 = 0, j0 = 0, j1 = 0;
  map.columns(std::min(p.ax, bx) - radius, std::max(p.ax, bx) + radius, i0, i1);
  map.rows(std::min(p.ay, by) - radius, std::max(p.ay, by) + radius, j0, j1);
  const std::size_t T = HeightMap::kTile;
  const double half = 0.5 * std::hypot(map.dx(), map.dy()) * static_cast<double>(T);
  const double r2 = radius * radius;
  Tally t;
  for (std::size_t tj = j0 / T; tj * T < j1; ++tj) {
    const std::size_t cj0 = std::max(j0, tj * T), cj1 = std::min(j1, (tj + 1) * T);
    for (std::size_t ti = i0 / T; ti * T < i1; ++ti) {
      const std::size_t ci0 = std::max(i0, ti * T), ci1 = std::min(i1, (ti + 1) * T);
      const double qx = map.x(ti * T) + 0.5 * (static_cast<double>(T) - 1.0) * map.dx() - p.ax;
      const double qy = map.y(tj * T) + 0.5 * (static_cast<double>(T) - 1.0) * map.dy() - p.ay;
      const double along = qx * p.ux + qy * p.uy;
      const double d = std::sqrt(distance2(p, along, qx * p.uy - qy * p.ux)) - half;
      if (d > radius) continue;
      if (static_cast<double>(map.tile_max(ti, tj)) <=
          lowest.tile_floor(std::max(0.0, d), along, half)) {
        continue;
      }
      if (sweep_cells(map, p, r2, ci0, ci1, cj0, cj1, mark, lowest, watch, t)) {
        map.touch(ti, tj);
      }
    }
  }
  Cut cut;
  cut.removed_mm3 = t.removed * map.cell_area();
  for (std::size_t k = 0; k < kCutParts; ++k)
    cut.parts_mm3[k] = t.parts[k] * map.cell_area();
  cut.deepest = static_cast<double>(t.deepest);
  cut.lowest = t.lowest + map.top();
  cut.shank_rub = t.shank > kShankContact ? t.shank : 0.0;
  cut.plunge_into = t.plunge > kPlungeStock ? t.plunge : 0.0;
  return cut;
}

// What the move is watched for: the shank when the flutes are given; the
// plunge when the tool does not cut at its centre and goes down steeper than
// its ramp (straight down is 90°).
Watch watch_of(const ToolShape& tool, const core::Vec3& a, const core::Vec3& b,
               const HeightMap& map) {
  Watch w;
  w.flutes = tool.flutes;
  if (tool.plunge_ramp > 0.0 && b.z < a.z) {
    const double angle = std::atan2(a.z - b.z, std::hypot(b.x - a.x, b.y - a.y));
    w.plunge = angle > tool.plunge_ramp * std::numbers::pi / 180.0;
    // Half a cell's diagonal: any place has a cell centre this near.
    w.axis2 = 0.25 * (map.dx() * map.dx() + map.dy() * map.dy());
  }
  return w;
}

// Calls f with the shape's Lowest for the path.
template <class F>
auto with_lowest(const ToolShape& tool, const Path& p, F&& f) {
  const double zmin = p.z0 + std::min(0.0, p.k * p.length);
  const double r = tool.radius();
  switch (tool.kind) {
  case ToolKind::Flat: return f(FlatLowest{&p, r});
  case ToolKind::Ball: return f(BallLowest{&p, r, zmin, 1.0 / std::sqrt(1.0 + p.k * p.k)});
  case ToolKind::BullNose: return f(BullLowest{&tool, zmin});
  case ToolKind::Drill:
  case ToolKind::Vee: break;
  }
  return f(ConeLowest{tool.cone_slope(), zmin});
}

}  // namespace

void Cut::add(const Cut& c) {
  removed_mm3 += c.removed_mm3;
  for (std::size_t k = 0; k < kCutParts; ++k)
    parts_mm3[k] += c.parts_mm3[k];
  deepest = std::max(deepest, c.deepest);
  lowest = std::min(lowest, c.lowest);
  shank_rub = std::max(shank_rub, c.shank_rub);
  holder_hit = std::max(holder_hit, c.holder_hit);
  plunge_into = std::max(plunge_into, c.plunge_into);
}

Cut sweep(HeightMap& map, const ToolShape& tool, const core::Vec3& a, const core::Vec3& b,
          std::uint8_t mark) {
  // Nothing below the top: no cell can be reached (every cell is at or below it).
  if (std::min(a.z, b.z) >= map.top()) return {};
  const Path p = path_of(a, b, map.top());
  const Watch watch = watch_of(tool, a, b, map);
  const bool holder = tool.holder > 0.0;
  const double before =
      holder ? holder_depth(map, p, tool, HolderStretch::BeforeTheTool, 0.0) : 0.0;
  Cut cut = with_lowest(tool, p, [&](const auto& lowest) {
    return sweep_with(map, tool.radius(), p, mark, lowest, watch);
  });
  if (holder) {
    cut.holder_hit = holder_depth(map, p, tool, HolderStretch::AfterTheTool, before);
  }
  return cut;
}

double envelope(const ToolShape& tool, const core::Vec3& a, const core::Vec3& b, double cx,
                double cy) {
  const Path p = path_of(a, b, 0.0);
  const double r2 = tool.radius() * tool.radius();
  const double qx = cx - p.ax, qy = cy - p.ay;
  const double along = qx * p.ux + qy * p.uy;
  const double e = qx * p.uy - qy * p.ux;
  return with_lowest(tool, p, [&](const auto& lowest) {
    double enter = 0.0;
    return lowest_at(p, r2, along, e, lowest, enter);
  });
}

}  // namespace usina::sim::stock
