// A tool table listed in descending order of tool number (fuzz_config's long
// seed `tools`): each line's tool used to be inserted before all the others
// read so far, quadratic in the table (scripts/fuzz.sh's scaling check
// proves the work now linear); here, that the table it gives is the same.
#include <string>

#include <gtest/gtest.h>

#include "core/source.hpp"
#include "gcode/tool_table.hpp"

namespace usina::gcode {
namespace {

TEST(ToolTableOrder, ADescendingTableIsReadIntoAscendingTools) {
  std::string text;
  for (int t = 2000; t >= 1; --t)
    text += "T" + std::to_string(t) + " P" + std::to_string(t) + " D" + std::to_string(t % 7) +
            " ;tool " + std::to_string(t) + "\n";
  const auto file = core::SourceFile::from_string("t.tbl", text);
  core::DiagnosticList diags;
  const auto table = read_tool_table(*file, 0, 1.0, diags);
  ASSERT_TRUE(table);
  EXPECT_TRUE(diags.all().empty());
  ASSERT_EQ(table->size(), 2000u);
  for (int t = 1; t <= 2000; ++t) {
    const ToolEntry& e = table->entries()[static_cast<std::size_t>(t - 1)];
    EXPECT_EQ(e.number, t);
    EXPECT_EQ(e.comment, "tool " + std::to_string(t));
    EXPECT_DOUBLE_EQ(e.diameter, t % 7);
  }
}

TEST(ToolTableOrder, ALaterLineOfTheSameToolReplacesItAndNamesTheLineBefore) {
  const auto file = core::SourceFile::from_string(
      "t.tbl", "T3 P1 D1\nT1 P2 D2\nT3 P3 D3 ;third\nT3 P4 D4 ;fourth\n");
  core::DiagnosticList diags;
  const auto table = read_tool_table(*file, 0, 1.0, diags);
  ASSERT_TRUE(table);
  ASSERT_EQ(table->size(), 2u);
  EXPECT_EQ(table->find(3)->pocket, 4);
  EXPECT_EQ(table->find(3)->comment, "fourth");
  ASSERT_EQ(diags.all().size(), 2u);
  EXPECT_EQ(diags.all()[0].code, core::Code::ToolRedefined);
  EXPECT_EQ(diags.all()[0].loc.line, 3u);
  EXPECT_NE(diags.all()[0].message.find("also on line 1"), std::string::npos);
  EXPECT_EQ(diags.all()[1].loc.line, 4u);
  EXPECT_NE(diags.all()[1].message.find("also on line 3"), std::string::npos);
}

}  // namespace
}  // namespace usina::gcode
