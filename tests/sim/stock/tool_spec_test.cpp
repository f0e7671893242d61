// `usina simulate --tool-shape T=SHAPE[/D]`, read by parse_tool_spec
// (fuzz_config's reader 5): a diameter written there is checked as written
// (a negative one was reported as missing from the tool table).
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "sim/stock/tool_shape.hpp"

namespace usina::sim::stock {
namespace {

std::map<int, ToolShape> table_with_tool_1() {
  std::map<int, ToolShape> known;
  known[1].diameter = 6.0;
  return known;
}

TEST(ToolSpec, ANumberAShapeAndADiameter) {
  const auto t = parse_tool_spec("4=bull:1/10", {});
  ASSERT_TRUE(t) << t.error();
  EXPECT_EQ(t->first, 4);
  EXPECT_EQ(t->second.kind, ToolKind::BullNose);
  EXPECT_DOUBLE_EQ(t->second.diameter, 10.0);
  EXPECT_DOUBLE_EQ(t->second.corner_radius, 1.0);
}

TEST(ToolSpec, WithoutADiameterTheToolTablesIsTaken) {
  const auto t = parse_tool_spec("1=ball", table_with_tool_1());
  ASSERT_TRUE(t) << t.error();
  EXPECT_DOUBLE_EQ(t->second.diameter, 6.0);
  const auto missing = parse_tool_spec("2=ball", table_with_tool_1());
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("no diameter in the tool table"), std::string::npos);
}

TEST(ToolSpec, ANegativeOrHugeDiameterIsOutOfRangeNotMissing) {
  // 64.9e-324 (a denormal) came from the fuzzer: below a micrometre is no tool.
  for (const char* spec : {"1=ball/-6", "3=flat/0", "3=flat/-0", "3=flat/1e308", "3=flat/64.9e-324",
                           "3=flat/0.0009"}) {
    const auto t = parse_tool_spec(spec, table_with_tool_1());
    ASSERT_FALSE(t) << spec;
    EXPECT_NE(t.error().find("must be at least 0.001 and at most 1000 mm"), std::string::npos)
        << t.error();
    EXPECT_EQ(t.error().find("no diameter in the tool table"), std::string::npos) << t.error();
  }
}

TEST(ToolSpec, WhatIsNoSpecSaysTheForm) {
  for (const char* spec : {"", "=", "ball/6", "-1=ball/6", "1.5=ball/6", "100000=ball/6",
                           "nan=ball/6", "inf=flat/1", "1=ball/nan", "1=ball/6/7"}) {
    EXPECT_FALSE(parse_tool_spec(spec, table_with_tool_1())) << spec;
  }
}

}  // namespace
}  // namespace usina::sim::stock
