// Tools with no tool table (issue 12, docs/rs274ngc.md "Tools"): a program
// is checked without the machine's table, so any tool number is a tool of
// unknown size, used as zero; a table the user gave lists every tool.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "canon/toolpath.hpp"
#include "core/diagnostic.hpp"
#include "core/source.hpp"
#include "gcode/interp/interpreter.hpp"
#include "gcode/tool_table.hpp"
#include "support/interp_run.hpp"

namespace usina::gcode {
namespace {

using interp_test::run;
using interp_test::Run;

InterpOptions table_of_tool_one() {
  InterpOptions o;
  ToolEntry one;
  one.number = 1;
  one.offset = {0, 0, 10};
  one.diameter = 6;
  o.tools.set(one);
  return o;
}

TEST(ToolsWithoutTable, AToolChangeAndItsLengthAreNoError) {
  // probe_basic's duplicate_tool_test: T8 M6 then G43 (the tool in the spindle).
  const auto r = run("T8 M6\nG43\nG0 X1 Z5\nG43 H1\nG41 D3 G1 X10 F100\nG40 G1 X20\nM2\n");
  EXPECT_TRUE(r->ok);
  EXPECT_FALSE(r->has(core::Code::UnknownTool));
}

TEST(ToolsWithoutTable, AnUnknownToolHasNoLengthNoDiameter) {
  // #5410: the diameter of the tool in the spindle (LinuxCNC);
  // #<_tool_offset>: 1 while a tool length offset is in force.
  const auto r = run("T8 M6\nG43 H8\n#1 = #5410\n#2 = #<_tool_offset>\n#3 = #<_z>\nM2\n");
  ASSERT_TRUE(r->ok);
  EXPECT_DOUBLE_EQ(r->param(1), 0.0);
  EXPECT_DOUBLE_EQ(r->param(2), 0.0);
  EXPECT_DOUBLE_EQ(r->param(3), 0.0);
}

TEST(ToolsWithoutTable, AToolTheProgramDefinesIsUsed) {
  // G10 L1 on an open table: tool 8 gets 10 mm (the current point reads
  // Z-10 once its length is on), and other numbers stay tools of no length.
  const auto r = run("G10 L1 P8 Z10\nT8 M6\nG43 H8\n#1 = #<_z>\nG43 H9\n#2 = #<_z>\nM2\n");
  ASSERT_TRUE(r->ok);
  EXPECT_NEAR(r->param(1), -10.0, 1e-9);
  EXPECT_NEAR(r->param(2), 0.0, 1e-9);
  EXPECT_FALSE(r->has(core::Code::UnknownTool));
}

TEST(ToolsWithoutTable, AToolNotInAGivenTableIsAnError) {
  const auto length = run("G43 H8\nM2\n", table_of_tool_one());
  EXPECT_FALSE(length->ok);
  EXPECT_TRUE(length->has(core::Code::UnknownTool));
  const auto comp = run("G41 D8\nM2\n", table_of_tool_one());
  EXPECT_FALSE(comp->ok);
  EXPECT_TRUE(comp->has(core::Code::UnknownTool));
  EXPECT_TRUE(run("G43 H1\nG41 D1\nG40\nM2\n", table_of_tool_one())->ok);
}

TEST(ToolsWithoutTable, AnEmptyTableGivenListsNoTool) {
  core::SourceManager sources;
  const std::uint32_t id =
      sources.add(core::SourceFile::from_string("empty.tbl", "; no tools yet\n"));
  core::DiagnosticList diags;
  auto table = read_tool_table(*sources.get(id), id, 1.0, diags);
  ASSERT_TRUE(table.has_value());
  EXPECT_TRUE(table->lists_tools());
  InterpOptions o;
  o.tools = *table;
  EXPECT_TRUE(run("G43 H1\nM2\n", o)->has(core::Code::UnknownTool));
}

TEST(ToolsWithoutTable, G10DoesNotMakeATable) {
  ToolTable open;
  EXPECT_FALSE(open.lists_tools());
  ToolEntry eight;
  eight.number = 8;
  open.define(eight);
  EXPECT_FALSE(open.lists_tools());
  EXPECT_NE(open.find(8), nullptr);
  open.set(eight);
  EXPECT_TRUE(open.lists_tools());
}

}  // namespace
}  // namespace usina::gcode
