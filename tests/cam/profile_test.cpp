#include "cam/profile.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "cam/pocket.hpp"
#include "cam_test_util.hpp"

namespace usina::cam {
namespace {

using testing::count_code;
using testing::end_of;
using testing::ops_of;

ProfileOptions options() {
  ProfileOptions o;
  o.cut.tool_diameter = 6;
  o.depth = 6;
  o.step_down = 2;
  return o;
}

TEST(ProfilePaths, OutsideIsClockwiseAToolRadiusOut) {
  ProfileOptions o = options();
  o.side = ProfileSide::Outside;
  const auto paths = profile_paths(circle({0, 0}, 10), o);
  ASSERT_EQ(paths.size(), 1u);
  const auto pts = linearize(paths[0], 0.001);
  EXPECT_LT(signed_area2(pts), 0.0);  // climb milling outside: clockwise
  for (const Vec2& p : pts)
    EXPECT_NEAR(core::norm(p), 13.0, 2e-3);
}

TEST(ProfilePaths, InsideIsCounterClockwiseAToolRadiusIn) {
  ProfileOptions o = options();
  o.side = ProfileSide::Inside;
  const Path cw = reversed(circle({0, 0}, 10));  // drawn clockwise: the direction is ours
  const auto paths = profile_paths(cw, o);
  ASSERT_EQ(paths.size(), 1u);
  const auto pts = linearize(paths[0], 0.001);
  EXPECT_GT(signed_area2(pts), 0.0);
  for (const Vec2& p : pts)
    EXPECT_NEAR(core::norm(p), 7.0, 2e-3);
}

TEST(ProfilePaths, AGivenOffsetReplacesTheToolRadius) {
  // A chamfer mill's cone meets the edge nearer its axis than its diameter.
  ProfileOptions o = options();
  o.offset = 0.5;
  const auto outside = profile_paths(circle({0, 0}, 10), o);
  ASSERT_EQ(outside.size(), 1u);
  for (const Vec2& p : linearize(outside[0], 0.001))
    EXPECT_NEAR(core::norm(p), 10.5, 2e-3);
  o.side = ProfileSide::Inside;
  const auto inside = profile_paths(circle({0, 0}, 10), o);
  ASSERT_EQ(inside.size(), 1u);
  for (const Vec2& p : linearize(inside[0], 0.001))
    EXPECT_NEAR(core::norm(p), 9.5, 2e-3);
}

TEST(ProfilePaths, AZeroOffsetRunsOnTheContourInTheSidesDirection) {
  ProfileOptions o = options();
  o.offset = 0.0;
  o.side = ProfileSide::Outside;
  const auto paths = profile_paths(circle({0, 0}, 10), o);  // drawn counter-clockwise
  ASSERT_EQ(paths.size(), 1u);
  const auto pts = linearize(paths[0], 0.001);
  EXPECT_LT(signed_area2(pts), 0.0);  // climb milling outside: clockwise still
  for (const Vec2& p : pts)
    EXPECT_NEAR(core::norm(p), 10.0, 2e-3);
  o.side = ProfileSide::Left;
  const Path open{{0, 0}, {{{10, 0}, std::nullopt, 1}}, false};
  const auto left = profile_paths(open, o);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(end_point(left[0]), (Vec2{10, 0}));
}

TEST(Profile, DepthPassesEqualAndEndingAtTheDepth) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  ProfileOptions o = options();
  o.depth = 5;
  ASSERT_TRUE(generate_profile({rectangle({0, 0}, 40, 20, 0)}, o, tp, d));
  std::vector<double> zs;
  for (const canon::Op& op : tp.ops()) {
    if (const auto* f = std::get_if<canon::Feed>(&op.kind); f && f->to.z < 0) {
      if (zs.empty() || zs.back() != f->to.z) zs.push_back(f->to.z);
    }
  }
  ASSERT_EQ(zs.size(), 3u);
  EXPECT_DOUBLE_EQ(zs[1] - zs[0], zs[2] - zs[1]);
  EXPECT_EQ(zs[2], -5.0);
}

TEST(Profile, LeadArcsAreTangentQuarterCirclesOnTheFreeSide) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  ProfileOptions o = options();
  o.depth = 2;
  o.lead_radius = 4;
  o.side = ProfileSide::Outside;
  ASSERT_TRUE(generate_profile({circle({0, 0}, 10)}, o, tp, d));
  const auto arcs = ops_of<canon::Arc>(tp);
  ASSERT_EQ(arcs.size(), 2u);  // the offset circle is a polyline; lead in and lead out
  const auto traverses = ops_of<canon::Traverse>(tp);
  const Vec3 plunge_at = traverses[0].to;
  // The lead-in starts outside the tool path (radius 13), away from the part.
  EXPECT_GT(std::hypot(plunge_at.x, plunge_at.y), 13.0 + 1.0);
  for (const canon::Arc& a : arcs) {
    EXPECT_NEAR(core::distance(Vec3{a.to.x, a.to.y, 0}, Vec3{a.center.x, a.center.y, 0}), 4.0,
                1e-9);
    EXPECT_EQ(a.turn, 1);  // left of the clockwise path: counter-clockwise arcs
  }
  // The lead-in ends on the tool path, its centre 4 mm further out: tangent.
  const Vec2 end{arcs[0].to.x, arcs[0].to.y};
  const Vec2 center{arcs[0].center.x, arcs[0].center.y};
  EXPECT_NEAR(core::norm(end), 13.0, 2e-3);
  EXPECT_NEAR(core::norm(center), 17.0, 2e-2);
}

TEST(Profile, TabsLeaveTheirHeightOnTheLastPassesOnly) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  ProfileOptions o = options();
  o.side = ProfileSide::On;  // the tool centre on the square itself: easy lengths
  o.depth = 6;
  o.step_down = 2;
  o.tabs = {4, 3.0, 2.5};  // tab top at -3.5: below it only the passes at -4 and -6
  ASSERT_TRUE(generate_profile({rectangle({0, 0}, 40, 40, 0)}, o, tp, d)) << d.all()[0].message;
  int tab_moves = 0;
  for (const auto& f : ops_of<canon::Feed>(tp)) {
    if (f.to.z == -3.5) ++tab_moves;
    EXPECT_TRUE(f.to.z >= 0 || f.to.z == -2 || f.to.z == -3.5 || f.to.z == -4 || f.to.z == -6)
        << f.to.z;
  }
  EXPECT_GT(tab_moves, 0);
  // The tabs of the last pass: centred at 20, 60, 100, 140 mm along the
  // square from its start (0, -20), each lifted over 3 + 6 = 9 mm.
  std::vector<Vec2> lifted;
  bool last = false;
  for (const canon::Op& op : tp.ops()) {
    const auto e = end_of(op);
    if (!e) continue;
    if (e->z == -6) last = true;
    if (last && e->z == -3.5) lifted.push_back({e->x, e->y});
  }
  // Each tab spans a corner of the square: up at its start (a vertical feed),
  // along to the corner, along to its end.
  ASSERT_EQ(lifted.size(), 12u);
  EXPECT_EQ(lifted[0], (Vec2{20 - 4.5, -20}));
  EXPECT_EQ(lifted[1], (Vec2{20, -20}));
  EXPECT_NEAR(lifted[2].x, 20, 1e-9);
  EXPECT_NEAR(lifted[2].y, -20 + 4.5, 1e-9);
}

TEST(Profile, TabsThatDoNotFitAreAnError) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  ProfileOptions o = options();
  o.side = ProfileSide::On;
  o.tabs = {20, 3.0, 1.0};  // 20 × 9 mm of lift on a 160 mm path
  EXPECT_FALSE(generate_profile({rectangle({0, 0}, 40, 40, 0)}, o, tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenBadValue), 1);
}

TEST(Profile, TooManyTabsOrPassesAreErrors) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  ProfileOptions o = options();
  o.tabs = {20000, 0.001, 1.0};
  EXPECT_FALSE(generate_profile({circle({0, 0}, 1e4)}, o, tp, d));
  o = options();
  o.step_down = 1e-9;
  EXPECT_FALSE(generate_profile({circle({0, 0}, 20)}, o, tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenBadValue), 2);
}

TEST(Profile, TabAsHighAsTheDepthIsAnError) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  ProfileOptions o = options();
  o.tabs = {2, 3.0, 6.0};
  EXPECT_FALSE(generate_profile({circle({0, 0}, 20)}, o, tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenBadValue), 1);
}

TEST(Profile, OutsideOfAnOpenContourIsAnError) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  const Path open{{0, 0}, {{{10, 0}, std::nullopt, 0}}, false};
  EXPECT_FALSE(generate_profile({open}, options(), tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenOpenOutline), 1);
}

TEST(Profile, OpenContourOnItsRightWithLeadsOnTheRight) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  ProfileOptions o = options();
  o.side = ProfileSide::Right;
  o.lead_radius = 2;
  o.depth = 1;
  const Path open{{0, 0}, {{{30, 0}, std::nullopt, 0}}, false};
  ASSERT_TRUE(generate_profile({open}, o, tp, d));
  const auto arcs = ops_of<canon::Arc>(tp);
  ASSERT_EQ(arcs.size(), 2u);
  EXPECT_EQ(arcs[0].turn, -1);
  EXPECT_NEAR(arcs[0].to.y, -3, 1e-3);      // the path, a tool radius to the right
  EXPECT_NEAR(arcs[0].center.y, -5, 1e-3);  // the lead arc further right
}

TEST(Profile, InsideTooSmallForTheToolIsAnError) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  ProfileOptions o = options();
  o.side = ProfileSide::Inside;
  EXPECT_FALSE(generate_profile({circle({0, 0}, 2)}, o, tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenToolTooBig), 1);
  EXPECT_EQ(tp.size(), 0u);
}

TEST(ProfileNesting, DepthCountsTheContoursAround) {
  // An outline, a hole in it and a boss standing in the hole.
  const std::vector<Path> c{circle({50, 30}, 3), rectangle({50, 30}, 100, 60, 0),
                            circle({50, 30}, 10)};
  EXPECT_EQ(nesting_depths(c, 0.01), (std::vector<int>{2, 0, 1}));
}

TEST(Profile, AutoCutsTheHoleInsideFirstThenTheOutlineOutside) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  ProfileOptions o = options();
  o.side = ProfileSide::Auto;
  ASSERT_TRUE(generate_profile({rectangle({50, 30}, 100, 60, 0), circle({50, 30}, 10)}, o, tp, d));
  std::vector<Vec2> cut;  // every feed end below the top
  for (const canon::Op& op : tp.ops()) {
    const auto at = end_of(op);
    if (at && at->z < 0 && !std::holds_alternative<canon::Traverse>(op.kind)) {
      cut.push_back({at->x, at->y});
    }
  }
  ASSERT_FALSE(cut.empty());
  // The hole first: a tool radius (3) inside its wall of radius 10.
  EXPECT_NEAR(core::norm(cut.front() - Vec2{50, 30}), 7.0, 2e-3);
  // The outline last: a tool radius outside the 100 x 60 rectangle.
  const Vec2 last = cut.back();
  const double out = std::max({-last.x, last.x - 100, -last.y, last.y - 60});
  EXPECT_NEAR(out, 3.0, 2e-3);
}

TEST(Profile, AutoOnAnOpenContourIsAnError) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  ProfileOptions o = options();
  o.side = ProfileSide::Auto;
  const Path open{{0, 0}, {{{10, 0}, std::nullopt, 0}}, false};
  EXPECT_FALSE(generate_profile({open}, o, tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenOpenOutline), 1);
  EXPECT_EQ(tp.size(), 0u);
}

}  // namespace
}  // namespace usina::cam
