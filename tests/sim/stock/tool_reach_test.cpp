// The words above a tool's end (tool_reach.cpp): flutes:L, holder:D,
// stickout:L, no-plunge[:A], in `--tool-shape` after the shape or anywhere in
// a tool table's comment; their bounds, and the sets that do not go together.
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "sim/stock/tool_shape.hpp"

namespace usina::sim::stock {
namespace {

void expect_refused(const char* spec, const char* because) {
  const auto t = parse_tool_spec(spec, {});
  ASSERT_FALSE(t) << spec;
  EXPECT_NE(t.error().find(because), std::string::npos) << spec << ": " << t.error();
}

TEST(StockTool, TheWordsAfterTheShapeAreRead) {
  const auto t = parse_tool_spec("1=flat/6,flutes:20,holder:32,stickout:30", {});
  ASSERT_TRUE(t) << t.error();
  EXPECT_DOUBLE_EQ(t->second.diameter, 6.0);
  EXPECT_DOUBLE_EQ(t->second.flutes, 20.0);
  EXPECT_DOUBLE_EQ(t->second.holder, 32.0);
  EXPECT_DOUBLE_EQ(t->second.stickout, 30.0);
  EXPECT_DOUBLE_EQ(t->second.plunge_ramp, 0.0);  // cuts at its centre unless told
}

TEST(StockTool, AToolWithoutTheWordsHasNone) {
  const auto t = parse_tool_spec("2=ball/6", {});
  ASSERT_TRUE(t) << t.error();
  EXPECT_EQ(t->second.flutes, 0.0);
  EXPECT_EQ(t->second.holder, 0.0);
  EXPECT_EQ(t->second.stickout, 0.0);
}

TEST(StockTool, ANoPlungeToolsRampIsFiveDegreesUnlessGiven) {
  const auto plain = parse_tool_spec("1=flat/6,no-plunge", {});
  ASSERT_TRUE(plain) << plain.error();
  EXPECT_DOUBLE_EQ(plain->second.plunge_ramp, 5.0);
  const auto given = parse_tool_spec("1=bull:1/10,NO-PLUNGE:3.5", {});
  ASSERT_TRUE(given) << given.error();
  EXPECT_DOUBLE_EQ(given->second.plunge_ramp, 3.5);
}

TEST(StockTool, AHolderWithoutAStickOutIsRefused) {
  expect_refused("1=flat/6,holder:32", "a holder needs its stick-out");
}

TEST(StockTool, FlutesShorterThanTheToolsEndAreRefused) {
  // A 10 mm ball's end is 5 mm high; a 118° drill of 10 mm, 3.004 mm.
  expect_refused("1=ball/10,flutes:4.99", "shorter than the tool's end (5 mm");
  expect_refused("1=drill/10,flutes:3", "shorter than the tool's end");
  EXPECT_TRUE(parse_tool_spec("1=ball/10,flutes:5", {}));
}

TEST(StockTool, AStickOutShorterThanTheFlutesOrTheEndIsRefused) {
  expect_refused("1=flat/6,flutes:20,holder:32,stickout:19", "shorter than the flutes (20 mm)");
  expect_refused("1=ball/10,stickout:4", "shorter than the tool's end (5 mm)");
  EXPECT_TRUE(parse_tool_spec("1=flat/6,flutes:20,holder:32,stickout:20", {}));
}

TEST(StockTool, NoPlungeIsForAFlatOrBullNoseOnly) {
  for (const char* spec : {"1=ball/6,no-plunge", "1=drill/6,no-plunge", "1=vee/6,no-plunge"}) {
    expect_refused(spec, "no-plunge is for a flat or bull nose");
  }
}

TEST(StockTool, LengthsOutOfTheirBoundsAreRefused) {
  for (const char* spec : {"1=flat/6,flutes:0", "1=flat/6,flutes:-2", "1=flat/6,flutes:1000.5",
                           "1=flat/6,holder:1e308,stickout:30", "1=flat/6,stickout:-0"}) {
    expect_refused(spec, "must be more than 0 and at most 1000 mm");
  }
  for (const char* spec : {"1=flat/6,flutes:nan", "1=flat/6,stickout:inf",
                           "1=flat/6,flutes:", "1=flat/6,flutes:20mm"}) {
    expect_refused(spec, "is not a number");
  }
}

TEST(StockTool, AHoldersLengthIsRefusedWithWhy) {
  expect_refused("1=flat/6,holder:32x40,stickout:30", "its length is not used");
}

TEST(StockTool, ARampOutOfItsBoundsIsRefused) {
  for (const char* spec : {"1=flat/6,no-plunge:0", "1=flat/6,no-plunge:90", "1=flat/6,no-plunge:-5",
                           "1=flat/6,no-plunge:nan", "1=flat/6,no-plunge:x"}) {
    expect_refused(spec, "more than 0 and less than 90 degrees");
  }
}

TEST(StockTool, AnUnknownWordAfterTheShapeIsRefused) {
  expect_refused("1=flat/6,flute:20", "'flute:20' is not a word after a tool's shape");
  expect_refused("1=flat/6,flutes", "'flutes' is not a word after a tool's shape");
}

TEST(StockTool, ATableCommentsWordsAreReadAnywhereAndProseSkipped) {
  const auto t = tool_from_comment(
      "6 mm end mill, 2 flutes; holder:32 stickout:30 flutes:20, no-plunge:3 roughing", 6.0);
  ASSERT_TRUE(t) << t.error();
  EXPECT_EQ(t->kind, ToolKind::Flat);
  EXPECT_DOUBLE_EQ(t->flutes, 20.0);
  EXPECT_DOUBLE_EQ(t->holder, 32.0);
  EXPECT_DOUBLE_EQ(t->stickout, 30.0);
  EXPECT_DOUBLE_EQ(t->plunge_ramp, 3.0);
  const auto ball = tool_from_comment("ball nose flutes:12", 10.0);
  ASSERT_TRUE(ball) << ball.error();
  EXPECT_EQ(ball->kind, ToolKind::Ball);
  EXPECT_DOUBLE_EQ(ball->flutes, 12.0);
}

TEST(StockTool, ATableCommentWithABadWordOrAMismatchIsRefused) {
  EXPECT_FALSE(tool_from_comment("end mill flutes:abc", 6.0));
  EXPECT_FALSE(tool_from_comment("end mill holder:32", 6.0));
  EXPECT_FALSE(tool_from_comment("ball flutes:2", 10.0));
}

TEST(StockTool, TheSpecKeepsTheTablesWordsItDoesNotWriteAgain) {
  std::map<int, ToolShape> known;
  known[1] = *tool_from_comment("flutes:20 holder:32 stickout:30", 6.0);
  const auto t = parse_tool_spec("1=bull:1,stickout:40", known);
  ASSERT_TRUE(t) << t.error();
  EXPECT_EQ(t->second.kind, ToolKind::BullNose);
  EXPECT_DOUBLE_EQ(t->second.diameter, 6.0);
  EXPECT_DOUBLE_EQ(t->second.flutes, 20.0);
  EXPECT_DOUBLE_EQ(t->second.holder, 32.0);
  EXPECT_DOUBLE_EQ(t->second.stickout, 40.0);
}

}  // namespace
}  // namespace usina::sim::stock
