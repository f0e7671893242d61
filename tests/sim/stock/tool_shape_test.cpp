// The cutters by shape: their lower surfaces, the words that name them and
// the bounds every shape keeps.
#include "sim/stock/tool_shape.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace usina::sim::stock {
namespace {

TEST(StockTool, LowerSurfacesRiseAsTheirShapes) {
  const ToolShape ball = *parse_shape("ball", 10.0);
  EXPECT_DOUBLE_EQ(ball.lift(0.0), 0.0);
  EXPECT_DOUBLE_EQ(ball.lift(5.0), 5.0);
  EXPECT_NEAR(ball.lift(3.0), 1.0, 1e-12);  // 5 - sqrt(25 - 9)
  const ToolShape drill = *parse_shape("drill", 10.0);
  EXPECT_NEAR(drill.lift(5.0), 5.0 / std::tan(59.0 * M_PI / 180.0), 1e-12);
  const ToolShape vee = *parse_shape("vee", 10.0);
  EXPECT_NEAR(vee.lift(2.0), 2.0, 1e-12);  // 90° included: 45° flanks
  const ToolShape bull = *parse_shape("bull:2", 10.0);
  EXPECT_DOUBLE_EQ(bull.lift(3.0), 0.0);
  EXPECT_NEAR(bull.lift(5.0), 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(parse_shape("flat", 6.0)->lift(2.9), 0.0);
}

TEST(StockTool, BadShapesSayWhy) {
  EXPECT_FALSE(parse_shape("blob", 6.0));
  EXPECT_FALSE(parse_shape("bull", 6.0));    // no corner radius
  EXPECT_FALSE(parse_shape("bull:3", 6.0));  // the corner is the whole radius: a ball
  EXPECT_FALSE(parse_shape("bull:nan", 6.0));
  EXPECT_FALSE(parse_shape("vee:180", 6.0));
  EXPECT_FALSE(parse_shape("drill:inf", 6.0));
  EXPECT_FALSE(parse_shape("ball:3", 6.0));
  EXPECT_FALSE(parse_shape("flat", 0.0));
  EXPECT_FALSE(parse_shape("flat", 1e6));
  EXPECT_FALSE(parse_shape("flat", std::numeric_limits<double>::quiet_NaN()));
  const auto e = parse_shape("blob", 6.0);
  ASSERT_FALSE(e);
  EXPECT_NE(e.error().find("ball"), std::string::npos) << e.error();
}

TEST(StockTool, ATableCommentNamesTheShapeByAWord) {
  EXPECT_EQ(shape_from_comment("6mm BALL nose, 2 flutes", 6.0).kind, ToolKind::Ball);
  const ToolShape bull = shape_from_comment("roughing bull:1.5", 12.0);
  EXPECT_EQ(bull.kind, ToolKind::BullNose);
  EXPECT_DOUBLE_EQ(bull.corner_radius, 1.5);
  EXPECT_EQ(shape_from_comment("spot drill:90", 8.0).kind, ToolKind::Drill);
  EXPECT_DOUBLE_EQ(shape_from_comment("spot drill:90", 8.0).angle, 90.0);
  EXPECT_EQ(shape_from_comment("1/4 end mill", 6.35).kind, ToolKind::Flat);
  EXPECT_DOUBLE_EQ(shape_from_comment("", 6.35).diameter, 6.35);
}

}  // namespace
}  // namespace usina::sim::stock
