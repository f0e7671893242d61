#include "core/spline.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace usina::core {

namespace {

// Control points in homogeneous form (w·x, w·y, w), so Béziers, rational
// Béziers and NURBS share one subdivision and one de Boor.
using Homogeneous = std::vector<Vec3>;

Vec3 lift(Vec2 p, double w) {
  return {p.x * w, p.y * w, w};
}

Vec2 project(const Vec3& h) {
  return {h.x / h.z, h.y / h.z};
}

double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  if (len2 == 0.0) return distance(p, a);
  const double t = std::clamp(dot(p - a, ab) / len2, 0.0, 1.0);
  return distance(p, a + ab * t);
}

// Largest distance of the inner control points from the chord. With positive
// weights the piece lies in the hull of its control points, and the tolerance
// band around a segment is convex, so this bounds the piece's deviation.
double hull_deviation(const Homogeneous& c) {
  const Vec2 a = project(c.front());
  const Vec2 b = project(c.back());
  double worst = 0.0;
  for (std::size_t i = 1; i + 1 < c.size(); ++i) {
    worst = std::max(worst, distance_to_segment(project(c[i]), a, b));
  }
  return worst;
}

// de Casteljau at t = 1/2: the control polygons of the two halves.
std::pair<Homogeneous, Homogeneous> split_half(Homogeneous work) {
  const std::size_t n = work.size() - 1;
  Homogeneous left(work.size());
  Homogeneous right(work.size());
  left[0] = work[0];
  right[n] = work[n];
  for (std::size_t r = 1; r <= n; ++r) {
    for (std::size_t i = 0; i + r <= n; ++i)
      work[i] = (work[i] + work[i + 1]) * 0.5;
    left[r] = work[0];
    right[n - r] = work[n - r];
  }
  return {std::move(left), std::move(right)};
}

void flatten(const Homogeneous& piece, double tolerance, int depth, std::vector<Vec2>& out) {
  if (depth >= kSplineMaxDepth || hull_deviation(piece) <= tolerance) {
    out.push_back(project(piece.back()));
    return;
  }
  const auto [left, right] = split_half(piece);
  flatten(left, tolerance, depth + 1, out);
  flatten(right, tolerance, depth + 1, out);
}

// The caller's tolerance, raised to the floor that keeps the count finite.
double effective_tolerance(double tolerance, const std::vector<Vec2>& points) {
  Vec2 lo = points.front();
  Vec2 hi = points.front();
  for (const Vec2& p : points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  const double floor = kSplineRelativeToleranceFloor * norm(hi - lo);
  return tolerance >= floor ? tolerance : floor;  // also replaces NaN
}

std::vector<Vec2> linearize_bezier(const std::vector<Vec2>& points, double tolerance) {
  Homogeneous piece;
  for (const Vec2& p : points)
    piece.push_back(lift(p, 1.0));
  std::vector<Vec2> out;
  flatten(piece, effective_tolerance(tolerance, points), 0, out);
  out.back() = points.back();
  return out;
}

// The knot span [t_j, t_j+1) that holds u, j in [order - 1, count - 1]; the
// end of the domain belongs to the last span.
std::size_t find_span(const Nurbs& c, double u) {
  const std::size_t p = static_cast<std::size_t>(c.order) - 1;
  const std::size_t n = c.points.size() - 1;
  if (u >= c.knots[n + 1]) return n;
  if (u <= c.knots[p]) return p;
  const auto begin = c.knots.begin();
  const auto it = std::upper_bound(begin + static_cast<std::ptrdiff_t>(p),
                                   begin + static_cast<std::ptrdiff_t>(n + 1), u);
  return static_cast<std::size_t>(it - begin) - 1;
}

struct HomogeneousEval {
  Vec3 value;
  Vec3 derivative;
};

// de Boor's algorithm on the homogeneous points. The derivative is
// p / (t_j+1 − t_j) times the difference of the last two intermediate points.
HomogeneousEval de_boor(const Nurbs& c, double u) {
  const std::size_t p = static_cast<std::size_t>(c.order) - 1;
  const std::size_t j = find_span(c, u);
  Homogeneous d(p + 1);
  for (std::size_t i = 0; i <= p; ++i)
    d[i] = lift(c.points[j - p + i], c.weights[j - p + i]);
  Vec3 derivative{};
  for (std::size_t r = 1; r <= p; ++r) {
    if (r == p) {
      derivative = (d[p] - d[p - 1]) * (static_cast<double>(p) / (c.knots[j + 1] - c.knots[j]));
    }
    for (std::size_t i = p; i >= r; --i) {
      const double lo = c.knots[j - p + i];
      const double hi = c.knots[j + 1 + i - r];
      const double a = (u - lo) / (hi - lo);
      d[i] = d[i - 1] * (1.0 - a) + d[i] * a;
    }
  }
  return {d[p], derivative};
}

// Boehm's knot insertion: adds u once, keeping the curve.
void insert_knot(std::vector<double>& knots, Homogeneous& pts, std::size_t p, double u) {
  const auto after = std::upper_bound(knots.begin(), knots.end(), u);
  const std::size_t k = static_cast<std::size_t>(after - knots.begin()) - 1;
  Homogeneous q;
  q.reserve(pts.size() + 1);
  for (std::size_t i = 0; i <= pts.size(); ++i) {
    if (i + p <= k) {
      q.push_back(pts[i]);
    } else if (i > k) {
      q.push_back(pts[i - 1]);
    } else {
      const double a = (u - knots[i]) / (knots[i + p] - knots[i]);
      q.push_back(pts[i - 1] * (1.0 - a) + pts[i] * a);
    }
  }
  knots.insert(after, u);
  pts = std::move(q);
}

// The curve as rational Bézier pieces, one per non-empty knot span: every
// interior knot raised to multiplicity p (the clamped ends already are).
std::vector<Homogeneous> bezier_pieces(const Nurbs& c) {
  const std::size_t p = static_cast<std::size_t>(c.order) - 1;
  std::vector<double> knots = c.knots;
  Homogeneous pts;
  for (std::size_t i = 0; i < c.points.size(); ++i)
    pts.push_back(lift(c.points[i], c.weights[i]));
  const auto [first, last] = domain(c);
  for (double u = first;;) {
    u = *std::upper_bound(knots.begin(), knots.end(), u);  // the next distinct knot
    if (u >= last) break;
    const auto count = static_cast<std::size_t>(std::count(knots.begin(), knots.end(), u));
    for (std::size_t s = count; s < p; ++s)
      insert_knot(knots, pts, p, u);
  }
  std::vector<Homogeneous> pieces;
  for (std::size_t s = 0; s + p < pts.size(); s += p) {
    pieces.emplace_back(pts.begin() + static_cast<std::ptrdiff_t>(s),
                        pts.begin() + static_cast<std::ptrdiff_t>(s + p + 1));
  }
  return pieces;
}

std::string format_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

CubicBezier cubic_from_g5(Vec2 start, Vec2 end, Vec2 ij, Vec2 pq) {
  return {start, start + ij, end + pq, end};
}

Vec2 g5_continuation_ij(const CubicBezier& previous) {
  return previous.p3 - previous.p2;
}

QuadBezier quad_from_g5_1(Vec2 start, Vec2 end, Vec2 ij) {
  return {start, start + ij, end};
}

Vec2 point(const CubicBezier& c, double t) {
  const double s = 1.0 - t;
  return c.p0 * (s * s * s) + c.p1 * (3.0 * s * s * t) + c.p2 * (3.0 * s * t * t) +
         c.p3 * (t * t * t);
}

Vec2 tangent(const CubicBezier& c, double t) {
  const double s = 1.0 - t;
  return ((c.p1 - c.p0) * (s * s) + (c.p2 - c.p1) * (2.0 * s * t) + (c.p3 - c.p2) * (t * t)) * 3.0;
}

Vec2 point(const QuadBezier& c, double t) {
  const double s = 1.0 - t;
  return c.p0 * (s * s) + c.p1 * (2.0 * s * t) + c.p2 * (t * t);
}

Vec2 tangent(const QuadBezier& c, double t) {
  return ((c.p1 - c.p0) * (1.0 - t) + (c.p2 - c.p1) * t) * 2.0;
}

std::vector<double> linuxcnc_knots(int order, std::size_t count) {
  // nurbs_additional_functions.cc, knot_vector_creator(n = count - 1, k = order).
  const auto k = static_cast<std::size_t>(order);
  std::vector<double> knots;
  knots.reserve(count + k);
  for (std::size_t i = 0; i < count + k; ++i) {
    const std::size_t v = i < k ? 0 : (i < count ? i - k + 1 : count - k + 1);
    knots.push_back(static_cast<double>(v));
  }
  return knots;
}

Nurbs make_nurbs(int order, std::vector<Vec2> points, std::vector<double> weights) {
  if (auto valid = check_nurbs(order, points, weights); !valid)
    throw std::invalid_argument(valid.error());
  std::vector<double> knots = linuxcnc_knots(order, points.size());
  return {order, std::move(points), std::move(weights), std::move(knots)};
}

std::pair<double, double> domain(const Nurbs& c) {
  const auto p = static_cast<std::size_t>(c.order) - 1;
  return {c.knots[p], c.knots[c.points.size()]};
}

Vec2 point(const Nurbs& c, double u) {
  const auto [first, last] = domain(c);
  return project(de_boor(c, std::clamp(u, first, last)).value);
}

Vec2 tangent(const Nurbs& c, double u) {
  const auto [first, last] = domain(c);
  const HomogeneousEval e = de_boor(c, std::clamp(u, first, last));
  // Quotient rule on C = A / w: C' = (A' − w' C) / w.
  const Vec2 value = project(e.value);
  const Vec2 a_prime{e.derivative.x, e.derivative.y};
  return (a_prime - value * e.derivative.z) / e.value.z;
}

std::vector<Vec2> linearize(const CubicBezier& c, double tolerance) {
  return linearize_bezier({c.p0, c.p1, c.p2, c.p3}, tolerance);
}

std::vector<Vec2> linearize(const QuadBezier& c, double tolerance) {
  return linearize_bezier({c.p0, c.p1, c.p2}, tolerance);
}

std::vector<Vec2> linearize(const Nurbs& c, double tolerance) {
  const double tol = effective_tolerance(tolerance, c.points);
  std::vector<Vec2> out;
  for (const Homogeneous& piece : bezier_pieces(c))
    flatten(piece, tol, 0, out);
  if (out.empty()) out.push_back(c.points.back());
  out.back() = c.points.back();
  return out;
}

tl::expected<void, std::string> check_nurbs_order(int order) {
  if (order >= 2) return {};
  return tl::unexpected("NURBS order L" + std::to_string(order) +
                        " is below 2; give L of 2 or more (LinuxCNC's default is 3)");
}

tl::expected<void, std::string> check_nurbs_count(int order, std::size_t count) {
  if (order < 0 || count >= static_cast<std::size_t>(order)) return {};
  return tl::unexpected("NURBS of order L" + std::to_string(order) + " needs at least " +
                        std::to_string(order) +
                        " control points, the start point included, but has " +
                        std::to_string(count) + "; add control points before G5.3 or lower L");
}

tl::expected<void, std::string> check_nurbs_weight(double weight, std::size_t index) {
  if (weight > 0.0 && std::isfinite(weight)) return {};
  return tl::unexpected("NURBS control point " + std::to_string(index) + " has weight P" +
                        format_number(weight) +
                        "; every weight must be a positive number (P1 is the usual)");
}

tl::expected<void, std::string> check_nurbs(int order, const std::vector<Vec2>& points,
                                            const std::vector<double>& weights) {
  if (auto e = check_nurbs_order(order); !e) return e;
  if (auto e = check_nurbs_count(order, points.size()); !e) return e;
  if (points.size() != weights.size()) {
    return tl::unexpected("NURBS has " + std::to_string(points.size()) + " control points but " +
                          std::to_string(weights.size()) + " weights; give one weight per point");
  }
  for (std::size_t i = 0; i < weights.size(); ++i) {
    if (auto e = check_nurbs_weight(weights[i], i); !e) return e;
  }
  return {};
}

}  // namespace usina::core
