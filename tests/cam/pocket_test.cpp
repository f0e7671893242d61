#include "cam/pocket.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "cam_test_util.hpp"

namespace usina::cam {
namespace {

using testing::count_code;
using testing::end_of;
using testing::ops_of;

double to_ring_edges(Vec2 p, const Ring& r) {
  double best = 1e300;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Vec2 a = r[i];
    const Vec2 e = r[(i + 1) % r.size()] - a;
    const double t = std::clamp(core::dot(p - a, e) / core::dot(e, e), 0.0, 1.0);
    best = std::min(best, core::distance(p, a + e * t));
  }
  return best;
}

PocketOptions options() {
  PocketOptions o;
  o.cut.tool_diameter = 6;
  o.depth = 5;
  o.step_down = 2;
  o.stepover = 2.5;
  o.finish_allowance = 0.2;
  return o;
}

TEST(Rectangle, CornerRadiusArcsAndPerimeter) {
  const Path p = rectangle({10, 5}, 40, 20, 4);
  EXPECT_TRUE(p.closed);
  EXPECT_EQ(p.start, (Vec2{10, -5}));
  EXPECT_EQ(end_point(p), p.start);
  EXPECT_NEAR(path_length(p), 2 * (40 - 8) + 2 * (20 - 8) + 2 * std::numbers::pi * 4, 1e-9);
  EXPECT_GT(signed_area2(linearize(p, 0.001)), 0.0);
  EXPECT_NEAR(path_length(rectangle({0, 0}, 10, 10, 0)), 40, 1e-12);
}

TEST(PocketRings, InsideTheOutlineOutOfTheIslandATooRadiusFromBoth) {
  PocketShape shape{rectangle({0, 0}, 60, 40, 5), {circle({10, 0}, 6)}};
  const PocketOptions o = options();
  const PocketRings rings = pocket_rings(shape, o);
  ASSERT_EQ(rings.finish.size(), 2u);  // the outline's wall and the island's
  ASSERT_GT(rings.roughing.size(), 3u);
  const Ring outline = to_ring(shape.outline, 0.001, true);
  const Ring island = to_ring(shape.islands[0], 0.001, true);
  for (const Ring& r : rings.roughing) {
    for (const Vec2& p : r) {
      EXPECT_TRUE(inside(outline, p));
      EXPECT_FALSE(inside(island, p));
      // A roughing ring leaves the finishing allowance on every wall.
      EXPECT_GE(to_ring_edges(p, outline), 3.0 + 0.2 - 2e-3);
      EXPECT_GE(to_ring_edges(p, island), 3.0 + 0.2 - 2e-3);
    }
  }
  for (const Ring& r : rings.finish) {
    for (const Vec2& p : r) {
      const double d = std::min(to_ring_edges(p, outline), to_ring_edges(p, island));
      EXPECT_NEAR(d, 3.0, 2e-3);  // the wall pass: one tool radius from the nearest wall
    }
  }
}

TEST(PocketRings, CircleRingsAreAStepoverApart) {
  PocketShape shape{circle({0, 0}, 20), {}};
  PocketOptions o = options();
  o.stepover = 2.0;
  const PocketRings rings = pocket_rings(shape, o);
  // Radii 20 - 3.2 - 2k for k = 0..8 (16.8 down to 0.8); the innermost first.
  ASSERT_EQ(rings.roughing.size(), 9u);
  for (std::size_t i = 0; i < rings.roughing.size(); ++i) {
    const double expect = 0.8 + 2.0 * static_cast<double>(i);
    for (const Vec2& p : rings.roughing[i])
      EXPECT_NEAR(core::norm(p), expect, 2e-3);
  }
}

TEST(PocketRings, AStepoverAboveTheRadiusGetsACoreRing) {
  // Width 14, tool 6, stepover 5: rings at 3.2 from the wall, the next at 8.2
  // is empty, and the core between 6.2 and 7 (the middle) would stay uncut.
  PocketShape shape{rectangle({0, 0}, 100, 14, 0), {}};
  PocketOptions o = options();
  o.stepover = 5;
  const PocketRings rings = pocket_rings(shape, o);
  ASSERT_EQ(rings.roughing.size(), 2u);
  for (const Vec2& p : rings.roughing[0])
    EXPECT_LE(std::fabs(p.y), 7 - 6.2 + 2e-3);
}

TEST(Pocket, DepthPassesFeatureAndCycleOrigin) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  PocketShape shape{rectangle({0, 0}, 40, 30, 3), {}};
  ASSERT_TRUE(generate_pocket(shape, options(), tp, d));
  EXPECT_FALSE(d.has_errors());
  const auto pockets = ops_of<canon::Pocket>(tp);
  ASSERT_EQ(pockets.size(), 1u);
  EXPECT_EQ(pockets[0].depth, 5.0);
  EXPECT_EQ(pockets[0].outline.start, shape.outline.start);
  std::vector<double> zs;
  for (const canon::Op& op : tp.ops()) {
    const auto e = end_of(op);
    if (!e || e->z >= 0) continue;
    EXPECT_EQ(op.origin, canon::Origin::Cycle);
    if (zs.empty() || zs.back() != e->z) zs.push_back(e->z);
  }
  // Three equal passes (5 / 2 rounded up), each level's moves together.
  ASSERT_EQ(zs.size(), 3u);
  EXPECT_DOUBLE_EQ(zs[0], -5.0 / 3);
  EXPECT_DOUBLE_EQ(zs[1], -10.0 / 3);
  EXPECT_EQ(zs[2], -5.0);
  // Every cutting move stays a tool radius inside the outline.
  const Ring outline = to_ring(shape.outline, 0.001, true);
  for (const canon::Op& op : tp.ops()) {
    const auto e = end_of(op);
    if (e && e->z < 0) {
      EXPECT_GE(to_ring_edges({e->x, e->y}, outline), 3.0 - 2e-3);
    }
  }
}

TEST(Pocket, ToolTooBigIsAnError) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  EXPECT_FALSE(generate_pocket({circle({0, 0}, 2.9), {}}, options(), tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenToolTooBig), 1);
  EXPECT_EQ(tp.size(), 0u);
}

TEST(Pocket, StepoverAboveTheToolDiameterIsAnError) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  PocketOptions o = options();
  o.stepover = 6.5;
  EXPECT_FALSE(generate_pocket({circle({0, 0}, 20), {}}, o, tp, d));
  ASSERT_EQ(count_code(d, core::Code::GenBadValue), 1);
  EXPECT_NE(d.all()[0].message.find("stepover 6.5 mm"), std::string::npos);
  EXPECT_EQ(tp.size(), 0u);
}

TEST(Pocket, OpenOutlineOrIslandIsAnError) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  const Path open{{0, 0}, {{{10, 0}, std::nullopt, 0}, {{10, 10}, std::nullopt, 0}}, false};
  EXPECT_FALSE(generate_pocket({open, {}}, options(), tp, d));
  EXPECT_FALSE(generate_pocket({circle({0, 0}, 20), {open}}, options(), tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenOpenOutline), 2);
}

TEST(PocketShape, LargestClosedContourIsTheOutlineTheOthersIslands) {
  core::DiagnosticList d;
  const auto shape =
      pocket_shape({circle({0, 0}, 3), rectangle({0, 0}, 40, 30, 2), circle({10, 5}, 2)}, d);
  ASSERT_TRUE(shape);
  EXPECT_NEAR(path_length(shape->outline), path_length(rectangle({0, 0}, 40, 30, 2)), 1e-12);
  ASSERT_EQ(shape->islands.size(), 2u);
  EXPECT_EQ(shape->islands[1].start, (Vec2{12, 5}));
}

TEST(PocketShape, OpenOutsideOrNothingIsAnError) {
  core::DiagnosticList d;
  const Path open{{0, 0}, {{{10, 0}, std::nullopt, 0}}, false};
  EXPECT_FALSE(pocket_shape({circle({0, 0}, 30), open}, d));
  EXPECT_FALSE(pocket_shape({circle({0, 0}, 30), circle({100, 0}, 3)}, d));
  EXPECT_FALSE(pocket_shape({}, d));
  EXPECT_EQ(count_code(d, core::Code::GenOpenOutline), 2);
  EXPECT_EQ(count_code(d, core::Code::GenBadValue), 1);
}

TEST(Pocket, LimitsKeepTheWorkFinite) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  PocketOptions o = options();
  o.stepover = 1e-6;  // 10^7 rings
  EXPECT_FALSE(generate_pocket({circle({0, 0}, 20), {}}, o, tp, d));
  o = options();
  o.step_down = 1e-6;  // 5·10^6 passes
  EXPECT_FALSE(generate_pocket({circle({0, 0}, 20), {}}, o, tp, d));
  EXPECT_FALSE(generate_pocket({circle({1e6, 0}, 20), {}}, options(), tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenBadValue), 3);
  EXPECT_EQ(tp.size(), 0u);
}

TEST(Pocket, BadValuesAreErrors) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  PocketOptions o = options();
  o.depth = 0;
  o.step_down = -1;
  o.finish_allowance = -0.1;
  EXPECT_FALSE(generate_pocket({circle({0, 0}, 20), {}}, o, tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenBadValue), 3);
}

}  // namespace
}  // namespace usina::cam
