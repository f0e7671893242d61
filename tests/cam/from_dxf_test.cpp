#include "cam/from_dxf.hpp"

#include <unistd.h>

#include <cstdio>
#include <fstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cam/chain.hpp"
#include "cam/dxf_import.hpp"
#include "cam_test_util.hpp"

namespace usina::cam {
namespace {

using testing::count_code;
using testing::ops_of;

std::vector<Path> slot() {
  core::DiagnosticList d;
  DxfOptions o;
  o.layer = "SLOT";
  auto e = read_dxf(std::string(USINA_TEST_DIR) + "/programs/dxf/arcs_bulges.dxf", o, d);
  return chain(*e);
}

TEST(FromDxf, RapidPlungeThePathWithItsArcsRetract) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  FromDxfOptions o;
  o.depth = 1.5;
  ASSERT_TRUE(generate_from_paths(slot(), o, tp, d));
  const auto arcs = ops_of<canon::Arc>(tp);
  ASSERT_EQ(arcs.size(), 2u);  // the bulges as arcs, not chords
  EXPECT_EQ(arcs[0].center, (Vec3{20, 5, -1.5}));
  EXPECT_EQ(arcs[0].to, (Vec3{20, 10, -1.5}));
  EXPECT_EQ(arcs[0].turn, 1);
  EXPECT_NEAR(arcs[1].center.x, 0, 1e-12);  // 1/tan(π/2) is 6e-17, not 0
  EXPECT_EQ(arcs[1].center.y, 5);
  const auto feeds = ops_of<canon::Feed>(tp);
  ASSERT_EQ(feeds.size(), 3u);
  EXPECT_EQ(feeds[0].to, (Vec3{0, 0, -1.5}));  // the plunge
  EXPECT_EQ(feeds[0].f, o.cut.plunge_feed);
  const auto t = ops_of<canon::Traverse>(tp);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0].to, (Vec3{0, 0, 5}));
  EXPECT_EQ(t[1].to, (Vec3{0, 0, 5}));  // the retract at the end
}

TEST(FromDxf, LeftOfTheCounterClockwiseSlotIsInsideByTheToolRadius) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  FromDxfOptions o;
  o.cut.tool_diameter = 4;
  o.side = Side::Left;
  ASSERT_TRUE(generate_from_paths(slot(), o, tp, d));
  EXPECT_TRUE(ops_of<canon::Arc>(tp).empty());  // an offset is a polyline
  int checked = 0;
  for (const auto& f : ops_of<canon::Feed>(tp)) {
    // Distance to the slot's spine (0,5)-(20,5) is 5 on the slot: 3 inside.
    const double x = std::clamp(f.to.x, 0.0, 20.0);
    EXPECT_NEAR(std::hypot(f.to.x - x, f.to.y - 5), 3.0, 2e-3);
    ++checked;
  }
  EXPECT_GT(checked, 20);
}

TEST(FromDxf, ToolTooBigForAClosedContourIsAnError) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  FromDxfOptions o;
  o.cut.tool_diameter = 12;  // the slot is 10 wide
  o.side = Side::Left;
  EXPECT_FALSE(generate_from_paths(slot(), o, tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenToolTooBig), 1);
  EXPECT_EQ(tp.size(), 0u);
}

TEST(FromDxf, BadDepthIsAnError) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  FromDxfOptions o;
  o.depth = -1;
  EXPECT_FALSE(generate_from_paths(slot(), o, tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenBadValue), 1);
}

// A sketch of `n` LINEs, as seed 002's free-form sketch makes them: a
// zig-zag 0.5 mm a step, every third line drawn backwards.
std::string sketch_dxf(int n) {
  std::string s = "0\nSECTION\n2\nENTITIES\n";
  for (int i = 0; i < n; ++i) {
    double x1 = i * 0.5, y1 = (i % 2) * 0.5, x2 = (i + 1) * 0.5, y2 = ((i + 1) % 2) * 0.5;
    if (i % 3 == 2) std::swap(x1, x2), std::swap(y1, y2);
    s += fmt::format("0\nLINE\n8\nSKETCH\n10\n{}\n20\n{}\n30\n0\n11\n{}\n21\n{}\n31\n0\n", x1, y1,
                     x2, y2);
  }
  return s + "0\nENDSEC\n0\nEOF\n";
}

TEST(FromDxf, TenThousandEntityDrawingIsOneSketchPath) {
  const std::string file =
      ::testing::TempDir() + "usina_sketch_10000_" + std::to_string(::getpid()) + ".dxf";
  std::ofstream(file) << sketch_dxf(10000);
  core::DiagnosticList d;
  const auto entities = read_dxf(file, {}, d);
  std::remove(file.c_str());
  ASSERT_TRUE(entities);
  ASSERT_EQ(entities->size(), 10000u);
  canon::Toolpath tp;
  ASSERT_TRUE(generate_from_paths(chain(*entities), {}, tp, d));
  const auto feeds = ops_of<canon::Feed>(tp);
  ASSERT_EQ(feeds.size(), 10001u);  // the plunge and one feed a line
  for (std::size_t i = 1; i < feeds.size(); ++i) {
    EXPECT_EQ(feeds[i].to.x, static_cast<double>(i) * 0.5);
  }
  EXPECT_EQ(ops_of<canon::Traverse>(tp).size(), 2u);
}

}  // namespace
}  // namespace usina::cam
