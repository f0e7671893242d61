#include "cam/spline_approx.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/spline.hpp"

namespace usina::cam {
namespace {

using core::Vec2;

// DXF group 10/40/41 data checked against the NURBS rules: knots.size() ==
// points + degree + 1, knots non-decreasing, positive weights.
std::string spline_error(int degree, const std::vector<WeightedPoint>& control,
                         const std::vector<double>& knots) {
  if (degree < 1 || degree > 25) return fmt::format("of degree {} (1 to 25 are valid)", degree);
  const std::size_t order = static_cast<std::size_t>(degree) + 1;
  if (control.size() < order) {
    return fmt::format("of degree {} with {} control points (needs at least {})", degree,
                       control.size(), order);
  }
  if (knots.size() != control.size() + order) {
    return fmt::format("with {} knots for {} control points of degree {} (needs {})", knots.size(),
                       control.size(), degree, control.size() + order);
  }
  if (!std::is_sorted(knots.begin(), knots.end()) || knots[order - 1] >= knots[control.size()]) {
    return "with knots that do not increase";
  }
  for (const WeightedPoint& c : control) {
    if (!(c.w > 0.0) || !std::isfinite(c.w)) return fmt::format("with a weight of {}", c.w);
  }
  return {};
}

bool clamped(const core::Nurbs& c) {
  const auto order = static_cast<std::ptrdiff_t>(c.order);
  return std::all_of(c.knots.begin(), c.knots.begin() + order,
                     [&](double k) { return k == c.knots.front(); }) &&
         std::all_of(c.knots.end() - order, c.knots.end(),
                     [&](double k) { return k == c.knots.back(); });
}

// An unclamped curve does not start at its first control point, which the
// Bézier decomposition of core assumes: halve each parameter interval until
// its middle point is within the tolerance of the chord (depth-limited), from
// 16 intervals a control point so no wiggle is skipped.
struct Sampler {
  const core::Nurbs& c;
  double tol;
  std::vector<Vec2> out;

  // Points of (u0, u1], the curve from a (at u0) to b (at u1).
  void subdivide(double u0, double u1, Vec2 a, Vec2 b, int depth) {
    const double um = (u0 + u1) / 2.0;
    const Vec2 m = core::point(c, um);
    const Vec2 chord = b - a;
    const double len = core::norm(chord);
    const double off = len > 0.0 ? std::fabs(core::cross(chord, m - a)) / len : core::norm(m - a);
    if (depth < 20 && off > tol) {
      subdivide(u0, um, a, m, depth + 1);
      subdivide(um, u1, m, b, depth + 1);
      return;
    }
    out.push_back(b);
  }
};

std::vector<Vec2> sample_unclamped(const core::Nurbs& c, double tol) {
  const auto [first, last] = core::domain(c);
  const int pieces = 16 * static_cast<int>(c.points.size());
  Sampler s{c, tol, {core::point(c, first)}};
  for (int i = 0; i < pieces; ++i) {
    const double u0 = first + (last - first) * i / pieces;
    const double u1 = first + (last - first) * (i + 1) / pieces;
    s.subdivide(u0, u1, s.out.back(), core::point(c, u1), 0);
  }
  return s.out;
}

}  // namespace

std::vector<Vec2> approximate_spline(int degree, const std::vector<WeightedPoint>& control,
                                     const std::vector<double>& knots, double tolerance,
                                     std::string& error) {
  error = spline_error(degree, control, knots);
  if (!error.empty()) return {};
  core::Nurbs c;
  c.order = degree + 1;
  c.knots = knots;
  for (const WeightedPoint& p : control) {
    c.points.push_back(p.p);
    c.weights.push_back(p.w);
  }
  if (!clamped(c)) return sample_unclamped(c, tolerance);
  std::vector<Vec2> pts{c.points.front()};
  const std::vector<Vec2> rest = core::linearize(c, tolerance);
  pts.insert(pts.end(), rest.begin(), rest.end());
  return pts;
}

}  // namespace usina::cam
