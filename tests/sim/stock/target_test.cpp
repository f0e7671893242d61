// Target depths (sim/stock/target.hpp): the cells inside a layer's closed
// contours against its Z, even-odd for islands, the tolerance.
#include "sim/stock/target.hpp"

#include <gtest/gtest.h>

namespace usina::sim::stock {
namespace {

// A 40 x 30 x 10 box, its top at Z0, in cells of 0.5 mm.
HeightMap box() {
  auto map = HeightMap::make({40.0, 30.0, 10.0, {0.0, 0.0, 0.0}}, 0.5);
  EXPECT_TRUE(map.has_value());
  return std::move(*map);
}

std::vector<Vec2> square(double x0, double y0, double side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

// Cuts the cells whose centres are in [x0, x1] x [y0, y1] down to `z`.
void cut(HeightMap& map, double x0, double x1, double y0, double y1, float z) {
  for (std::size_t j = 0; j < map.ny(); ++j)
    for (std::size_t i = 0; i < map.nx(); ++i)
      if (map.x(i) >= x0 && map.x(i) <= x1 && map.y(j) >= y0 && map.y(j) <= y1) map.row(j)[i] = z;
}

TargetLayer layer(std::string name, double z, std::vector<std::vector<Vec2>> rings) {
  TargetLayer t;
  t.layer = std::move(name);
  t.z = z;
  t.rings = std::move(rings);
  return t;
}

TEST(Target, UncutStockStandsAboveTheWholeArea) {
  const HeightMap map = box();
  const TargetResult r = check_target(map, layer("POCKET", -2.0, {square(10, 10, 10)}), 0.01);
  EXPECT_DOUBLE_EQ(r.area_mm2, 100.0);  // 20 x 20 cell centres inside
  EXPECT_DOUBLE_EQ(r.above_mm2, 100.0);
  EXPECT_NEAR(r.most_above_mm, 2.0, 1e-6);
  EXPECT_NEAR(r.left_mm3, 200.0, 1e-3);
  EXPECT_GT(r.most_at.x, 10.0);
  EXPECT_LT(r.most_at.x, 20.0);
}

TEST(Target, AnAreaCutToItsDepthHasNothingAbove) {
  HeightMap map = box();
  cut(map, 10, 20, 10, 20, -2.0F);
  const TargetResult r = check_target(map, layer("POCKET", -2.0, {square(10, 10, 10)}), 0.01);
  EXPECT_DOUBLE_EQ(r.above_mm2, 0.0);
  EXPECT_DOUBLE_EQ(r.most_above_mm, 0.0);
  EXPECT_DOUBLE_EQ(r.left_mm3, 0.0);
}

TEST(Target, WhatIsLeftIsFoundWhereItIs) {
  HeightMap map = box();
  cut(map, 10, 20, 10, 17, -2.0F);  // the top three mm of the square not cut
  cut(map, 10, 20, 17, 20, -1.5F);
  const TargetResult r = check_target(map, layer("POCKET", -2.0, {square(10, 10, 10)}), 0.01);
  EXPECT_DOUBLE_EQ(r.above_mm2, 30.0);
  EXPECT_NEAR(r.most_above_mm, 0.5, 1e-6);
  EXPECT_GT(r.most_at.y, 17.0);
  EXPECT_NEAR(r.left_mm3, 15.0, 1e-3);
}

TEST(Target, WithinTheToleranceIsNotAbove) {
  HeightMap map = box();
  cut(map, 10, 20, 10, 20, -1.995F);
  const TargetResult tight = check_target(map, layer("POCKET", -2.0, {square(10, 10, 10)}), 0.001);
  const TargetResult loose = check_target(map, layer("POCKET", -2.0, {square(10, 10, 10)}), 0.01);
  EXPECT_DOUBLE_EQ(tight.above_mm2, 100.0);
  EXPECT_DOUBLE_EQ(loose.above_mm2, 0.0);
  EXPECT_NEAR(loose.left_mm3, 0.5, 1e-3);  // 100 mm² x 0.005 mm, counted all the same
}

TEST(Target, AContourInsideAContourIsAnIsland) {
  const HeightMap map = box();
  const TargetResult r =
      check_target(map, layer("POCKET", -2.0, {square(10, 10, 10), square(13, 13, 4)}), 0.01);
  EXPECT_DOUBLE_EQ(r.area_mm2, 100.0 - 16.0);
}

TEST(Target, AVertexOnACellRowIsCrossedOnce) {
  // A diamond whose side vertices lie on the row of centres y = 15.25:
  // counted twice, a vertex would open a span to the box's edge.
  const HeightMap map = box();
  const std::vector<Vec2> diamond{{20, 10.25}, {25, 15.25}, {20, 20.25}, {15, 15.25}};
  const TargetResult r = check_target(map, layer("D", -1.0, {diamond}), 0.01);
  EXPECT_NEAR(r.area_mm2, 50.0, 5.0);  // the diamond's 50 mm², to the grid
}

TEST(Target, OutsideTheStockThereAreNoCells) {
  const HeightMap map = box();
  const TargetResult r = check_target(map, layer("FAR", -1.0, {square(100, 100, 10)}), 0.01);
  EXPECT_DOUBLE_EQ(r.area_mm2, 0.0);
  EXPECT_DOUBLE_EQ(r.above_mm2, 0.0);
}

TEST(Target, TheMessageNamesTheLayerTheAreaAndWhere) {
  HeightMap map = box();
  cut(map, 10, 20, 10, 17, -2.0F);
  const TargetResult r = check_target(map, layer("POCKET", -2.0, {square(10, 10, 10)}), 0.01);
  const std::string m = material_above_message(r, 0.01);
  EXPECT_NE(m.find("layer POCKET (Z-2)"), std::string::npos) << m;
  EXPECT_NE(m.find("30.00 mm² of its 100.00 mm²"), std::string::npos) << m;
  EXPECT_NE(m.find("up to 2.000 mm"), std::string::npos) << m;
}

}  // namespace
}  // namespace usina::sim::stock
