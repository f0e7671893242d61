#include "cam/drill.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cam_test_util.hpp"

namespace usina::cam {
namespace {

using testing::count_code;
using testing::ops_of;

TEST(BoltCircle, EqualAnglesFromTheStartAngle) {
  const auto pts = bolt_circle({10, 20}, 30, 6, 15);
  ASSERT_EQ(pts.size(), 6u);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Vec2 v = pts[i] - Vec2{10, 20};
    EXPECT_NEAR(core::norm(v), 30, 1e-12);
    const double deg = std::atan2(v.y, v.x) * 180 / std::numbers::pi;
    EXPECT_NEAR(std::remainder(deg - (15 + 60.0 * static_cast<double>(i)), 360.0), 0.0, 1e-9);
  }
}

TEST(Grid, RowByRowEveryOtherRowBack) {
  const auto pts = grid({0, 0}, 3, 2, 10, 5);
  const std::vector<Vec2> expect{{0, 0}, {10, 0}, {20, 0}, {20, 5}, {10, 5}, {0, 5}};
  EXPECT_EQ(pts, expect);
}

DrillOptions options() {
  DrillOptions o;
  o.cut.tool_diameter = 8.5;
  o.cut.safe_z = 10;
  o.depth = 12;
  o.retract = 2;
  return o;
}

TEST(Drill, HoleFeatureThenTheG81MovesAsCycle) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  ASSERT_TRUE(generate_drill({{5, 5}, {25, 5}}, options(), tp, d));
  const auto holes = ops_of<canon::Hole>(tp);
  ASSERT_EQ(holes.size(), 2u);
  // As the interpreter's G81: the Hole at the R plane, depth from R to the bottom.
  EXPECT_EQ(holes[1].at, (Vec3{25, 5, 2}));
  EXPECT_EQ(holes[1].depth, 14.0);
  EXPECT_EQ(holes[1].diameter, 8.5);
  // The second hole's ops: over at the clear level, down to R, Hole, feed to
  // the bottom, out to the clear level (G98).
  std::vector<std::string> seq;
  bool second = false;
  for (const canon::Op& op : tp.ops()) {
    if (const auto* t = std::get_if<canon::Traverse>(&op.kind); t && t->to.x == 25) second = true;
    if (!second || op.origin != canon::Origin::Cycle) continue;
    const auto e = testing::end_of(op);
    seq.push_back(fmt::format("{} {:g}", canon::op_name(op.kind), e ? e->z : 0.0));
  }
  const std::vector<std::string> expect{"traverse 10", "traverse 2", "hole 0", "feed -12",
                                        "traverse 10"};
  EXPECT_EQ(seq, expect);
}

TEST(Drill, PecksAsG83OutToRAndBackToTheClearance) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  DrillOptions o = options();
  o.peck = 5;
  ASSERT_TRUE(generate_drill({{0, 0}}, o, tp, d));
  std::vector<double> zs;
  for (const canon::Op& op : tp.ops()) {
    if (op.origin != canon::Origin::Cycle) continue;
    if (const auto e = testing::end_of(op)) zs.push_back(e->z);
  }
  // R 2, pecks to -3 and -8, then the bottom -12; back to R and down to 1 mm
  // above the last peck between them.
  const std::vector<double> expect{10, 2, -3, 2, -2, -8, 2, -7, -12, 10};
  EXPECT_EQ(zs, expect);
}

TEST(Drill, FeaturesFormIsBareHolesAfterAFeedThatSetsTheRate) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  DrillOptions o = options();
  o.form = HoleForm::Features;
  ASSERT_TRUE(generate_drill(bolt_circle({0, 0}, 20, 4, 0), o, tp, d));
  const auto holes = ops_of<canon::Hole>(tp);
  ASSERT_EQ(holes.size(), 4u);
  EXPECT_NEAR(holes[1].at.y, 20, 1e-12);
  for (const canon::Op& op : tp.ops())
    EXPECT_EQ(op.origin, canon::Origin::Program);
  const auto feeds = ops_of<canon::Feed>(tp);
  ASSERT_EQ(feeds.size(), 1u);
  EXPECT_EQ(feeds[0].to, (Vec3{20, 0, 2}));
  EXPECT_EQ(feeds[0].f, o.cut.plunge_feed);
  // Back at the safe Z before the first hole: the cycle's clear level.
  const auto t = ops_of<canon::Traverse>(tp);
  EXPECT_EQ(t[1].to, (Vec3{20, 0, 10}));
}

TEST(Drill, ErrorsNothingEmitted) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  EXPECT_FALSE(generate_drill({}, options(), tp, d));
  DrillOptions o = options();
  o.retract = 11;  // above the safe Z
  EXPECT_FALSE(generate_drill({{0, 0}}, o, tp, d));
  o = options();
  o.peck = -1;
  EXPECT_FALSE(generate_drill({{0, 0}}, o, tp, d));
  o = options();
  o.peck = 1e-6;
  EXPECT_FALSE(generate_drill({{0, 0}}, o, tp, d));
  EXPECT_FALSE(generate_drill({{0, std::nan("")}}, options(), tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenBadValue), 5);
  EXPECT_EQ(tp.size(), 0u);
}

TEST(Drill, TappingFeedsThePitchAndReversesAtTheBottom) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  DrillOptions o = options();
  o.cut.rpm = 300;
  o.cut.feed = 999;  // not read: a tap feeds its pitch a revolution
  o.pitch = 1.25;
  ASSERT_TRUE(generate_drill({{0, 0}}, o, tp, d)) << (d.all().empty() ? "" : d.all()[0].message);
  std::vector<std::string> seq;
  for (const canon::Op& op : tp.ops()) {
    if (op.origin != canon::Origin::Cycle) continue;
    if (const auto* s = std::get_if<canon::Spindle>(&op.kind)) {
      seq.push_back(s->dir == canon::SpindleDir::Ccw ? "ccw" : "cw");
    } else if (const auto* f = std::get_if<canon::Feed>(&op.kind)) {
      EXPECT_DOUBLE_EQ(*f->f, 375.0);  // 1.25 mm x 300 rev/min
      seq.push_back(fmt::format("feed {:g}", f->to.z));
    }
  }
  const std::vector<std::string> expect{"feed -12", "ccw", "feed 2", "cw"};
  EXPECT_EQ(seq, expect);
}

TEST(Drill, ATapIsNotPecked) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  DrillOptions o = options();
  o.pitch = 1.25;
  o.peck = 3;
  EXPECT_FALSE(generate_drill({{0, 0}}, o, tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenBadValue), 1);
  EXPECT_TRUE(tp.ops().empty());
}

}  // namespace
}  // namespace usina::cam
