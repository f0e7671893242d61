// The drawing a DrawingBuilder makes of hand-made op streams: the arcs'
// angles and directions, helix projection, part against toolpath view,
// cycle moves left out, holes and pockets.
#include "draw/builder.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "draw/layer_style.hpp"

namespace usina::draw {
namespace {

using canon::Origin;
using core::Vec3;

constexpr double kPi = std::numbers::pi;
const Vec3 kUp{0, 0, 1};

canon::Op op(canon::OpKind kind, Origin origin = Origin::Program) {
  return canon::Op{std::move(kind), {}, origin};
}

canon::Arc arc(Vec3 to, Vec3 center, Vec3 normal, int turn) {
  return {to, center, normal, turn, std::nullopt};
}

// Runs the ops through a builder of `view` starting at `start`.
Drawing draw(const std::vector<canon::Op>& ops, View view = View::Part, Vec3 start = {}) {
  Drawing d;
  DrawingBuilder b(d, view, start);
  for (const auto& o : ops)
    b.on(o);
  b.finish();
  return d;
}

std::vector<Entity> entities(Drawing& d, std::string_view layer) {
  return d.layer(layer).entities.to_vector();
}

TEST(Builder, CounterClockwiseArcKeepsItsAngles) {
  Drawing d = draw({op(canon::Traverse{{10, 0, 0}}), op(arc({0, 10, 0}, {0, 0, 0}, kUp, 1))});
  const auto& e = entities(d, kContourLayer);
  ASSERT_EQ(e.size(), 1u);
  const Arc& a = std::get<Arc>(e[0]);
  EXPECT_TRUE(a.ccw);
  EXPECT_NEAR(a.radius, 10.0, 1e-12);
  EXPECT_NEAR(a.start_angle, 0.0, 1e-12);
  EXPECT_NEAR(a.end_angle, kPi / 2, 1e-12);
}

TEST(Builder, ClockwiseArcAndArcAboutMinusZ) {
  // turn −1 about +Z and turn +1 about −Z are both clockwise seen from above.
  for (const auto& [normal, turn] : {std::pair{kUp, -1}, std::pair{Vec3{0, 0, -1}, 1}}) {
    Drawing d =
        draw({op(canon::Traverse{{0, 10, 0}}), op(arc({10, 0, 0}, {0, 0, 0}, normal, turn))});
    const Arc a = std::get<Arc>(entities(d, kContourLayer).at(0));
    EXPECT_FALSE(a.ccw);
    EXPECT_NEAR(a.start_angle, kPi / 2, 1e-12);
    EXPECT_NEAR(a.end_angle, 0.0, 1e-12);
    EXPECT_NEAR(arc_sweep(a), kPi / 2, 1e-12);
  }
}

TEST(Builder, HelixProjectsToItsArc) {
  Drawing d = draw({op(canon::Traverse{{5, 0, 0}}), op(arc({-5, 0, -3}, {0, 0, 0}, kUp, 1))});
  const Arc a = std::get<Arc>(entities(d, kContourLayer).at(0));
  EXPECT_NEAR(a.radius, 5.0, 1e-12);
  EXPECT_NEAR(std::fabs(a.end_angle), kPi, 1e-12);
  EXPECT_NEAR(arc_sweep(a), kPi, 1e-12);
}

TEST(Builder, MultiTurnHelixAndFullCircleProjectToACircle) {
  Drawing d = draw({op(canon::Traverse{{5, 0, 0}}),
                    op(arc({-5, 0, -3}, {0, 0, 0}, kUp, 3)),     // 2.5 turns down
                    op(arc({-5, 0, -4}, {0, 0, 0}, kUp, -1))});  // one closed turn
  const auto& e = entities(d, kContourLayer);
  // Both are the circle of radius 5: the second retraces the first and is
  // drawn once (builder.hpp, memory bounded by what the picture shows).
  ASSERT_EQ(e.size(), 1u);
  for (const Entity& x : e) {
    const Circle& c = std::get<Circle>(x);
    EXPECT_EQ(c.center, (Vec2{0, 0}));
    EXPECT_NEAR(c.radius, 5.0, 1e-12);
  }
}

TEST(Builder, ArcInAVerticalPlaneProjectsToItsShadow) {
  // G18 semicircle over the top from X0 to X20 about X10 Z0: its shadow on
  // XY runs along Y = 7 from X0 to X20.
  Drawing d =
      draw({op(canon::Traverse{{0, 7, 0}}), op(arc({20, 7, 0}, {10, 7, 0}, {0, 1, 0}, -1))});
  const auto& e = entities(d, kContourLayer);
  ASSERT_EQ(e.size(), 1u);
  const Line& l = std::get<Line>(e[0]);  // collinear points merge to one line
  EXPECT_NEAR(l.from.x, 0.0, 1e-9);
  EXPECT_NEAR(l.to.x, 20.0, 1e-9);
  EXPECT_NEAR(l.to.y, 7.0, 1e-9);
}

TEST(Builder, SplineIsAPolyline) {
  canon::Spline s{{3, 1, 0}, {{1, 1, 0}, {2, 0, 0}, {3, 1, 0}}, std::nullopt};
  Drawing d = draw({op(s)});
  const auto p = std::get<Polyline>(entities(d, kContourLayer).at(0));
  const std::vector<Vec2> want{{0, 0}, {1, 1}, {2, 0}, {3, 1}};
  EXPECT_EQ(p.points, want);
}

TEST(Builder, PartViewPutsFeedsOnContourAndRapidsOnRapid) {
  Drawing d = draw({op(canon::Traverse{{0, 0, 5}}), op(canon::Traverse{{10, 0, 5}}),
                    op(canon::Feed{{10, 0, -1}, 100.0}), op(canon::Feed{{20, 0, -1}, 100.0})});
  ASSERT_EQ(entities(d, kRapidLayer).size(), 1u);
  ASSERT_EQ(entities(d, kContourLayer).size(), 1u);
  const Line l = std::get<Line>(entities(d, kContourLayer)[0]);
  EXPECT_EQ(l.from, (Vec2{10, 0}));
  EXPECT_EQ(l.to, (Vec2{20, 0}));
  std::vector<std::string> names;
  for (const Layer* layer : d.layers())
    names.push_back(layer->name);
  EXPECT_EQ(names, (std::vector<std::string>{"CONTOUR", "RAPID", "HOLES", "POCKETS"}));
}

// The cycle's rapid from hole to hole stays (the seed's drawing shows it), its
// feeds and the tool-change excursion do not.
TEST(Builder, PartViewLeavesCycleFeedsAndToolChangeMovesOut) {
  Drawing d = draw(
      {op(canon::Feed{{10, 0, 0}, 100.0}), op(canon::Traverse{{20, 0, 0}}, Origin::Cycle),
       op(canon::Feed{{20, 10, 0}, 100.0}, Origin::Cycle),
       op(arc({20, 10, 0}, {25, 10, 0}, kUp, 1), Origin::Cycle),
       op(canon::Traverse{{50, 50, 0}}, Origin::ToolChange), op(canon::Feed{{60, 50, 0}, 100.0})});
  const auto& rapids = entities(d, kRapidLayer);
  ASSERT_EQ(rapids.size(), 1u);
  EXPECT_EQ(std::get<Line>(rapids[0]).from, (Vec2{10, 0}));
  EXPECT_EQ(std::get<Line>(rapids[0]).to, (Vec2{20, 0}));
  const auto& c = entities(d, kContourLayer);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(std::get<Line>(c[1]).from, (Vec2{50, 50}));  // the position still follows
}

TEST(Builder, PartViewRecordsWhichToolCutTheContour) {
  Drawing d = draw({op(canon::Feed{{5, 5, 0}, 100.0}), op(canon::ToolChange{1, 6.0}),
                    op(canon::Feed{{10, 0, 0}, 100.0}), op(canon::Feed{{10, 0, -5}, 100.0}),
                    op(canon::ToolChange{2, 3.0}), op(canon::Feed{{10, 10, 0}, 100.0})});
  const Layer& c = d.layer(kContourLayer);
  ASSERT_EQ(c.entities.size(), 3u);
  ASSERT_EQ(c.tool_runs.size(), 3u);
  EXPECT_EQ(c.tool_runs[0].tool, 0);
  EXPECT_EQ(c.tool_runs[1].first, 1u);
  EXPECT_EQ(c.tool_runs[1].tool, 1);
  EXPECT_EQ(c.tool_runs[2].first, 2u);
  EXPECT_EQ(c.tool_runs[2].tool, 2);
}

TEST(Builder, ToolpathViewDrawsEveryMoveOnTheToolsLayer) {
  Drawing d = draw({op(canon::ToolChange{3, 6.0}), op(canon::Feed{{10, 0, 0}, 100.0}),
                    op(canon::Feed{{10, 5, 0}, 100.0}, Origin::Cycle),
                    op(canon::Traverse{{0, 0, 0}}, Origin::Cycle), op(canon::ToolChange{7, 2.0}),
                    op(arc({10, 0, 0}, {5, 0, 0}, kUp, -1))},
                   View::Toolpath);
  EXPECT_EQ(entities(d, toolpath_layer(3)).size(), 2u);
  EXPECT_EQ(entities(d, toolpath_layer(7)).size(), 1u);
  EXPECT_EQ(entities(d, kRapidLayer).size(), 1u);
  for (const Layer* l : d.layers())
    EXPECT_NE(l->name, kContourLayer);
}

TEST(Builder, PartViewDrawsHolesAsCirclesOfTheirDiameter) {
  Drawing d =
      draw({op(canon::Hole{{12, 15, 0}, 8.5, 6.0}), op(canon::Hole{{28, 15, 0}, 8.5, 6.0})});
  const auto& h = entities(d, kHolesLayer);
  ASSERT_EQ(h.size(), 2u);
  EXPECT_EQ(std::get<Circle>(h[0]).center, (Vec2{12, 15}));
  EXPECT_DOUBLE_EQ(std::get<Circle>(h[0]).radius, 4.25);
}

TEST(Builder, HoleOfUnknownDiameterIsACross) {
  Drawing d = draw({op(canon::Hole{{12, 15, 0}, 0.0, 6.0})});
  const auto& h = entities(d, kHolesLayer);
  ASSERT_EQ(h.size(), 2u);
  EXPECT_EQ(std::get<Line>(h[0]).from, (Vec2{11, 15}));
  EXPECT_EQ(std::get<Line>(h[1]).to, (Vec2{12, 16}));
}

TEST(Builder, ToolpathViewDrawsNoFeatures) {
  canon::Pocket p{{{0, 0}, {{{10, 0}, std::nullopt, 0}}}, 2.0};
  Drawing d = draw({op(canon::Hole{{12, 15, 0}, 8.5, 6.0}), op(p)}, View::Toolpath);
  EXPECT_EQ(d.entity_count(), 0u);
}

TEST(Builder, PocketOutlineIsItsLinesAndArcs) {
  // A 20 × 10 slot with round ends: two lines, two half circles.
  canon::Outline o{{0, 0},
                   {{{20, 0}, std::nullopt, 0},
                    {{20, 10}, Vec2{20, 5}, 1},
                    {{0, 10}, std::nullopt, 0},
                    {{0, 0}, Vec2{0, 5}, 1}}};
  Drawing d = draw({op(canon::Pocket{o, 3.0})});
  const auto& e = entities(d, kPocketsLayer);
  ASSERT_EQ(e.size(), 4u);
  const Arc& a = std::get<Arc>(e[1]);
  EXPECT_TRUE(a.ccw);
  EXPECT_NEAR(a.start_angle, -kPi / 2, 1e-12);
  EXPECT_NEAR(a.end_angle, kPi / 2, 1e-12);
  EXPECT_NEAR(d.bounds().min.x, -5.0, 1e-12);
  EXPECT_NEAR(d.bounds().max.x, 25.0, 1e-12);
}

TEST(Builder, CircularPocketIsACircle) {
  canon::Outline o{{10, 0}, {{{10, 0}, Vec2{0, 0}, 1}}};
  Drawing d = draw({op(canon::Pocket{o, 3.0})});
  EXPECT_NEAR(std::get<Circle>(entities(d, kPocketsLayer).at(0)).radius, 10.0, 1e-12);
}

TEST(Builder, FirstMoveStartsAtTheStartPoint) {
  Drawing d = draw({op(canon::Traverse{{10, 0, 0}})}, View::Part, {-5, -5, 0});
  EXPECT_EQ(std::get<Line>(entities(d, kRapidLayer).at(0)).from, (Vec2{-5, -5}));
}

TEST(Builder, NonMotionOpsDrawNothing) {
  Drawing d = draw({op(canon::Comment{"x"}), op(canon::Dwell{1.0}), op(canon::Spindle{}),
                    op(canon::Coolant{}), op(canon::ProgramEnd{})});
  EXPECT_EQ(d.entity_count(), 0u);
  EXPECT_TRUE(d.bounds().empty);
}

}  // namespace
}  // namespace usina::draw
