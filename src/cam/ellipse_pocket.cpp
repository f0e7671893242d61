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
  Geometry g{std::max(p.rx, p.ry), std::min(p.rx, p.ry), p.cut.tool_diameter / 2, p.ae_finish, 0};
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

namespace {

inline constexpr Range kResolution{0.0001, kMaxCoordinate, true, "mm"};

bool check_ranges(const EllipsePocket& p, core::DiagnosticSink& diags) {
  bool ok = check_cutting(p.cut, diags);
  ok = check_point("the centre (--center)", p.center, diags) && ok;
  ok = check_range("the radius along X (--rx)", p.rx, kLength, diags) && ok;
  ok = check_range("the radius along Y (--ry)", p.ry, kLength, diags) && ok;
  ok = check_range("the depth (--depth)", p.depth, kLength, diags) && ok;
  ok = check_range("the stepover (--stepover)", p.ae, kLength, diags) && ok;
  ok = check_range("the step down (--step-down)", p.ap, kLength, diags) && ok;
  ok =
      check_range("the finish allowance (--finish-allowance)", p.ae_finish, kLengthOrZero, diags) &&
      ok;
  ok = check_range("the floor allowance (--floor-allowance)", p.ap_finish, kLengthOrZero, diags) &&
       ok;
  ok = check_range("the resolution (--resolution)", p.resolution, kResolution, diags) && ok;
  return ok;
}

// The first thing that makes the pocket impossible, as one error.
bool check_geometry(const EllipsePocket& p, core::DiagnosticSink& diags) {
  const Geometry g = geometry(p);
  const double d = p.cut.tool_diameter;
  if (p.resolution >= g.b) {
    return fail(diags, core::Code::GenBadValue,
                fmt::format("the resolution {:g} mm is not smaller than the radii ({:g} and {:g} "
                            "mm); give a smaller --resolution",
                            p.resolution, p.rx, p.ry));
  }
  if (d >= 2 * g.b) {
    return fail(diags, core::Code::GenToolTooBig,
                fmt::format("the tool (diameter {:g} mm) is not narrower than the minor axis "
                            "({:g} mm); use a smaller tool",
                            d, 2 * g.b));
  }
  if (p.ae > d) {
    return fail(diags, core::Code::GenBadValue,
                fmt::format("the stepover {:g} mm is bigger than the tool diameter {:g} mm, "
                            "which would leave ridges between the rings; give at most {:g}",
                            p.ae, d, d));
  }
  if (p.ae_finish > d) {
    return fail(diags, core::Code::GenBadValue,
                fmt::format("the finish allowance {:g} mm is bigger than the tool diameter "
                            "{:g} mm; the finishing ring could not remove it",
                            p.ae_finish, d));
  }
  if (p.ap_finish >= p.depth) {
    return fail(diags, core::Code::GenBadValue,
                fmt::format("the floor allowance {:g} mm is not smaller than the depth {:g} mm",
                            p.ap_finish, p.depth));
  }
  const double curvature = g.b * g.b / g.a;
  if (g.r + g.f > curvature) {
    return fail(diags, core::Code::GenToolTooBig,
                fmt::format("the tool radius plus the finish allowance ({:g} mm) is larger than "
                            "the wall's smallest radius of curvature ({:.4g} mm, at the ends of "
                            "the major axis): the tool cannot follow it; use a smaller tool",
                            g.r + g.f, curvature));
  }
  return true;
}

// The rings one level has: at most kMaxPasses similar ones (the transition
// rings are fewer than the similar ones would be in the same gap).
bool check_counts(const EllipsePocket& p, core::DiagnosticSink& diags) {
  if (!check_passes(p.depth - p.ap_finish, p.ap, diags)) return false;
  const Geometry g = geometry(p);
  if (g.s_last * g.a / p.ae <= kMaxPasses) return true;
  return fail(diags, core::Code::GenBadValue,
              fmt::format("a stepover of {:g} mm makes more than {} rings in a pocket {:g} mm "
                          "long; give a larger stepover",
                          p.ae, kMaxPasses, 2 * g.a));
}

// Points of the DDA ellipse of radii s·rx, s·ry, from above: each quadrant
// has n increments along each axis (dda_increment), and each clock that
// steps one axis or both is a point, so at most 2n + 1 a quadrant.
double ring_points(const EllipsePocket& p, double s) {
  const double n = std::max(1.0, std::ceil(s * std::max(p.rx, p.ry) / p.resolution));
  return 4 * (2 * n + 1);
}

}  // namespace

bool check(const EllipsePocket& p, core::DiagnosticSink& diags) {
  if (!check_ranges(p, diags) || !check_geometry(p, diags) || !check_counts(p, diags)) {
    return false;
  }
  return check_work("the elliptical pocket", estimate_moves(p), p.cut.max_moves,
                    "give a coarser --resolution, a larger --stepover or --step-down", diags);
}

double estimate_moves(const EllipsePocket& p) {
  const Geometry g = geometry(p);
  const EllipsePlan pl = plan(p);
  double level = 2;  // the plunge and the move back to the centre
  for (int k = 1; k <= pl.roughing_rings; ++k)
    level += ring_points(p, g.s_last * k / pl.roughing_rings);
  level += (pl.transition_rings + 1) * ring_points(p, 1.0);
  return static_cast<double>(pl.z_levels.size()) * level + 7;
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
  // Sampled at no more than about 6000 points, whatever the resolution.
  for (const Vec2& e : ellipse_points(p.rx, p.ry, std::max(p.resolution, g.a / 1000)))
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
  const Cutting& c = p.cut;
  emit(canon::Comment{fmt::format("elliptical pocket X{} Y{} RX{} RY{} depth {} tool D{}",
                                  p.center.x, p.center.y, p.rx, p.ry, p.depth, c.tool_diameter)});
  emit(canon::ToolChange{c.tool, c.tool_diameter});
  emit(canon::Spindle{c.rpm, canon::SpindleDir::Cw});
  emit(canon::Traverse{at(p.center, c.safe_z)});
  for (const double z : pl.z_levels) {
    emit(canon::Feed{at(p.center, z), c.plunge_feed});  // plunge at the centre (seed)
    for_each_ring(p, pl, [&](RingKind, const std::vector<Vec2>& pts) {
      for (const Vec2& q : pts)  // the first point is the step along +Y
        emit(canon::Feed{at(q, z), c.feed});
    });
    emit(canon::Feed{at(p.center, z), c.feed});  // across the cleared floor
  }
  emit(canon::Traverse{at(p.center, c.safe_z)});
  emit(canon::Spindle{0, canon::SpindleDir::Off});
  emit(canon::ProgramEnd{});
}

bool generate_ellipse_pocket(const EllipsePocket& p, canon::Sink& sink,
                             core::DiagnosticSink& diags) {
  if (!check(p, diags)) return false;
  generate(p, sink);
  return true;
}

}  // namespace usina::cam
