// The drawing model: merging of collinear segments, bounds, the view box,
// polylines and the order of layers.
#include "draw/drawing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

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
  const auto e = l.entities.to_vector();
  ASSERT_EQ(e.size(), 1u);
  const Line& line = std::get<Line>(e[0]);
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

// The distance from `p` to the segment a-b.
double distance_to(Vec2 p, const Line& l) {
  const Vec2 d = l.to - l.from;
  const double t = std::clamp(core::dot(p - l.from, d) / core::dot(d, d), 0.0, 1.0);
  return core::distance(p, l.from + d * t);
}

// An Archimedean spiral of 0.2 mm steps, as bench/gen_spiral.py writes it.
std::vector<Vec2> spiral(int steps) {
  std::vector<Vec2> pts{{0, 0}};
  double theta = 0.0;
  for (int i = 0; i < steps; ++i) {
    const double r0 = 0.5 * theta / (2 * kPi);
    theta += 0.2 / std::max(r0, 0.2);
    const double r = 0.5 * theta / (2 * kPi);
    pts.push_back({r * std::cos(theta), r * std::sin(theta)});
  }
  return pts;
}

// Each point of `pts` lies within `tol` of the line drawn for it: the lines
// run through the points in order, so walk both.
void expect_within(const std::vector<Vec2>& pts, const std::vector<Entity>& lines, double tol) {
  std::size_t e = 0;
  for (const Vec2& p : pts) {
    ASSERT_LT(e, lines.size());
    const Line* line = &std::get<Line>(lines[e]);
    if (e + 1 < lines.size() && core::distance(p, line->to) > 1e-9 && distance_to(p, *line) > tol) {
      line = &std::get<Line>(lines[++e]);
    }
    EXPECT_LE(distance_to(p, *line), tol + 1e-12) << p.x << "," << p.y;
    if (core::distance(p, line->to) < 1e-12 && e + 1 < lines.size()) ++e;
  }
  EXPECT_EQ(e + 1, lines.size());
}

TEST(Drawing, WithoutToleranceEveryBendOfACurveIsKept) {
  Drawing d;
  Layer& l = d.layer(kContourLayer);
  const auto pts = spiral(2000);
  for (std::size_t i = 1; i < pts.size(); ++i)
    d.add_line(l, pts[i - 1], pts[i]);
  EXPECT_EQ(l.entities.size(), 2000u);
}

TEST(Drawing, ARunOfMovesWithinTheToleranceIsOneLine) {
  Drawing d;
  d.set_tolerance(0.01);
  Layer& l = d.layer(kContourLayer);
  const auto pts = spiral(20'000);
  for (std::size_t i = 1; i < pts.size(); ++i)
    d.add_line(l, pts[i - 1], pts[i]);
  // The chord that strays 0.01 mm from a circle of radius r is sqrt(0.08 r)
  // long: 14 steps of 0.2 mm at the spiral's outer radius (12.6 mm).
  EXPECT_LT(l.entities.size(), 20'000u / 4);
  EXPECT_GT(l.entities.size(), 20'000u / 40);
  // Every line starts where the last ended, and passes within 0.01 mm of
  // every point it stands for.
  const auto lines = l.entities.to_vector();
  for (std::size_t i = 1; i < lines.size(); ++i)
    EXPECT_EQ(std::get<Line>(lines[i]).from, std::get<Line>(lines[i - 1]).to);
  expect_within(pts, lines, 0.01);
}

TEST(Drawing, AToleranceNeverMergesACornerOrAReversal) {
  Drawing d;
  d.set_tolerance(0.01);
  Layer& l = d.layer(kContourLayer);
  d.add_line(l, {0, 0}, {10, 0});
  d.add_line(l, {10, 0}, {10, 0.02});  // a step of twice the tolerance
  d.add_line(l, {10, 0.02}, {20, 0.02});
  d.add_line(l, {20, 0.02}, {15, 0.021});      // back along itself
  d.add_line(l, {15, 0.021}, {15.005, 0.02});  // back again, within 0.01 of the last end
  EXPECT_EQ(l.entities.size(), 5u);
}

TEST(Drawing, AToleranceDoesNotJoinLinesAcrossAnotherEntityOrATool) {
  Drawing d;
  d.set_tolerance(0.01);
  Layer& l = d.layer(kContourLayer);
  d.add_line(l, {0, 0}, {1, 0});
  d.add_circle(l, {{1, 0}, 0.5});
  d.add_line(l, {1, 0}, {2, 0});  // after the circle: a line of its own
  l.tool_runs.push_back({l.entities.size(), 2});
  d.add_line(l, {2, 0}, {3, 0});  // the next tool's: a line of its own
  EXPECT_EQ(l.entities.size(), 4u);
}

TEST(Drawing, APictureMergesWhatIsFinerThanHalfAPixel) {
  // A zigzag of 0.05 mm across 100 mm: in 1000 x 1000 pixels (0.1 mm each)
  // it is one line; as a drawing with 0.01 mm it keeps every zig.
  auto zigzag = [](Drawing& d) {
    Layer& l = d.layer(kContourLayer);
    d.add_line(l, {-50, -50}, {50, 50});  // the picture's bounds first
    Vec2 at{0, 0};
    for (int i = 1; i <= 1000; ++i) {
      const Vec2 to{0.1 * i, i % 2 == 0 ? 0.0 : 0.02};
      d.add_line(l, at, to);
      at = to;
    }
    return l.entities.size();
  };
  Drawing picture;
  picture.set_tolerance(0.01);
  picture.set_picture(1000, 1000);
  EXPECT_EQ(zigzag(picture), 2u);  // the diagonal, then the zigzag as one line
  Drawing drawing;
  drawing.set_tolerance(0.01);
  EXPECT_EQ(zigzag(drawing), 1001u);
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
  const auto e = l.entities.to_vector();
  ASSERT_EQ(e.size(), 1u);
  const auto& p = std::get<Polyline>(e[0]);
  const std::vector<Vec2> want{{0, 0}, {2, 0}, {2, 3}, {0, 3}};
  EXPECT_EQ(p.points, want);
}

TEST(Drawing, PolylineOfTwoPointsIsALineAndOfOneNothing) {
  Drawing d;
  Layer& l = d.layer(kContourLayer);
  d.add_polyline(l, {{0, 0}, {1, 1}, {2, 2}});
  d.add_polyline(l, {{7, 7}, {7, 7}});
  ASSERT_EQ(l.entities.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<Line>(l.entities.back()));
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
