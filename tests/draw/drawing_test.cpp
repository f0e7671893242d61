// The drawing model: merging of collinear segments, bounds, the view box,
// polylines and the order of layers.
#include "draw/drawing.hpp"

#include <numbers>

#include <gtest/gtest.h>

#include "draw/layer_style.hpp"

namespace usina::draw {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Drawing, CollinearContinuationMergesIntoOneLine) {
  Drawing d;
  Layer& l = d.layer(kContourLayer);
  d.add_line(l, {0, 0}, {1, 0});
  d.add_line(l, {1, 0}, {2, 0});
  d.add_line(l, {2, 0}, {5, 0});
  ASSERT_EQ(l.entities.size(), 1u);
  const Line& line = std::get<Line>(l.entities[0]);
  EXPECT_EQ(line.from, (Vec2{0, 0}));
  EXPECT_EQ(line.to, (Vec2{5, 0}));
}

TEST(Drawing, BendReversalOrGapStartsANewLine) {
  Drawing d;
  Layer& l = d.layer(kContourLayer);
  d.add_line(l, {0, 0}, {1, 0});
  d.add_line(l, {1, 0}, {2, 0.001});       // bend
  d.add_line(l, {2, 0.001}, {1, 0.0005});  // back along itself
  d.add_line(l, {5, 5}, {6, 5.0005});      // not joined to the last end
  EXPECT_EQ(l.entities.size(), 4u);
}

TEST(Drawing, MovesAlongZOnlyAddNothing) {
  Drawing d;
  Layer& l = d.layer(kContourLayer);
  d.add_line(l, {3, 4}, {3, 4});
  EXPECT_TRUE(l.entities.empty());
  EXPECT_TRUE(d.bounds().empty);
}

TEST(Drawing, LinesOnOtherLayersDoNotMerge) {
  Drawing d;
  d.add_line(d.layer(kContourLayer), {0, 0}, {1, 0});
  d.add_line(d.layer(kRapidLayer), {1, 0}, {2, 0});
  EXPECT_EQ(d.layer(kContourLayer).entities.size(), 1u);
  EXPECT_EQ(d.layer(kRapidLayer).entities.size(), 1u);
  EXPECT_EQ(d.entity_count(), 2u);
}

TEST(Drawing, ArcBoundsTakeTheQuadrantPointsItPasses) {
  Drawing d;
  // From 45° to 135° counter-clockwise over the top: passes 90°.
  d.add_arc(d.layer(kContourLayer), {{0, 0}, 10, kPi / 4, 3 * kPi / 4, true});
  EXPECT_NEAR(d.bounds().max.y, 10.0, 1e-12);
  EXPECT_NEAR(d.bounds().min.y, 10.0 * std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(d.bounds().min.x, -10.0 * std::sqrt(0.5), 1e-12);
}

TEST(Drawing, ClockwiseArcBoundsGoTheOtherWay) {
  Drawing d;
  // From 45° to 135° clockwise: under the centre, through 0°, 270°, 180°.
  d.add_arc(d.layer(kContourLayer), {{0, 0}, 10, kPi / 4, 3 * kPi / 4, false});
  EXPECT_NEAR(d.bounds().min.y, -10.0, 1e-12);
  EXPECT_NEAR(d.bounds().max.x, 10.0, 1e-12);
  EXPECT_NEAR(d.bounds().min.x, -10.0, 1e-12);
  EXPECT_NEAR(d.bounds().max.y, 10.0 * std::sqrt(0.5), 1e-12);
}

TEST(Drawing, ArcSweepIsBetweenZeroAndFullTurn) {
  EXPECT_NEAR(arc_sweep(Arc{{0, 0}, 1, 0, kPi / 2, true}), kPi / 2, 1e-12);
  EXPECT_NEAR(arc_sweep(Arc{{0, 0}, 1, 0, kPi / 2, false}), 3 * kPi / 2, 1e-12);
  EXPECT_NEAR(arc_sweep(Arc{{0, 0}, 1, 3, -3, true}), 2 * kPi - 6, 1e-12);
}

TEST(Drawing, EmptyDrawingShowsTenMillimetresAboutTheOrigin) {
  const Box b = view_box(Drawing{}.bounds());
  EXPECT_FALSE(b.empty);
  EXPECT_EQ(b.min, (Vec2{-5, -5}));
  EXPECT_EQ(b.max, (Vec2{5, 5}));
}

TEST(Drawing, ViewBoxAddsFivePercentOfTheLargerSide) {
  Box b;
  b.add(Vec2{0, 0});
  b.add(Vec2{200, 50});
  const Box v = view_box(b);
  EXPECT_EQ(v.min, (Vec2{-10, -10}));
  EXPECT_EQ(v.max, (Vec2{210, 60}));
}

TEST(Drawing, PolylineDropsRepeatsAndMergesCollinearRuns) {
  Drawing d;
  Layer& l = d.layer(kContourLayer);
  d.add_polyline(l, {{0, 0}, {0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 1}, {2, 3}, {0, 3}});
  ASSERT_EQ(l.entities.size(), 1u);
  const auto& p = std::get<Polyline>(l.entities[0]);
  const std::vector<Vec2> want{{0, 0}, {2, 0}, {2, 3}, {0, 3}};
  EXPECT_EQ(p.points, want);
}

TEST(Drawing, PolylineOfTwoPointsIsALineAndOfOneNothing) {
  Drawing d;
  Layer& l = d.layer(kContourLayer);
  d.add_polyline(l, {{0, 0}, {1, 1}, {2, 2}});
  d.add_polyline(l, {{7, 7}, {7, 7}});
  ASSERT_EQ(l.entities.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<Line>(l.entities[0]));
}

TEST(Drawing, LayersComeInTheWritersOrder) {
  Drawing d;
  d.layer(toolpath_layer(12));
  d.layer(toolpath_layer(2));
  d.layer(kPocketsLayer);
  d.layer(kRapidLayer);
  d.layer(kContourLayer);
  d.layer(kHolesLayer);
  std::vector<std::string> names;
  for (const Layer* l : d.layers())
    names.push_back(l->name);
  const std::vector<std::string> want{"CONTOUR", "RAPID",       "HOLES",
                                      "POCKETS", "TOOLPATH_T2", "TOOLPATH_T12"};
  EXPECT_EQ(names, want);
}

TEST(LayerStyle, RapidsAreDashedAndToolsHaveTheirOwnColours) {
  EXPECT_TRUE(style_of(kRapidLayer).dashed);
  EXPECT_FALSE(style_of(kContourLayer).dashed);
  EXPECT_NE(style_of(toolpath_layer(1)).aci, style_of(toolpath_layer(2)).aci);
  EXPECT_EQ(style_of(toolpath_layer(1)).aci, style_of(toolpath_layer(7)).aci);  // six colours
  EXPECT_EQ(tool_of_layer("TOOLPATH_T15"), 15);
  EXPECT_EQ(tool_of_layer("TOOLPATH_T"), std::nullopt);
  EXPECT_EQ(tool_of_layer("TOOLPATH_T1x"), std::nullopt);
  EXPECT_EQ(tool_of_layer("CONTOUR"), std::nullopt);
}

}  // namespace
}  // namespace usina::draw
