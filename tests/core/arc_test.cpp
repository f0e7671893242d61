#include "core/arc.hpp"

#include <cmath>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "core/units.hpp"
#include "core/vec3.hpp"

namespace usina::core {
namespace {

constexpr double kEps = 1e-12;

// Greatest distance between the arc of `radius` about `center` and the chord
// from a to b (both on the arc, less than half a turn apart): the sagitta.
double sagitta(const Vec2& a, const Vec2& b, double radius) {
  const double half = distance(a, b) / 2.0;
  return radius - std::sqrt(std::max(0.0, radius * radius - half * half));
}

// --- planes -----------------------------------------------------------------

TEST(Plane, AxesFollowRs274ngcOrderSoEachPlaneIsRightHanded) {
  EXPECT_EQ(axes_of(Plane::XY).first, 0);
  EXPECT_EQ(axes_of(Plane::XY).second, 1);
  EXPECT_EQ(axes_of(Plane::XY).axial, 2);
  // G18: the first axis is Z and the second X, so Z x X = +Y.
  EXPECT_EQ(axes_of(Plane::ZX).first, 2);
  EXPECT_EQ(axes_of(Plane::ZX).second, 0);
  EXPECT_EQ(axes_of(Plane::ZX).axial, 1);
  EXPECT_EQ(axes_of(Plane::YZ).first, 1);
  EXPECT_EQ(axes_of(Plane::YZ).second, 2);
  EXPECT_EQ(axes_of(Plane::YZ).axial, 0);
}

TEST(Plane, NormalIsTheUnitAxialAxis) {
  EXPECT_EQ(normal_of(Plane::XY), (Vec3{0, 0, 1}));
  EXPECT_EQ(normal_of(Plane::ZX), (Vec3{0, 1, 0}));
  EXPECT_EQ(normal_of(Plane::YZ), (Vec3{1, 0, 0}));
}

TEST(Plane, InPlaneAndFromPlaneAreInverse) {
  const Vec3 p{1, 2, 3};
  for (const Plane pl : {Plane::XY, Plane::ZX, Plane::YZ}) {
    const Vec2 v = in_plane(p, pl);
    EXPECT_EQ(from_plane(v, p[axes_of(pl).axial], pl), p);
  }
  EXPECT_EQ(in_plane(p, Plane::ZX), (Vec2{3, 1}));
  EXPECT_EQ(in_plane(p, Plane::YZ), (Vec2{2, 3}));
}

// --- arc_sweep --------------------------------------------------------------

TEST(ArcSweep, CounterClockwiseQuarterIsPlusHalfPi) {
  EXPECT_NEAR(arc_sweep({1, 0}, {0, 1}, {0, 0}, true), kPi / 2, kEps);
}

TEST(ArcSweep, ClockwiseToTheSamePointGoesTheOtherWayRound) {
  EXPECT_NEAR(arc_sweep({1, 0}, {0, 1}, {0, 0}, false), -3 * kPi / 2, kEps);
}

TEST(ArcSweep, ClockwiseQuarterIsMinusHalfPi) {
  EXPECT_NEAR(arc_sweep({0, 1}, {1, 0}, {0, 0}, false), -kPi / 2, kEps);
}

TEST(ArcSweep, EndAtStartIsAFullCircleEitherWay) {
  EXPECT_NEAR(arc_sweep({5, 0}, {5, 0}, {0, 0}, true), 2 * kPi, kEps);
  EXPECT_NEAR(arc_sweep({5, 0}, {5, 0}, {0, 0}, false), -2 * kPi, kEps);
}

TEST(ArcSweep, HalfCircleAcrossTheAtan2CutIsPi) {
  // Start at angle 180 degrees, where atan2 jumps from +pi to -pi.
  EXPECT_NEAR(arc_sweep({-1, 0}, {1, 0}, {0, 0}, true), kPi, kEps);
  EXPECT_NEAR(arc_sweep({-1, 0}, {1, 0}, {0, 0}, false), -kPi, kEps);
}

TEST(ArcSweep, EachExtraTurnAddsTwoPiInTheArcsDirection) {
  EXPECT_NEAR(arc_sweep({1, 0}, {0, 1}, {0, 0}, true, 3), kPi / 2 + 4 * kPi, 1e-9);
  EXPECT_NEAR(arc_sweep({1, 0}, {0, 1}, {0, 0}, false, 2), -3 * kPi / 2 - 2 * kPi, 1e-9);
}

TEST(ArcSweep, TurnsBelowOneCountAsOne) {
  EXPECT_NEAR(arc_sweep({1, 0}, {0, 1}, {0, 0}, true, 0), kPi / 2, kEps);
  EXPECT_NEAR(arc_sweep({1, 0}, {0, 1}, {0, 0}, true, -4), kPi / 2, kEps);
}

TEST(ArcSweep, CentreAwayFromTheOriginIsUsed) {
  EXPECT_NEAR(arc_sweep({11, 5}, {10, 6}, {10, 5}, true), kPi / 2, kEps);
}

// --- arc_center_from_radius -------------------------------------------------

TEST(ArcCenterFromRadius, PositiveRadiusCounterClockwiseTakesShortArcCentreLeftOfChord) {
  const auto c = arc_center_from_radius({0, 0}, {2, 0}, std::sqrt(2.0), true);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->x, 1.0, kEps);
  EXPECT_NEAR(c->y, 1.0, kEps);
  // And the sweep from that centre is the short one (90 degrees).
  EXPECT_NEAR(arc_sweep({0, 0}, {2, 0}, *c, true), kPi / 2, 1e-9);
}

TEST(ArcCenterFromRadius, PositiveRadiusClockwiseTakesShortArcCentreRightOfChord) {
  const auto c = arc_center_from_radius({0, 0}, {2, 0}, std::sqrt(2.0), false);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->x, 1.0, kEps);
  EXPECT_NEAR(c->y, -1.0, kEps);
  EXPECT_NEAR(arc_sweep({0, 0}, {2, 0}, *c, false), -kPi / 2, 1e-9);
}

TEST(ArcCenterFromRadius, NegativeRadiusTakesLongArc) {
  // RS274NGC 3.5.3.1: a negative R asks for the arc of more than 180 degrees.
  const auto ccw = arc_center_from_radius({0, 0}, {2, 0}, -std::sqrt(2.0), true);
  ASSERT_TRUE(ccw.has_value());
  EXPECT_NEAR(ccw->x, 1.0, kEps);
  EXPECT_NEAR(ccw->y, -1.0, kEps);
  EXPECT_NEAR(arc_sweep({0, 0}, {2, 0}, *ccw, true), 3 * kPi / 2, 1e-9);
  const auto cw = arc_center_from_radius({0, 0}, {2, 0}, -std::sqrt(2.0), false);
  ASSERT_TRUE(cw.has_value());
  EXPECT_NEAR(cw->y, 1.0, kEps);
  EXPECT_NEAR(arc_sweep({0, 0}, {2, 0}, *cw, false), -3 * kPi / 2, 1e-9);
}

TEST(ArcCenterFromRadius, CentreIsAtRadiusFromBothEnds) {
  const Vec2 a{3, -1};
  const Vec2 b{-2, 4};
  for (const double r : {4.0, -4.0, 10.0, -10.0}) {
    for (const bool ccw : {true, false}) {
      const auto c = arc_center_from_radius(a, b, r, ccw);
      ASSERT_TRUE(c.has_value());
      EXPECT_NEAR(distance(a, *c), std::fabs(r), 1e-9);
      EXPECT_NEAR(distance(b, *c), std::fabs(r), 1e-9);
    }
  }
}

TEST(ArcCenterFromRadius, HalfCircleHasCentreOnTheChordMidpoint) {
  const auto c = arc_center_from_radius({0, 0}, {10, 0}, 5.0, true);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->x, 5.0, kEps);
  EXPECT_NEAR(c->y, 0.0, kEps);
}

TEST(ArcCenterFromRadius, RadiusJustUnderHalfChordWithinToleranceGivesMidpoint) {
  // Half the chord is 5; R = 5 - 5e-7 is within the default 1e-6.
  const auto c = arc_center_from_radius({0, 0}, {10, 0}, 5.0 - 5e-7, true);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->x, 5.0, kEps);
  EXPECT_NEAR(c->y, 0.0, kEps);
}

TEST(ArcCenterFromRadius, RadiusSmallerThanHalfChordBeyondToleranceHasNoCentre) {
  EXPECT_FALSE(arc_center_from_radius({0, 0}, {10, 0}, 4.99, true).has_value());
  EXPECT_FALSE(arc_center_from_radius({0, 0}, {10, 0}, -4.99, false).has_value());
  EXPECT_FALSE(arc_center_from_radius({0, 0}, {10, 0}, 5.0 - 2e-6, true).has_value());
}

TEST(ArcCenterFromRadius, ToleranceArgumentWidensTheAcceptedGap) {
  const auto c = arc_center_from_radius({0, 0}, {10, 0}, 4.99, true, 0.02);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->x, 5.0, kEps);
  EXPECT_NEAR(c->y, 0.0, kEps);
}

TEST(ArcCenterFromRadius, ZeroLengthChordHasNoCentre) {
  EXPECT_FALSE(arc_center_from_radius({1, 1}, {1, 1}, 5.0, true).has_value());
}

// --- helix_length -----------------------------------------------------------

TEST(HelixLength, FlatArcIsRadiusTimesSweep) {
  EXPECT_NEAR(helix_length(2.0, kPi, 0.0), 2 * kPi, kEps);
  EXPECT_NEAR(helix_length(2.0, -kPi, 0.0), 2 * kPi, kEps);
}

TEST(HelixLength, AxialTravelIsTheOtherLegOfTheUnrolledTriangle) {
  EXPECT_NEAR(helix_length(1.0, 3.0, 4.0), 5.0, kEps);
}

// --- segments_for_tolerance -------------------------------------------------

TEST(SegmentsForTolerance, CountIsTheSmallestKeepingTheSagittaWithinTolerance) {
  for (const double radius : {0.5, 10.0, 250.0}) {
    for (const double tol : {0.001, 0.01, 0.1}) {
      for (const double sweep : {kPi / 7, kPi / 2, 2 * kPi, 5 * kPi}) {
        const int n = segments_for_tolerance(radius, sweep, tol);
        const double step = sweep / n;
        const double s = radius * (1.0 - std::cos(step / 2));
        EXPECT_LE(s, tol * (1 + 1e-9)) << radius << " " << tol << " " << sweep;
        if (n > 1) {
          const double coarser = sweep / (n - 1);
          EXPECT_GT(radius * (1.0 - std::cos(coarser / 2)), tol) << radius << " " << sweep;
        }
      }
    }
  }
}

TEST(SegmentsForTolerance, NegativeSweepNeedsAsManyAsPositive) {
  EXPECT_EQ(segments_for_tolerance(10, -kPi, 0.01), segments_for_tolerance(10, kPi, 0.01));
}

TEST(SegmentsForTolerance, AtLeastOneSegment) {
  EXPECT_EQ(segments_for_tolerance(10, 0.0, 0.01), 1);
  EXPECT_EQ(segments_for_tolerance(10, 1e-9, 0.01), 1);
}

TEST(SegmentsForTolerance, RadiusNotAboveToleranceIsOneSegment) {
  EXPECT_EQ(segments_for_tolerance(0.01, 2 * kPi, 0.01), 1);
  EXPECT_EQ(segments_for_tolerance(0.0, 2 * kPi, 0.01), 1);
}

TEST(SegmentsForTolerance, NonPositiveToleranceIsOneSegmentNotADivisionByZero) {
  EXPECT_EQ(segments_for_tolerance(10, 2 * kPi, 0.0), 1);
  EXPECT_EQ(segments_for_tolerance(10, 2 * kPi, -1.0), 1);
}

TEST(SegmentsForTolerance, HugeRatiosAreCappedSoMemoryStaysBounded) {
  EXPECT_LE(segments_for_tolerance(1e9, 1e6, 1e-12), 10'000'000);
  EXPECT_GE(segments_for_tolerance(1e9, 1e6, 1e-12), 1);
}

// --- linearize_arc ----------------------------------------------------------

TEST(LinearizeArc, EndsExactlyAtTheEndPoint) {
  const Vec3 start{10, 0, 0};
  const Vec3 end{0, 10, 0};
  const auto pts = linearize_arc(start, end, {0, 0, 0}, Plane::XY, kPi / 2, 0.01);
  ASSERT_FALSE(pts.empty());
  EXPECT_EQ(pts.back(), end);
  EXPECT_EQ(static_cast<int>(pts.size()), segments_for_tolerance(10, kPi / 2, 0.01));
}

TEST(LinearizeArc, EveryPointIsOnTheCircleAndEveryChordWithinTolerance) {
  const double tol = 0.005;
  const double r = 25.0;
  const Vec3 start{r, 0, 0};
  const Vec3 end{-r, 0, 0};
  const auto pts = linearize_arc(start, end, {0, 0, 0}, Plane::XY, kPi, tol);
  ASSERT_GT(pts.size(), 2u);
  Vec2 prev{start.x, start.y};
  for (const Vec3& p : pts) {
    EXPECT_NEAR(std::hypot(p.x, p.y), r, 1e-9);
    EXPECT_EQ(p.z, 0.0);
    EXPECT_LE(sagitta(prev, {p.x, p.y}, r), tol * (1 + 1e-9));
    prev = {p.x, p.y};
  }
}

TEST(LinearizeArc, ClockwiseSweepGoesClockwise) {
  // From (10, 0) clockwise a quarter turn: the first point has negative Y.
  const auto pts = linearize_arc({10, 0, 0}, {0, -10, 0}, {0, 0, 0}, Plane::XY, -kPi / 2, 0.01);
  ASSERT_GT(pts.size(), 1u);
  EXPECT_LT(pts.front().y, 0.0);
  EXPECT_GT(pts.front().x, 0.0);
}

TEST(LinearizeArc, HelixAxialCoordinateMovesLinearlyWithAngle) {
  // Full turn in XY climbing from Z0 to Z4.
  const auto pts = linearize_arc({5, 0, 0}, {5, 0, 4}, {0, 0, 0}, Plane::XY, 2 * kPi, 0.01);
  const auto n = pts.size();
  ASSERT_GT(n, 4u);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i + 1) / static_cast<double>(n);
    EXPECT_NEAR(pts[i].z, 4.0 * t, 1e-9);
  }
  EXPECT_EQ(pts.back(), (Vec3{5, 0, 4}));
}

TEST(LinearizeArc, ZxPlaneKeepsYAsTheAxialCoordinate) {
  // G18: start at Z=10 (first axis) about the origin, a quarter turn CCW
  // (seen from +Y) goes towards +X.
  const auto pts = linearize_arc({0, 3, 10}, {10, 3, 0}, {0, 3, 0}, Plane::ZX, kPi / 2, 0.01);
  ASSERT_GT(pts.size(), 1u);
  for (const Vec3& p : pts) {
    EXPECT_NEAR(p.y, 3.0, 1e-12);
    EXPECT_NEAR(std::hypot(p.z, p.x), 10.0, 1e-9);
    EXPECT_GE(p.x, -1e-12);
  }
  EXPECT_EQ(pts.back(), (Vec3{10, 3, 0}));
}

TEST(LinearizeArc, YzPlaneRotatesYTowardsZ) {
  const auto pts = linearize_arc({0, 10, 0}, {0, 0, 10}, {0, 0, 0}, Plane::YZ, kPi / 2, 0.01);
  ASSERT_GT(pts.size(), 1u);
  EXPECT_GT(pts.front().z, 0.0);
  for (const Vec3& p : pts) {
    EXPECT_NEAR(p.x, 0.0, 1e-12);
    EXPECT_NEAR(std::hypot(p.y, p.z), 10.0, 1e-9);
  }
}

TEST(LinearizeArc, TinyArcIsOneSegmentToTheEnd) {
  const auto pts = linearize_arc({0.001, 0, 0}, {0, 0.001, 0}, {0, 0, 0}, Plane::XY, kPi / 2, 0.01);
  ASSERT_EQ(pts.size(), 1u);
  EXPECT_EQ(pts[0], (Vec3{0, 0.001, 0}));
}

}  // namespace
}  // namespace usina::core
