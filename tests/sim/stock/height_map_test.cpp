// The stock's grid: the --stock words, the bounds on every input, and the
// cell count refused before anything is allocated.
#include "sim/stock/height_map.hpp"

#include <limits>

#include <gtest/gtest.h>

namespace usina::sim::stock {
namespace {

TEST(StockGrid, ABoxHasItsTopAtTheOriginsZ) {
  const auto box = parse_stock("box:200x150x30");
  ASSERT_TRUE(box);
  const auto map = HeightMap::make(*box, 0.5);
  ASSERT_TRUE(map) << map.error();
  EXPECT_EQ(map->nx(), 400u);
  EXPECT_EQ(map->ny(), 300u);
  EXPECT_DOUBLE_EQ(map->top(), 0.0);
  EXPECT_DOUBLE_EQ(map->bottom(), -30.0);
  EXPECT_DOUBLE_EQ(map->x(0), 0.25);
  EXPECT_NEAR(map->volume(), 200.0 * 150.0 * 30.0, 1e-6);
  EXPECT_DOUBLE_EQ(map->removed(), 0.0);
}

TEST(StockGrid, CellsDivideTheBoxWhole) {
  StockBox box{10.0, 3.0, 1.0, {5.0, -2.0, 7.0}};
  const auto map = HeightMap::make(box, 0.4);  // 10/0.4 = 25, 3/0.4 = 7.5 -> 8 cells of 0.375
  ASSERT_TRUE(map);
  EXPECT_EQ(map->nx(), 25u);
  EXPECT_EQ(map->ny(), 8u);
  EXPECT_DOUBLE_EQ(map->dy(), 0.375);
  EXPECT_DOUBLE_EQ(map->z(3, 3), 7.0);
  EXPECT_NEAR(map->volume(), 30.0, 1e-9);
}

TEST(StockGrid, BadStockWordsAreRefused) {
  for (const char* bad : {"200x150x30", "box:200x150", "box:200x150x", "box:ax1x1", "box:1x1x1x1",
                          "cylinder:10x5", "box:1e999x1x1"}) {
    EXPECT_FALSE(parse_stock(bad)) << bad;
  }
}

TEST(StockGrid, EveryInputIsBounded) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(HeightMap::make({0.0, 10, 10, {}}, 1.0));
  EXPECT_FALSE(HeightMap::make({-5.0, 10, 10, {}}, 1.0));
  EXPECT_FALSE(HeightMap::make({20000.0, 10, 10, {}}, 1.0));
  EXPECT_FALSE(HeightMap::make({nan, 10, 10, {}}, 1.0));
  EXPECT_FALSE(HeightMap::make({10, 10, 10, {nan, 0, 0}}, 1.0));
  EXPECT_FALSE(HeightMap::make({10, 10, 10, {0, 0, 1e9}}, 1.0));
  EXPECT_FALSE(HeightMap::make({10, 10, 10, {}}, 0.0));
  EXPECT_FALSE(HeightMap::make({10, 10, 10, {}}, nan));
  EXPECT_FALSE(HeightMap::make({10, 10, 10, {}}, 1e-6));
}

TEST(StockGrid, AGridTooLargeIsRefusedWithItsNumbers) {
  // 10 m x 10 m at 1 µm would be 10^14 cells: refused before any allocation.
  const auto map = HeightMap::make({10000.0, 10000.0, 10.0, {}}, 0.001);
  ASSERT_FALSE(map);
  EXPECT_NE(map.error().find("10000000 x 10000000"), std::string::npos) << map.error();
  EXPECT_NE(map.error().find("134217728"), std::string::npos) << map.error();
  // Just over the bound: 11,585 x 11,586 = 134,223,810 cells > 2^27.
  const auto over = HeightMap::make({1158.5, 1158.6, 1.0, {}}, 0.1);
  ASSERT_FALSE(over);
  EXPECT_NE(over.error().find("11585 x 11586"), std::string::npos) << over.error();
}

}  // namespace
}  // namespace usina::sim::stock
