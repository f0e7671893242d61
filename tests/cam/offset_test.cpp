#include "cam/offset.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "cam/pocket.hpp"

namespace usina::cam {
namespace {

// Distance from p to the segment a-b.
double to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 e = b - a;
  const double t = std::clamp(core::dot(p - a, e) / core::dot(e, e), 0.0, 1.0);
  return core::distance(p, a + e * t);
}

double to_polyline(Vec2 p, const std::vector<Vec2>& pts) {
  double best = 1e300;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i)
    best = std::min(best, to_segment(p, pts[i], pts[i + 1]));
  return best;
}

TEST(Offset, OutsideOfASquareIsATheToolRadiusAway) {
  const Path square = rectangle({0, 0}, 20, 20, 0);  // counter-clockwise
  const auto out = offset_closed(square, 3.0, /*left=*/false, 0.001);
  ASSERT_EQ(out.size(), 1u);
  const auto src = linearize(square, 0.001);
  for (const Vec2& p : linearize(out[0], 0.001))
    EXPECT_NEAR(to_polyline(p, src), 3.0, 2e-3);
  EXPECT_GT(signed_area2(linearize(out[0], 0.001)), 0.0);              // kept counter-clockwise
  EXPECT_NEAR(core::distance(out[0].start, square.start), 3.0, 1e-3);  // starts near the start
}

TEST(Offset, InsideOfACircleIsASmallerCircle) {
  const Path c = circle({5, 5}, 10);
  const auto in = offset_closed(c, 2.0, /*left=*/true, 0.001);
  ASSERT_EQ(in.size(), 1u);
  for (const Vec2& p : linearize(in[0], 0.001))
    EXPECT_NEAR(core::distance(p, {5, 5}), 8.0, 2e-3);
}

TEST(Offset, TooSmallForTheToolVanishes) {
  EXPECT_TRUE(offset_closed(circle({0, 0}, 2), 2.5, true, 0.001).empty());
}

TEST(Offset, OpenPathOneSide) {
  // An L: (0,0) -> (20,0) -> (20,20). Its left side is inside the corner.
  const Path l{{0, 0}, {{{20, 0}, std::nullopt, 0}, {{20, 20}, std::nullopt, 0}}, false};
  const auto left = offset_open(l, 2.0, true, 0.001);
  ASSERT_TRUE(left);
  const auto src = linearize(l, 0.001);
  const auto pts = linearize(*left, 0.001);
  EXPECT_NEAR(pts.front().x, 0, 1e-3);
  EXPECT_NEAR(pts.front().y, 2, 1e-3);
  EXPECT_NEAR(pts.back().x, 18, 1e-3);
  EXPECT_NEAR(pts.back().y, 20, 1e-3);
  for (const Vec2& p : pts)
    EXPECT_NEAR(to_polyline(p, src), 2.0, 2e-3);
  const auto right = offset_open(l, 2.0, false, 0.001);
  ASSERT_TRUE(right);
  const auto rpts = linearize(*right, 0.001);
  EXPECT_NEAR(rpts.front().y, -2, 1e-3);
  for (const Vec2& p : rpts)
    EXPECT_NEAR(to_polyline(p, src), 2.0, 2e-3);
  // The outer corner is rounded: a point at 45° from the corner, 2 mm away.
  double best = 1e9;
  for (const Vec2& p : rpts)
    best = std::min(best, core::distance(p, {20 + std::sqrt(2.0), -std::sqrt(2.0)}));
  EXPECT_LT(best, 0.07);  // the corner's chords are within 0.001 mm of the arc
}

TEST(Offset, InsideTestFollowsEvenOdd) {
  const Ring square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  EXPECT_TRUE(inside(square, {5, 5}));
  EXPECT_FALSE(inside(square, {15, 5}));
  EXPECT_FALSE(inside({}, {0, 0}));
}

}  // namespace
}  // namespace usina::cam
