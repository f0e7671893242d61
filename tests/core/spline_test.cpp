#include "core/spline.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

namespace usina::core {
namespace {

using Curve = std::function<Vec2(double)>;

// Distance from q to the curve f over [t0, t1]: the nearest of many samples,
// then a golden-section search between its neighbours.
double distance_to_curve(const Curve& f, double t0, double t1, Vec2 q) {
  constexpr int kSamples = 1500;
  const double step = (t1 - t0) / kSamples;
  int best = 0;
  double best_d = distance(f(t0), q);
  for (int i = 1; i <= kSamples; ++i) {
    const double d = distance(f(t0 + step * i), q);
    if (d < best_d) {
      best_d = d;
      best = i;
    }
  }
  double a = std::max(t0, t0 + step * (best - 1));
  double b = std::min(t1, t0 + step * (best + 1));
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int i = 0; i < 200; ++i) {
    const double m1 = b - g * (b - a);
    const double m2 = a + g * (b - a);
    if (distance(f(m1), q) < distance(f(m2), q)) {
      b = m2;
    } else {
      a = m1;
    }
  }
  return std::min(best_d, distance(f((a + b) / 2.0), q));
}

double distance_to_polyline(Vec2 start, const std::vector<Vec2>& pts, Vec2 q) {
  double best = std::numeric_limits<double>::infinity();
  Vec2 a = start;
  for (const Vec2& b : pts) {
    const Vec2 ab = b - a;
    const double len2 = dot(ab, ab);
    const double t = len2 == 0.0 ? 0.0 : std::clamp(dot(q - a, ab) / len2, 0.0, 1.0);
    best = std::min(best, distance(a + ab * t, q));
    a = b;
  }
  return best;
}

// Checks the chordal tolerance both ways: every output point on the curve,
// points along every chord within `tol` of the curve, and curve samples
// within `tol` of the polyline.
void expect_within_tolerance(const Curve& f, double t0, double t1, const std::vector<Vec2>& pts,
                             double tol) {
  Vec2 prev = f(t0);
  for (const Vec2& p : pts) {
    EXPECT_LE(distance_to_curve(f, t0, t1, p), 1e-9) << "(" << p.x << ", " << p.y << ")";
    for (double s : {0.25, 0.5, 0.75}) {
      const Vec2 q = prev + (p - prev) * s;
      EXPECT_LE(distance_to_curve(f, t0, t1, q), tol * (1.0 + 1e-9));
    }
    prev = p;
  }
  for (int i = 0; i <= 1000; ++i) {
    const Vec2 q = f(t0 + (t1 - t0) * i / 1000.0);
    EXPECT_LE(distance_to_polyline(f(t0), pts, q), tol * (1.0 + 1e-9));
  }
}

void expect_same_direction(Vec2 a, Vec2 b) {
  EXPECT_NEAR(cross(a, b), 0.0, 1e-9 * norm(a) * norm(b));
  EXPECT_GT(dot(a, b), 0.0);
}

void expect_near(Vec2 a, Vec2 b, double tol = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
}

const CubicBezier kN{{0, 0}, {0, 3}, {1, -2}, {1, 1}};  // LinuxCNC docs' "curvy N"

Curve of(const CubicBezier& c) {
  return [c](double t) { return point(c, t); };
}

Curve of(const QuadBezier& c) {
  return [c](double t) { return point(c, t); };
}

Curve of(const Nurbs& c) {
  return [c](double u) { return point(c, u); };
}

// --- G-code words ------------------------------------------------------------

TEST(G5, IJFromStartAndPQFromEnd) {
  // LinuxCNC docs, G5 example: G0 X0 Y0 / G5 I0 J3 P0 Q-3 X1 Y1.
  const CubicBezier c = cubic_from_g5({0, 0}, {1, 1}, {0, 3}, {0, -3});
  EXPECT_EQ(c.p0, (Vec2{0, 0}));
  EXPECT_EQ(c.p1, (Vec2{0, 3}));
  EXPECT_EQ(c.p2, (Vec2{1, -2}));
  EXPECT_EQ(c.p3, (Vec2{1, 1}));
}

TEST(G5, OmittedIJAreThePreviousPQNegated) {
  // LinuxCNC docs, G5: the follow-on "G5 P0 Q-3 X2 Y2" after the first N.
  const Vec2 ij = g5_continuation_ij(kN);
  EXPECT_EQ(ij, (Vec2{0, 3}));
  const CubicBezier next = cubic_from_g5(kN.p3, {2, 2}, ij, {0, -3});
  EXPECT_EQ(next.p1, (Vec2{1, 4}));
  // The first control point is the previous second one reflected through the start.
  EXPECT_EQ(next.p1, kN.p3 * 2.0 - kN.p2);
}

TEST(G5, ContinuationKeepsTheTangent) {
  const CubicBezier prev = cubic_from_g5({0, 0}, {5, 1}, {2, 3}, {-1, -2});
  const CubicBezier next = cubic_from_g5(prev.p3, {9, -4}, g5_continuation_ij(prev), {1, 1});
  expect_near(tangent(prev, 1.0), tangent(next, 0.0));
}

TEST(G5_1, DocsExampleIsTheParabolaYEqualsXSquared) {
  // LinuxCNC docs, G5.1: G0 X-2 Y4 / G5.1 X2 I2 J-8 is a parabola through the origin.
  const QuadBezier c = quad_from_g5_1({-2, 4}, {2, 4}, {2, -8});
  EXPECT_EQ(c.p1, (Vec2{0, -4}));
  expect_near(point(c, 0.5), {0, 0});
  for (const Vec2& p : linearize(c, 0.01))
    EXPECT_NEAR(p.y, p.x * p.x, 1e-12);
}

// --- Cubic Bézier ------------------------------------------------------------

TEST(CubicBezier, EndPointsAreExact) {
  EXPECT_EQ(point(kN, 0.0), kN.p0);
  EXPECT_EQ(point(kN, 1.0), kN.p3);
  const CubicBezier odd{{0.1, 0.7}, {3.3, -1.9}, {-2.2, 5.1}, {1.0 / 3.0, 2.0 / 7.0}};
  for (double tol : {1.0, 1e-2, 1e-5})
    EXPECT_EQ(linearize(odd, tol).back(), odd.p3);
}

TEST(CubicBezier, TangentsAtEndsFollowTheControlLegs) {
  expect_same_direction(tangent(kN, 0.0), kN.p1 - kN.p0);
  expect_same_direction(tangent(kN, 1.0), kN.p3 - kN.p2);
  expect_near(tangent(kN, 0.0), (kN.p1 - kN.p0) * 3.0);
}

TEST(CubicBezier, TangentIsTheDerivative) {
  for (double t : {0.1, 0.4, 0.77}) {
    const double h = 1e-6;
    const Vec2 numeric = (point(kN, t + h) - point(kN, t - h)) / (2.0 * h);
    expect_near(tangent(kN, t), numeric, 1e-6);
  }
}

TEST(CubicBezier, ChordsStayWithinTolerance) {
  for (double tol : {0.1, 0.01, 0.001}) {
    SCOPED_TRACE(tol);
    expect_within_tolerance(of(kN), 0.0, 1.0, linearize(kN, tol), tol);
  }
}

TEST(CubicBezier, SegmentCountGrowsAsToleranceShrinks) {
  std::size_t last = 0;
  for (double tol : {1.0, 0.1, 0.01, 0.001, 0.0001}) {
    const std::size_t n = linearize(kN, tol).size();
    EXPECT_GT(n, last) << tol;
    last = n;
  }
}

TEST(CubicBezier, StraightLineIsOneSegment) {
  const CubicBezier line{{0, 0}, {1, 1}, {2, 2}, {3, 3}};
  const std::vector<Vec2> pts = linearize(line, 1e-6);
  ASSERT_EQ(pts.size(), 1U);
  EXPECT_EQ(pts[0], line.p3);
}

TEST(CubicBezier, CollinearCurveThatDoublesBackIsNotOneSegment) {
  // Control points past the end make the path overshoot and return.
  const CubicBezier back{{0, 0}, {4, 0}, {4, 0}, {1, 0}};
  const std::vector<Vec2> pts = linearize(back, 0.01);
  EXPECT_GT(pts.size(), 1U);
  expect_within_tolerance(of(back), 0.0, 1.0, pts, 0.01);
}

TEST(CubicBezier, SegmentsAreShorterWhereTheCurveBends) {
  // Straight for most of its length, then a tight turn near (10, 0).
  const CubicBezier hook{{0, 0}, {10, 0}, {10, 0}, {10, 1}};
  const std::vector<Vec2> pts = linearize(hook, 0.001);
  double shortest = std::numeric_limits<double>::infinity();
  double longest = 0.0;
  Vec2 prev = hook.p0;
  for (const Vec2& p : pts) {
    shortest = std::min(shortest, distance(prev, p));
    longest = std::max(longest, distance(prev, p));
    prev = p;
  }
  EXPECT_GT(longest, 4.0 * shortest);
}

TEST(CubicBezier, CuspIsLinearisedWithinTolerance) {
  const CubicBezier cusp{{0, 0}, {2, 2}, {-1, 2}, {1, 0}};
  expect_within_tolerance(of(cusp), 0.0, 1.0, linearize(cusp, 0.001), 0.001);
}

TEST(CubicBezier, DegenerateToleranceStillTerminates) {
  for (double tol : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
    const std::vector<Vec2> pts = linearize(kN, tol);
    EXPECT_GT(pts.size(), 1U);
    EXPECT_LT(pts.size(), 1'000'000U);
    EXPECT_EQ(pts.back(), kN.p3);
  }
}

TEST(CubicBezier, PointCurveIsOneSegment) {
  const CubicBezier dot_curve{{2, 3}, {2, 3}, {2, 3}, {2, 3}};
  EXPECT_EQ(linearize(dot_curve, 0.0), (std::vector<Vec2>{{2, 3}}));
}

// --- Quadratic Bézier --------------------------------------------------------

TEST(QuadBezier, EndPointsAndTangentsFollowTheControlPoint) {
  const QuadBezier c{{1, 1}, {4, 5}, {7, 0}};
  EXPECT_EQ(point(c, 0.0), c.p0);
  EXPECT_EQ(point(c, 1.0), c.p2);
  expect_same_direction(tangent(c, 0.0), c.p1 - c.p0);
  expect_same_direction(tangent(c, 1.0), c.p2 - c.p1);
  EXPECT_EQ(linearize(c, 0.01).back(), c.p2);
}

TEST(QuadBezier, ChordsStayWithinTolerance) {
  const QuadBezier c{{1, 1}, {4, 5}, {7, 0}};
  for (double tol : {0.1, 0.001}) {
    SCOPED_TRACE(tol);
    expect_within_tolerance(of(c), 0.0, 1.0, linearize(c, tol), tol);
  }
}

TEST(QuadBezier, StraightLineIsOneSegment) {
  EXPECT_EQ(linearize(QuadBezier{{0, 0}, {0.5, 1}, {1, 2}}, 1e-9).size(), 1U);
}

// --- NURBS -------------------------------------------------------------------

TEST(Nurbs, KnotsAreLinuxcncClampedUniformIntegers) {
  // nurbs_additional_functions.cc, knot_vector_creator(n = 4, k = 3).
  EXPECT_EQ(linuxcnc_knots(3, 5), (std::vector<double>{0, 0, 0, 1, 2, 3, 3, 3}));
  EXPECT_EQ(linuxcnc_knots(4, 4), (std::vector<double>{0, 0, 0, 0, 1, 1, 1, 1}));
  EXPECT_EQ(linuxcnc_knots(2, 3), (std::vector<double>{0, 0, 1, 2, 2}));
  const Nurbs c = make_nurbs(4, {{0, 0}, {1, 2}, {3, 2}, {4, 0}, {6, 1}}, {1, 1, 1, 1, 1});
  EXPECT_EQ(c.knots, linuxcnc_knots(4, 5));
  EXPECT_EQ(domain(c), (std::pair<double, double>{0.0, 2.0}));
}

TEST(Nurbs, Order4With4UnitWeightPointsIsTheCubicBezier) {
  // What LinuxCNC feeds for G5 (convert_spline: NURBS_FEED with order 4).
  const Nurbs n = make_nurbs(4, {kN.p0, kN.p1, kN.p2, kN.p3}, {1, 1, 1, 1});
  for (int i = 0; i <= 20; ++i) {
    const double t = i / 20.0;
    expect_near(point(n, t), point(kN, t));
    expect_near(tangent(n, t), tangent(kN, t), 1e-11);
  }
  EXPECT_EQ(linearize(n, 0.01), linearize(kN, 0.01));
}

TEST(Nurbs, Order3With3UnitWeightPointsIsTheQuadBezier) {
  // What LinuxCNC feeds for G5.1 (convert_spline: NURBS_FEED with order 3).
  const QuadBezier q{{-2, 4}, {0, -4}, {2, 4}};
  const Nurbs n = make_nurbs(3, {q.p0, q.p1, q.p2}, {1, 1, 1});
  for (int i = 0; i <= 20; ++i)
    expect_near(point(n, i / 20.0), point(q, i / 20.0));
  EXPECT_EQ(linearize(n, 0.01), linearize(q, 0.01));
}

TEST(Nurbs, EndPointsAreExact) {
  // LinuxCNC docs, G5.2 example: order 3, the last point of weight 2.
  const Nurbs c = make_nurbs(3, {{0, 0}, {0, 1}, {2, 2}, {2, 0}, {0, 0}}, {1, 1, 1, 1, 2});
  EXPECT_EQ(point(c, domain(c).first), c.points.front());
  EXPECT_EQ(point(c, domain(c).second), c.points.back());
  EXPECT_EQ(linearize(c, 0.001).back(), c.points.back());
}

TEST(Nurbs, TangentsAtEndsFollowTheFirstAndLastLegs) {
  const Nurbs c = make_nurbs(4, {{0, 0}, {1, 2}, {3, 2}, {4, 0}, {6, 1}}, {1, 3, 0.5, 1, 2});
  expect_same_direction(tangent(c, domain(c).first), c.points[1] - c.points[0]);
  expect_same_direction(tangent(c, domain(c).second), c.points[4] - c.points[3]);
}

TEST(Nurbs, TangentIsTheDerivative) {
  const Nurbs c = make_nurbs(4, {{0, 0}, {1, 2}, {3, 2}, {4, 0}, {6, 1}}, {1, 3, 0.5, 1, 2});
  for (double u : {0.2, 0.9, 1.3, 1.95}) {
    const double h = 1e-6;
    const Vec2 numeric = (point(c, u + h) - point(c, u - h)) / (2.0 * h);
    expect_near(tangent(c, u), numeric, 1e-5);
  }
}

TEST(Nurbs, ChordsStayWithinTolerance) {
  const Nurbs docs = make_nurbs(3, {{0, 0}, {0, 1}, {2, 2}, {2, 0}, {0, 0}}, {1, 1, 1, 1, 2});
  const Nurbs wavy = make_nurbs(4, {{0, 0}, {1, 3}, {2, -3}, {3, 3}, {4, -3}, {5, 3}, {6, 0}},
                                {1, 2, 0.5, 1, 4, 1, 1});
  for (const Nurbs* c : {&docs, &wavy}) {
    for (double tol : {0.05, 0.001}) {
      SCOPED_TRACE(tol);
      expect_within_tolerance(of(*c), domain(*c).first, domain(*c).second, linearize(*c, tol), tol);
    }
  }
}

TEST(Nurbs, SegmentCountGrowsAsToleranceShrinks) {
  const Nurbs c = make_nurbs(3, {{0, 0}, {0, 1}, {2, 2}, {2, 0}, {0, 0}}, {1, 1, 1, 1, 2});
  std::size_t last = 0;
  for (double tol : {0.5, 0.05, 0.005, 0.0005}) {
    const std::size_t n = linearize(c, tol).size();
    EXPECT_GT(n, last) << tol;
    last = n;
  }
}

TEST(Nurbs, RationalQuadraticGivesAnExactQuarterCircle) {
  const Nurbs c = make_nurbs(3, {{1, 0}, {1, 1}, {0, 1}}, {1, std::numbers::sqrt2 / 2.0, 1});
  for (int i = 0; i <= 10; ++i)
    EXPECT_NEAR(norm(point(c, i / 10.0)), 1.0, 1e-12);
  for (const Vec2& p : linearize(c, 1e-4))
    EXPECT_NEAR(norm(p), 1.0, 1e-12);
}

TEST(Nurbs, ScalingAllWeightsKeepsTheCurve) {
  const std::vector<Vec2> pts{{0, 0}, {1, 2}, {3, 2}, {4, 0}, {6, 1}};
  const Nurbs a = make_nurbs(3, pts, {1, 2, 3, 1, 0.5});
  const Nurbs b = make_nurbs(3, pts, {7, 14, 21, 7, 3.5});
  for (int i = 0; i <= 30; ++i)
    expect_near(point(a, i / 10.0), point(b, i / 10.0));
}

TEST(Nurbs, HeavierWeightPullsTheCurveTowardItsPoint) {
  const std::vector<Vec2> pts{{0, 0}, {1, 2}, {3, 2}, {4, 0}};
  const Nurbs light = make_nurbs(3, pts, {1, 1, 1, 1});
  const Nurbs heavy = make_nurbs(3, pts, {1, 5, 1, 1});
  const auto [first, last] = domain(light);
  EXPECT_LT(distance_to_curve(of(heavy), first, last, pts[1]),
            distance_to_curve(of(light), first, last, pts[1]) / 2.0);
}

TEST(Nurbs, Order2IsTheControlPolygon) {
  const Nurbs c = make_nurbs(2, {{0, 0}, {1, 2}, {3, 2}, {4, 0}}, {1, 2, 3, 1});
  const std::vector<Vec2> pts = linearize(c, 1e-9);
  ASSERT_EQ(pts.size(), 3U);
  for (std::size_t i = 0; i < 3; ++i)
    expect_near(pts[i], c.points[i + 1]);
}

TEST(Nurbs, PointClampsParameterToDomain) {
  const Nurbs c = make_nurbs(3, {{0, 0}, {0, 1}, {2, 2}, {2, 0}}, {1, 1, 1, 1});
  EXPECT_EQ(point(c, -5.0), c.points.front());
  EXPECT_EQ(point(c, 99.0), c.points.back());
}

// --- Validation --------------------------------------------------------------

TEST(NurbsErrors, OrderBelowTwoIsRejected) {
  EXPECT_TRUE(check_nurbs_order(2));
  EXPECT_TRUE(check_nurbs_order(5));
  const auto e = check_nurbs_order(1);
  ASSERT_FALSE(e);
  EXPECT_NE(e.error().find("L1"), std::string::npos) << e.error();
  EXPECT_FALSE(check_nurbs_order(0));
  EXPECT_FALSE(check_nurbs_order(-3));
}

TEST(NurbsErrors, FewerPointsThanOrderIsRejected) {
  EXPECT_TRUE(check_nurbs_count(3, 3));
  EXPECT_TRUE(check_nurbs_count(3, 10));
  const auto e = check_nurbs_count(4, 3);
  ASSERT_FALSE(e);
  EXPECT_NE(e.error().find("at least 4"), std::string::npos) << e.error();
  EXPECT_NE(e.error().find("has 3"), std::string::npos) << e.error();
}

TEST(NurbsErrors, NonPositiveWeightIsRejected) {
  EXPECT_TRUE(check_nurbs_weight(0.25, 1));
  for (double w : {0.0, -1.5, std::numeric_limits<double>::quiet_NaN(),
                   std::numeric_limits<double>::infinity()}) {
    EXPECT_FALSE(check_nurbs_weight(w, 2)) << w;
  }
  const auto e = check_nurbs_weight(-1.5, 2);
  ASSERT_FALSE(e);
  EXPECT_NE(e.error().find("P-1.5"), std::string::npos) << e.error();
  EXPECT_NE(e.error().find("point 2"), std::string::npos) << e.error();
}

TEST(NurbsErrors, WholeBlockReportsTheFirstProblem) {
  const std::vector<Vec2> pts{{0, 0}, {1, 1}, {2, 0}};
  EXPECT_TRUE(check_nurbs(3, pts, {1, 1, 1}));
  EXPECT_FALSE(check_nurbs(1, pts, {1, 1, 1}));
  EXPECT_FALSE(check_nurbs(4, pts, {1, 1, 1}));
  EXPECT_FALSE(check_nurbs(3, pts, {1, 1}));
  EXPECT_FALSE(check_nurbs(3, pts, {1, 0, 1}));
}

TEST(NurbsErrors, MakeNurbsThrowsOnInvalidInput) {
  EXPECT_THROW(make_nurbs(4, {{0, 0}, {1, 1}}, {1, 1}), std::invalid_argument);
  EXPECT_THROW(make_nurbs(3, {{0, 0}, {1, 1}, {2, 0}}, {1, -1, 1}), std::invalid_argument);
}

}  // namespace
}  // namespace usina::core
