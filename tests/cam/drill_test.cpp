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

TEST(Drill, FeaturesFormIsBareHolesThatCarryTheirFeed) {
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
  // No feed down to R to set the rate (it cost a bore 26 s at its feed):
  // each hole carries it, and the cycle goes to R at rapid.
  EXPECT_TRUE(ops_of<canon::Feed>(tp).empty());
  for (const canon::Hole& h : holes)
    EXPECT_EQ(h.f, o.cut.plunge_feed);
  // At the safe Z over the first hole: the cycle's clear level.
  const auto t = ops_of<canon::Traverse>(tp);
  EXPECT_EQ(t.back().to, (Vec3{20, 0, 10}));
}

TEST(Drill, ABoresCycleAndDwellAreChecked) {
  const auto refused = [](const DrillOptions& o, const std::string& words) {
    canon::Toolpath tp;
    core::DiagnosticList d;
    EXPECT_FALSE(generate_drill({{0, 0}}, o, tp, d));
    ASSERT_EQ(count_code(d, core::Code::GenBadValue), 1) << words;
    EXPECT_NE(d.all()[0].message.find(words), std::string::npos) << d.all()[0].message;
    EXPECT_EQ(tp.size(), 0u);
  };
  DrillOptions o = options();
  o.bore = true;
  o.bore_cycle = canon::HoleCycle::Drill;
  refused(o, "not G81");
  o.bore_cycle = canon::HoleCycle::Bore;
  o.dwell = 0.5;
  refused(o, "only a G89 bore dwells");
  o.bore_cycle = canon::HoleCycle::BoreDwell;
  for (const double bad : {0.0, -0.5, 61.0}) {
    o.dwell = bad;
    refused(o, "dwell");
  }
}

// As moves: G89 dwells at the bottom before the feed out; G86 stops the
// spindle, rapids out and starts it again.
TEST(Drill, BoreCyclesAsMoves) {
  DrillOptions o = options();
  o.bore = true;
  o.bore_cycle = canon::HoleCycle::BoreDwell;
  o.dwell = 0.5;
  canon::Toolpath tp;
  core::DiagnosticList d;
  ASSERT_TRUE(generate_drill({{0, 0}}, o, tp, d));
  const auto dwells = ops_of<canon::Dwell>(tp);
  ASSERT_EQ(dwells.size(), 1u);
  EXPECT_EQ(dwells[0].s, 0.5);
  EXPECT_EQ(ops_of<canon::Hole>(tp)[0].dwell, 0.5);
  const auto feeds = ops_of<canon::Feed>(tp);
  ASSERT_EQ(feeds.size(), 2u);
  EXPECT_EQ(feeds[1].to.z, 2);  // fed out to R
  o.bore_cycle = canon::HoleCycle::BoreStop;
  o.dwell = 0;
  canon::Toolpath stop;
  ASSERT_TRUE(generate_drill({{0, 0}}, o, stop, d));
  EXPECT_EQ(ops_of<canon::Feed>(stop).size(), 1u);  // in; out at rapid
  std::vector<canon::SpindleDir> dirs;
  for (const canon::Spindle& s : ops_of<canon::Spindle>(stop))
    dirs.push_back(s.dir);
  // Started, stopped at the bottom, started again, stopped at the end.
  EXPECT_EQ(dirs, (std::vector<canon::SpindleDir>{canon::SpindleDir::Cw, canon::SpindleDir::Off,
                                                  canon::SpindleDir::Cw, canon::SpindleDir::Off}));
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
