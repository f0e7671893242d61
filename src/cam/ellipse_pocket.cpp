#include "cam/ellipse_pocket.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "cam/ellipse_dda.hpp"

namespace usina::cam {

namespace {

// Whole passes of at most `step` covering `length` (equation 4, rounded up).
int passes(double length, double step) {
  return static_cast<int>(std::ceil(length / step - 1e-9));
}

// The unit inward normal of the ellipse at (a point near) p, from the
// gradient of x²/rx² + y²/ry².
Vec2 inward_normal(const Vec2& p, double rx, double ry) {
  const Vec2 g{p.x / (rx * rx), p.y / (ry * ry)};
  return g * (-1.0 / core::norm(g));
}

// The DDA point e pulled onto the ellipse along its ray from the centre. The
// interpolator drifts outward (up to about 1.8 increments: the accumulators
// truncate and the integration spirals out, see ellipse_dda_test); on the
// curve, no ring can cut into the wall or the finishing stock.
Vec2 on_ellipse(const Vec2& e, double rx, double ry) {
  return e / std::hypot(e.x / rx, e.y / ry);
}

// The DDA ellipse with its points on the curve.
std::vector<Vec2> ellipse_points(double rx, double ry, double resolution) {
  std::vector<Vec2> pts = dda_ellipse(rx, ry, resolution);
  for (Vec2& e : pts)
    e = on_ellipse(e, rx, ry);
  return pts;
}

struct Geometry {
  double a, b, r, f;
  double s_last;  // scale of the last similar ring: r + f from the wall at the minor axis
};

Geometry geometry(const EllipsePocket& p) {
  Geometry g{std::max(p.rx, p.ry), std::min(p.rx, p.ry), p.tool_diameter / 2, p.ae_finish, 0};
  // A similar ellipse s·E is nearest the wall at the minor vertex, (1 − s)·b
  // away (the support function of E is never less than b).
  g.s_last = std::max(0.0, 1.0 - (g.r + g.f) / g.b);
  return g;
}

Vec2 finish_stock_point(const Vec2& e, const EllipsePocket& p, double distance) {
  return e + inward_normal(e, p.rx, p.ry) * distance;
}

// Calls `visit(kind, points)` for each ring of one level in cutting order.
template <class Visit>
void for_each_ring(const EllipsePocket& p, const EllipsePlan& pl, Visit&& visit) {
  const Geometry g = geometry(p);
  std::vector<Vec2> pts;
  for (int k = 1; k <= pl.roughing_rings; ++k) {
    const double s = g.s_last * k / pl.roughing_rings;
    pts = ellipse_points(s * p.rx, s * p.ry, p.resolution);
    for (Vec2& q : pts)
      q = q + p.center;
    visit(RingKind::Roughing, pts);
  }
  const std::vector<Vec2> wall = ellipse_points(p.rx, p.ry, p.resolution);
  const int blends = pl.transition_rings + (p.ae_finish > 0 ? 0 : 1);
  for (int j = 1; j <= pl.transition_rings; ++j) {
    // Between the last similar ring and the offset by r + f, point by point.
    const double t = static_cast<double>(j) / blends;
    pts.clear();
    for (const Vec2& e : wall)
      pts.push_back(p.center + e * ((1 - t) * g.s_last) + finish_stock_point(e, p, g.r + g.f) * t);
    visit(RingKind::Transition, pts);
  }
  pts.clear();
  for (const Vec2& e : wall)
    pts.push_back(p.center + finish_stock_point(e, p, g.r));
  visit(RingKind::Finishing, pts);
}

}  // namespace

std::optional<std::string> check(const EllipsePocket& p) {
  const std::pair<const char*, double> positive[] = {{"rx", p.rx},
                                                     {"ry", p.ry},
                                                     {"depth", p.depth},
                                                     {"tool-diameter", p.tool_diameter},
                                                     {"ae", p.ae},
                                                     {"ap", p.ap},
                                                     {"resolution", p.resolution},
                                                     {"feed", p.feed},
                                                     {"plunge-feed", p.plunge_feed},
                                                     {"rpm", p.rpm},
                                                     {"safe-z", p.safe_z}};
  for (const auto& [name, v] : positive)
    if (!(v > 0) || !std::isfinite(v))
      return fmt::format("--{} must be a positive number, not {}", name, v);
  if (!(p.ae_finish >= 0) || !(p.ap_finish >= 0) || !std::isfinite(p.ae_finish + p.ap_finish))
    return fmt::format("--ae-finish and --ap-finish must be 0 or more");
  if (!std::isfinite(p.center.x) || !std::isfinite(p.center.y))
    return std::string("--center must be finite");
  const Geometry g = geometry(p);
  if (p.resolution >= g.b)
    return fmt::format("the resolution {} is not smaller than the radii ({} and {})", p.resolution,
                       p.rx, p.ry);
  if (p.tool_diameter >= 2 * g.b)
    return fmt::format("the tool (diameter {}) is not narrower than the minor axis ({})",
                       p.tool_diameter, 2 * g.b);
  if (p.ae > p.tool_diameter)
    return fmt::format("the stepover ae {} is bigger than the tool diameter {}", p.ae,
                       p.tool_diameter);
  if (p.ae_finish > p.tool_diameter)
    return fmt::format("ae-finish {} is bigger than the tool diameter {}", p.ae_finish,
                       p.tool_diameter);
  if (p.ap_finish >= p.depth)
    return fmt::format("ap-finish {} is not smaller than the depth {}", p.ap_finish, p.depth);
  const double curvature = g.b * g.b / g.a;
  if (g.r + g.f > curvature)
    return fmt::format(
        "the tool radius plus ae-finish ({}) is larger than the wall's smallest radius of "
        "curvature ({:.4g}, at the ends of the major axis): the tool cannot follow it",
        g.r + g.f, curvature);
  return std::nullopt;
}

EllipsePlan plan(const EllipsePocket& p) {
  const Geometry g = geometry(p);
  EllipsePlan pl;
  // Roughing: equal steps of at most ae where the rings are farthest apart,
  // along the major axis (for a circle: the seed's I = (R − d_finish)/d).
  if (g.s_last > 0) {
    pl.roughing_rings = passes(g.s_last * g.a, p.ae);
    pl.ae_used = g.s_last * g.a / pl.roughing_rings;
    pl.ae_y = g.s_last * p.ry / pl.roughing_rings;
  }
  // Transition: the last similar ring is r + f from the wall only at the
  // minor axis; rings blending it into the offset by r + f close the gap in
  // steps of at most ae, so the finishing ring removes ae_finish everywhere.
  double gap = 0;
  for (const Vec2& e : ellipse_points(p.rx, p.ry, std::max(p.resolution, g.b / 1000)))
    gap = std::max(gap, core::distance(e * g.s_last, finish_stock_point(e, p, g.r + g.f)));
  const int blends = gap > 1e-6 ? passes(gap, p.ae) : 0;
  pl.transition_rings = p.ae_finish > 0 ? blends : std::max(0, blends - 1);
  // Depth: equal roughing levels, then the finishing level (equation 4 in Z).
  const double rough = p.depth - p.ap_finish;
  const int levels = passes(rough, p.ap);
  pl.ap_used = rough / levels;
  for (int k = 1; k <= levels; ++k)
    pl.z_levels.push_back(k == levels ? -rough : -pl.ap_used * k);
  if (p.ap_finish > 0) pl.z_levels.push_back(-p.depth);
  return pl;
}

std::vector<Ring> rings(const EllipsePocket& p, const EllipsePlan& pl) {
  std::vector<Ring> out;
  for_each_ring(p, pl, [&](RingKind kind, const std::vector<Vec2>& pts) {
    out.push_back({kind, pts});
  });
  return out;
}

void generate(const EllipsePocket& p, canon::Sink& sink) {
  const EllipsePlan pl = plan(p);
  auto emit = [&](canon::OpKind k) {
    sink.on(canon::Op{std::move(k), {}, canon::Origin::Program});
  };
  const auto at = [&](const Vec2& q, double z) { return core::Vec3{q.x, q.y, z}; };
  emit(canon::Comment{fmt::format("elliptical pocket X{} Y{} RX{} RY{} depth {} tool D{}",
                                  p.center.x, p.center.y, p.rx, p.ry, p.depth, p.tool_diameter)});
  emit(canon::ToolChange{p.tool, p.tool_diameter});
  emit(canon::Spindle{p.rpm, canon::SpindleDir::Cw});
  emit(canon::Traverse{at(p.center, p.safe_z)});
  for (const double z : pl.z_levels) {
    emit(canon::Feed{at(p.center, z), p.plunge_feed});  // plunge at the centre (seed)
    for_each_ring(p, pl, [&](RingKind, const std::vector<Vec2>& pts) {
      for (const Vec2& q : pts)  // the first point is the step along +Y
        emit(canon::Feed{at(q, z), p.feed});
    });
    emit(canon::Feed{at(p.center, z), p.feed});  // across the cleared floor
  }
  emit(canon::Traverse{at(p.center, p.safe_z)});
  emit(canon::Spindle{0, canon::SpindleDir::Off});
  emit(canon::ProgramEnd{});
}

}  // namespace usina::cam
