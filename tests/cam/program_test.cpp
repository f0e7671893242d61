#include "cam/program.hpp"

#include <gtest/gtest.h>

#include "cam_test_util.hpp"

namespace usina::cam {
namespace {

TEST(DepthLevels, EqualStepsEndingAtTheDepth) {
  const auto z = depth_levels(5.0, 2.0);  // 3 passes of 5/3, not 2 + 2 + 1
  ASSERT_EQ(z.size(), 3u);
  EXPECT_DOUBLE_EQ(z[0], -5.0 / 3);
  EXPECT_DOUBLE_EQ(z[1], -10.0 / 3);
  EXPECT_EQ(z[2], -5.0);
}

TEST(DepthLevels, AStepThatDividesTheDepthIsKept) {
  const auto z = depth_levels(6.0, 2.0);
  ASSERT_EQ(z.size(), 3u);
  EXPECT_DOUBLE_EQ(z[0], -2.0);
  EXPECT_EQ(z[2], -6.0);
  EXPECT_EQ(depth_levels(1.0, 3.0), std::vector<double>{-1.0});
}

TEST(CheckCutting, EveryBadValueIsReported) {
  core::DiagnosticList d;
  Cutting c;
  c.tool_diameter = 0;
  c.feed = -1;
  c.plunge_feed = std::nan("");
  c.rpm = 0;
  c.safe_z = -5;
  c.tool = -1;
  EXPECT_FALSE(check_cutting(c, d));
  EXPECT_EQ(testing::count_code(d, core::Code::GenBadValue), 6);
  EXPECT_NE(d.all()[1].message.find("the feed (--feed) is -1 mm/min"), std::string::npos);
}

TEST(ProgramWriter, RapidsOverAtTheSafeZAndRetractsBeforeMovingOn) {
  canon::Toolpath tp;
  Cutting c;
  c.safe_z = 7;
  ProgramWriter w(tp, c);
  w.begin("t");
  w.rapid_over({1, 2});
  w.plunge(-1);
  w.feed({5, 2, -1});
  w.rapid_over({9, 9});
  w.end();
  const auto t = testing::ops_of<canon::Traverse>(tp);
  ASSERT_EQ(t.size(), 3u);  // end() adds none: the tool is at the safe Z already
  EXPECT_EQ(t[0].to, (Vec3{1, 2, 7}));
  EXPECT_EQ(t[1].to, (Vec3{5, 2, 7}));  // straight up first
  EXPECT_EQ(t[2].to, (Vec3{9, 9, 7}));
  EXPECT_EQ(testing::ops_of<canon::ToolChange>(tp)[0].diameter, 6.0);
  EXPECT_EQ(testing::ops_of<canon::ProgramEnd>(tp).size(), 1u);
  const auto f = testing::ops_of<canon::Feed>(tp);
  EXPECT_EQ(f[0].f, 200.0);  // the plunge at the plunge feed
  EXPECT_EQ(f[1].f, 600.0);
}

}  // namespace
}  // namespace usina::cam
