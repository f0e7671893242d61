// The elliptical pocket's passes (seed 002, section 3.2, equation 4) and
// the exact finishing offset.
#include "cam/ellipse_pocket.hpp"

#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "../post/round_trip.hpp"
#include "ellipse_geometry.hpp"

namespace usina::cam {
namespace {

EllipsePocket pocket() {
  EllipsePocket p;
  p.center = {50, 40};
  p.rx = 30;
  p.ry = 18;
  p.depth = 5;
  p.cut.tool_diameter = 8;
  p.ae = 3;
  p.ap = 2;
  p.ae_finish = 0.5;
  p.ap_finish = 0.5;
  p.resolution = 0.2;
  return p;
}

Vec2 local(const EllipsePocket& p, Vec2 q) {
  return q - p.center;
}

TEST(EllipsePocket, ZLevelsAreEqualStepsEndingAtTheDepth) {
  const EllipsePlan pl = plan(pocket());
  // 4.5 mm of roughing in steps of at most 2: three of 1.5, then the finish.
  ASSERT_EQ(pl.z_levels.size(), 4u);
  EXPECT_DOUBLE_EQ(pl.ap_used, 1.5);
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_NEAR(pl.z_levels[k], -1.5 * static_cast<double>(k + 1), 1e-12);
  EXPECT_EQ(pl.z_levels.back(), -5.0);
  EllipsePocket p = pocket();
  p.ap_finish = 0;
  p.ap = 2.5;
  const EllipsePlan two = plan(p);
  EXPECT_THAT(two.z_levels, testing::ElementsAre(-2.5, -5.0));
}

TEST(EllipsePocket, RoughingPassesAreEqualAndNoWiderThanAe) {
  // A circle: the seed's I = (R − d_finish)/d rounded up, R the tool centre's.
  EllipsePocket c = pocket();
  c.rx = c.ry = 20;
  const EllipsePlan pl = plan(c);
  EXPECT_EQ(pl.roughing_rings, 6);  // (20 − 4 − 0.5)/3 = 5.17
  EXPECT_DOUBLE_EQ(pl.ae_y, 15.5 / 6);
  EXPECT_EQ(pl.transition_rings, 0);  // the last similar ring is the offset
  const auto rs = rings(c, pl);
  ASSERT_EQ(rs.size(), 7u);
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_EQ(rs[k].kind, RingKind::Roughing);
    EXPECT_NEAR(local(c, rs[k].points.front()).y, pl.ae_y * static_cast<double>(k + 1), 1e-9);
    EXPECT_NEAR(local(c, rs[k].points.front()).x, 0, 1e-12);
  }
  EXPECT_EQ(rs.back().kind, RingKind::Finishing);
}

// The test pocket turned a quarter: Y is now the major axis.
EllipsePocket tall_pocket() {
  EllipsePocket p = pocket();
  std::swap(p.rx, p.ry);
  return p;
}

class EllipsePocketBoth : public testing::TestWithParam<bool> {
 protected:
  EllipsePocket subject() const { return GetParam() ? tall_pocket() : pocket(); }
};

INSTANTIATE_TEST_SUITE_P(WideAndTall, EllipsePocketBoth, testing::Bool());

TEST_P(EllipsePocketBoth, FinishingRingIsTheToolRadiusFromTheWall) {
  const EllipsePocket p = subject();
  const auto rs = rings(p, plan(p));
  ASSERT_EQ(rs.back().kind, RingKind::Finishing);
  double worst = 0;
  const auto& pts = rs.back().points;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Vec2 l = local(p, pts[i]);
    EXPECT_TRUE(test::inside_ellipse(l, p.rx, p.ry));
    worst = std::max(worst, std::abs(test::ellipse_distance(l, p.rx, p.ry) - 4.0));
    if (i == 0) continue;
    // The chord between two points: its middle is as close (figure 7.5 a).
    const Vec2 mid = local(p, (pts[i] + pts[i - 1]) * 0.5);
    worst = std::max(worst, std::abs(test::ellipse_distance(mid, p.rx, p.ry) - 4.0));
  }
  EXPECT_LE(worst, p.resolution);
  std::printf("finishing ring: worst |distance − r| %.5f mm at resolution %g\n", worst,
              p.resolution);
}

TEST_P(EllipsePocketBoth, EveryRoughingPointIsInsideWithTheFinishStock) {
  const EllipsePocket p = subject();
  const EllipsePlan pl = plan(p);
  EXPECT_GT(pl.transition_rings, 0);  // 30 × 18: similar rings leave the ends wide
  // Equal roughing rings at most ae apart along the major axis.
  EXPECT_LE(pl.ae_used, p.ae);
  EXPECT_NEAR(pl.ae_used * pl.roughing_rings, (1 - 4.5 / 18) * 30, 1e-9);
  const auto rs = rings(p, pl);
  double prev_y = 0;
  for (const Ring& r : rs) {
    // Each ring starts a step of at most ae further out along +Y.
    const double y = local(p, r.points.front()).y;
    EXPECT_GE(y, prev_y);  // transitions start together where the rings touch
    EXPECT_LE(y - prev_y, p.ae + 1e-9);
    prev_y = y;
    if (r.kind == RingKind::Finishing) continue;
    for (const Vec2& q : r.points) {
      const Vec2 l = local(p, q);
      ASSERT_TRUE(test::inside_ellipse(l, p.rx, p.ry));
      ASSERT_GE(test::ellipse_distance(l, p.rx, p.ry), 4.0 + 0.5 - 1e-6);
    }
  }
}

// No ridge is left: every point of a ring is within ae of the ring before
// it (the first ring: of the centre), so the tool's passes overlap.
TEST_P(EllipsePocketBoth, RingsAreNeverMoreThanAeApart) {
  const EllipsePocket p = subject();
  const auto rs = rings(p, plan(p));
  std::vector<Vec2> previous{p.center};
  for (const Ring& r : rs) {
    double widest = 0;
    for (const Vec2& q : r.points) {
      double nearest = 1e300;
      for (const Vec2& o : previous)
        nearest = std::min(nearest, core::distance(q, o));
      widest = std::max(widest, nearest);
    }
    EXPECT_LE(widest, p.ae + p.resolution);
    previous = r.points;
  }
}

TEST(EllipsePocket, ChecksTheInput) {
  auto message = [](auto change) {
    EllipsePocket p = pocket();
    change(p);
    core::DiagnosticList diags;
    EXPECT_FALSE(check(p, diags));
    return diags.all().empty() ? std::string() : diags.all().front().message;
  };
  core::DiagnosticList good;
  EXPECT_TRUE(check(pocket(), good));
  EXPECT_TRUE(good.all().empty());
  EXPECT_THAT(message([](EllipsePocket& p) { p.cut.tool_diameter = 36; }),
              testing::HasSubstr("not narrower than the minor axis"));
  EXPECT_THAT(message([](EllipsePocket& p) { p.ae = 9; }),
              testing::HasSubstr("bigger than the tool"));
  EXPECT_THAT(message([](EllipsePocket& p) { p.ae_finish = 9; }),
              testing::HasSubstr("bigger than the tool"));
  EXPECT_THAT(message([](EllipsePocket& p) { p.resolution = 18; }),
              testing::HasSubstr("not smaller than the radii"));
  EXPECT_THAT(message([](EllipsePocket& p) { p.depth = 0; }),
              testing::HasSubstr("the depth (--depth) is 0 mm; give a number above 0"));
  EXPECT_THAT(message([](EllipsePocket& p) { p.rx = -1; }), testing::HasSubstr("--rx"));
  EXPECT_THAT(message([](EllipsePocket& p) { p.ae_finish = -1; }),
              testing::HasSubstr("give a number from 0 to"));
  EXPECT_THAT(message([](EllipsePocket& p) { p.ap_finish = 5; }),
              testing::HasSubstr("not smaller than the depth"));
  // 30 × 18: the wall's radius of curvature at (±30, 0) is 18²/30 = 10.8.
  EXPECT_THAT(message([](EllipsePocket& p) { p.cut.tool_diameter = 22; }),
              testing::HasSubstr("radius of curvature"));
}

TEST(EllipsePocket, ProgramRoundTripsThroughTheRs274ngcPost) {
  EllipsePocket p = pocket();
  p.resolution = 0.5;
  canon::Toolpath path;
  generate(p, path);
  core::DiagnosticList diags;
  const std::string text = test::post_text(path.ops(), "rs274ngc", diags);
  EXPECT_FALSE(diags.has_errors());
  test::expect_same_path(path.ops(), test::interpret(text), 1e-4);
  // grbl's program is plain RS274 too (its M0 tool pause aside): same path
  // within its 3 decimals.
  const std::string grbl = test::post_text(path.ops(), "grbl", diags);
  test::expect_same_path(path.ops(), test::interpret(grbl), 1e-3);
}

TEST(EllipsePocket, ProgramPlungesAtTheCentreAndEndsAboveIt) {
  EllipsePocket p = pocket();
  p.resolution = 1;
  canon::Toolpath path;
  generate(p, path);
  const auto ends = test::motion_ends(path.ops(), 1e-9);
  ASSERT_GE(ends.size(), 3u);
  EXPECT_EQ(ends.front(), (core::Vec3{50, 40, 5}));
  EXPECT_EQ(ends[1], (core::Vec3{50, 40, -1.5}));
  EXPECT_EQ(ends.back(), (core::Vec3{50, 40, 5}));
  for (const core::Vec3& e : ends)
    EXPECT_GE(e.z, -5.0);
}

}  // namespace
}  // namespace usina::cam
