// The DDA ellipse of seed 002 (figure 2, equations 1-3).
#include "cam/ellipse_dda.hpp"

#include <cstdio>

#include <gtest/gtest.h>

#include "ellipse_geometry.hpp"

namespace usina::cam {
namespace {

TEST(EllipseDda, QuadrantRunsClockwiseFromTheTopToTheRight) {
  const auto q = dda_quadrant(30, 20, 0.5);
  ASSERT_GE(q.size(), 2u);
  EXPECT_EQ(q.front().x, 0.0);
  EXPECT_EQ(q.front().y, 20.0);
  EXPECT_EQ(q.back().x, 30.0);
  EXPECT_EQ(q.back().y, 0.0);
  const double inc = dda_increment(30, 20, 0.5);
  for (std::size_t i = 1; i < q.size(); ++i) {
    const double dx = q[i].x - q[i - 1].x;
    const double dy = q[i - 1].y - q[i].y;
    EXPECT_GE(dx, 0.0);
    EXPECT_GE(dy, 0.0);
    // One increment per axis per clock: X scaled by Rx/Ry (equation 1).
    EXPECT_LE(dx, inc * 30 / 20 + 1e-12);
    EXPECT_LE(dy, inc + 1e-12);
    EXPECT_GT(dx + dy, 0.0);
  }
}

TEST(EllipseDda, IncrementIsTheResolutionOrFinerSoBothAxesStepWithinIt) {
  EXPECT_DOUBLE_EQ(dda_increment(20, 20, 0.5), 0.5);
  EXPECT_DOUBLE_EQ(dda_increment(20, 20, 0.3), 20.0 / 67);  // divides the radius
  EXPECT_LE(dda_increment(40, 20, 0.5) * 40 / 20, 0.5);     // X steps within it
}

TEST(EllipseDda, WholeEllipseIsClosedCounterClockwiseAndSymmetric) {
  const auto e = dda_ellipse(30, 20, 0.25);
  const auto q = dda_quadrant(30, 20, 0.25);
  ASSERT_EQ(e.size(), 4 * (q.size() - 1) + 1);
  EXPECT_EQ(e.front().x, e.back().x);
  EXPECT_EQ(e.front().y, e.back().y);
  double area2 = 0;
  for (std::size_t i = 1; i < e.size(); ++i)
    area2 += core::cross(e[i - 1], e[i]);
  EXPECT_GT(area2, 0);  // counter-clockwise
  EXPECT_NEAR(area2 / 2, std::numbers::pi * 30 * 20, 0.02 * std::numbers::pi * 30 * 20);
  // The seed's order: the left half first, through (−rx, 0) and (0, −ry).
  const std::size_t m = q.size() - 1;
  EXPECT_DOUBLE_EQ(e[m].x, -30);
  EXPECT_DOUBLE_EQ(e[2 * m].y, -20);
  EXPECT_DOUBLE_EQ(e[3 * m].x, 30);
  for (std::size_t i = 0; i <= m; ++i) {  // mirror images (equations 2 and 3)
    EXPECT_DOUBLE_EQ(e[i].x, -e[4 * m - i].x);
    EXPECT_DOUBLE_EQ(e[i].y, e[4 * m - i].y);
  }
}

// Seed 004 figure 7.5: the deviation of the polyline from the curve, outside
// it (the points) and inside it (the chords' midpoints), for resolutions a
// decade apart. It shrinks with the resolution; all of it is outside (figure
// 7.5 b): the accumulators start at 0 and truncate, and the integration
// spirals outward, so the points drift out by up to about 1.8 increments.
struct Deviation {
  double outside = 0;
  double inside = 0;
};

Deviation deviation(double rx, double ry, double res) {
  const auto q = dda_quadrant(rx, ry, res);
  Deviation d;
  auto note = [&](Vec2 p) {
    const double dist = test::ellipse_distance(p, rx, ry);
    double& side = test::inside_ellipse(p, rx, ry) ? d.inside : d.outside;
    side = std::max(side, dist);
  };
  for (std::size_t i = 0; i < q.size(); ++i) {
    note(q[i]);
    if (i > 0) note((q[i] + q[i - 1]) * 0.5);
  }
  return d;
}

TEST(EllipseDda, ChordalErrorFollowsTheResolution) {
  double previous = 0;
  for (const double res : {1.0, 0.1, 0.01}) {
    const Deviation d = deviation(30, 20, res);
    std::printf("resolution %-5g  outside %.5f  inside %.5f  (mm)\n", res, d.outside, d.inside);
    EXPECT_LE(d.outside, 2 * res);
    EXPECT_LE(d.inside, 0.01 * res);
    const double worst = std::max(d.outside, d.inside);
    if (previous > 0) {
      EXPECT_LT(worst, previous / 5);  // about linear in the resolution
    }
    previous = worst;
  }
}

}  // namespace
}  // namespace usina::cam
