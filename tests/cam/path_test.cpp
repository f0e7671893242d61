#include "cam/path.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace usina::cam {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Bulge, OneIsACounterClockwiseHalfCircle) {
  const PathSegment s = bulge_segment({20, 0}, {20, 10}, 1.0);
  ASSERT_TRUE(s.center);
  EXPECT_NEAR(s.center->x, 20.0, 1e-12);
  EXPECT_NEAR(s.center->y, 5.0, 1e-12);
  EXPECT_EQ(s.turn, 1);
  EXPECT_NEAR(segment_sweep({20, 0}, s), kPi, 1e-12);
}

TEST(Bulge, NegativeTanOfAQuarterIsAClockwiseQuarterCircle) {
  // tan(-90°/4): the included angle is 90° clockwise.
  const PathSegment s = bulge_segment({80, 0}, {90, 10}, std::tan(-kPi / 8));
  ASSERT_TRUE(s.center);
  EXPECT_NEAR(s.center->x, 90.0, 1e-9);
  EXPECT_NEAR(s.center->y, 0.0, 1e-9);
  EXPECT_EQ(s.turn, -1);
  EXPECT_NEAR(segment_sweep({80, 0}, s), -kPi / 2, 1e-9);
}

TEST(Bulge, AboveOneIsMoreThanAHalfCircle) {
  // Bulge tan(270°/4): the centre is on the right of the chord, sweep 270°.
  const PathSegment s = bulge_segment({0, 0}, {10, 0}, std::tan(3 * kPi / 8));
  ASSERT_TRUE(s.center);
  EXPECT_NEAR(s.center->y, -5.0, 1e-9);
  EXPECT_NEAR(segment_sweep({0, 0}, s), 1.5 * kPi, 1e-9);
}

TEST(Bulge, ZeroIsAStraightSegment) {
  EXPECT_FALSE(bulge_segment({0, 0}, {10, 0}, 0.0).center);
}

TEST(Path, ReversedWalksBackAndTurnsArcsTheOtherWay) {
  const Path p{{0, 0}, {{{10, 0}, std::nullopt, 0}, {{15, 5}, Vec2{10, 5}, 1}}, false};
  const Path r = reversed(p);
  EXPECT_EQ(r.start, (Vec2{15, 5}));
  ASSERT_EQ(r.segs.size(), 2u);
  EXPECT_EQ(r.segs[0].to, (Vec2{10, 0}));
  EXPECT_EQ(r.segs[0].turn, -1);
  EXPECT_EQ(r.segs[1].to, (Vec2{0, 0}));
  EXPECT_NEAR(path_length(r), path_length(p), 1e-12);
  EXPECT_NEAR(path_length(p), 10 + 5 * kPi / 2, 1e-12);
}

TEST(Path, LinearizeKeepsChordsWithinTheTolerance) {
  const Vec2 c{0, 0};
  const Path p{{10, 0}, {{{10, 0}, c, 1}}, true};  // a full circle of radius 10
  const auto pts = linearize(p, 0.01);
  ASSERT_GT(pts.size(), 10u);
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const Vec2 mid = (pts[i] + pts[i + 1]) * 0.5;
    EXPECT_LE(10.0 - core::norm(mid), 0.01 + 1e-12);
    EXPECT_NEAR(core::norm(pts[i]), 10.0, 1e-9);
  }
  EXPECT_EQ(pts.back(), (Vec2{10, 0}));
  EXPECT_GT(signed_area2(pts), 0.0);
}

}  // namespace
}  // namespace usina::cam
