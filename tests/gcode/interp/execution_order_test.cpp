// The order in which a block's parts run is table data a dialect gives
// (interp/execution_order.hpp), as its G/M table is: the interpreter runs
// the steps in the order the table lists them.
#include "gcode/interp/execution_order.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "canon/toolpath.hpp"
#include "gcode/interp/interpreter.hpp"

namespace usina::gcode {
namespace {

// The kinds of op a run sent, in order: 'S' spindle, 'C' coolant, 'T' tool
// change, 'F' feed move, 'R' rapid.
std::string op_kinds(const std::string& program, const ExecutionOrder* order) {
  core::SourceManager sources;
  core::DiagnosticList diags;
  canon::Toolpath path;
  const std::uint32_t id = sources.add(core::SourceFile::from_string("t.ngc", program));
  Interpreter interp(sources, {}, path, diags, nullptr, DialectRules{.order = order});
  EXPECT_TRUE(interp.run(id)) << (diags.all().empty() ? "" : diags.all()[0].message);
  std::string kinds;
  for (const canon::Op& op : path.ops()) {
    if (std::holds_alternative<canon::Spindle>(op.kind)) kinds += 'S';
    if (std::holds_alternative<canon::Coolant>(op.kind)) kinds += 'C';
    if (std::holds_alternative<canon::ToolChange>(op.kind)) kinds += 'T';
    if (std::holds_alternative<canon::Feed>(op.kind)) kinds += 'F';
    if (std::holds_alternative<canon::Traverse>(op.kind)) kinds += 'R';
  }
  return kinds;
}

TEST(ExecutionOrder, LinuxcncNamesEveryStepOnce) {
  EXPECT_NO_THROW(check_execution_order(linuxcnc_execution_order()));
  const auto steps = linuxcnc_execution_order().steps;
  const auto at = [&](ExecStep s) { return std::find(steps.begin(), steps.end(), s); };
  // execute_block's order: the tool change before the spindle, the spindle
  // before coolant, the G codes' settings before the move, stops last.
  EXPECT_LT(at(ExecStep::ChangeTool), at(ExecStep::Spindle));
  EXPECT_LT(at(ExecStep::Spindle), at(ExecStep::Coolant));
  EXPECT_LT(at(ExecStep::Units), at(ExecStep::Motion));
  EXPECT_EQ(steps.back(), ExecStep::Stop);
}

TEST(ExecutionOrder, AStepMissingOrTwiceIsTheTablesError) {
  std::vector<ExecStep> steps(linuxcnc_execution_order().steps.begin(),
                              linuxcnc_execution_order().steps.end());
  steps.pop_back();
  EXPECT_THROW(check_execution_order({"test", steps}), std::logic_error);
  steps.push_back(ExecStep::Motion);
  EXPECT_THROW(check_execution_order({"test", steps}), std::logic_error);
  steps.back() = ExecStep::Stop;
  EXPECT_NO_THROW(check_execution_order({"test", steps}));
  // The interpreter refuses a wrong order when it is made, not at a block.
  steps.pop_back();
  const ExecutionOrder wrong{"test", steps};
  core::SourceManager sources;
  core::DiagnosticList diags;
  canon::Toolpath path;
  EXPECT_THROW(Interpreter(sources, {}, path, diags, nullptr, DialectRules{.order = &wrong}),
               std::logic_error);
}

// The same block runs as the table orders it: LinuxCNC changes the tool,
// then turns the spindle on, then coolant, then moves (and M2 stops the
// spindle). An order that lists coolant first and the tool change after
// the move sends them so; its M6 then stops the running spindle first, as
// LinuxCNC's M6 does.
TEST(ExecutionOrder, TheInterpreterRunsTheTablesOrder) {
  const std::string program = "T1 M6 M3 M8 S1000 G1 X10 F100\nM2\n";
  EXPECT_EQ(op_kinds(program, nullptr), "TSCFS");
  std::vector<ExecStep> steps(linuxcnc_execution_order().steps.begin(),
                              linuxcnc_execution_order().steps.end());
  const auto move_before = [&](ExecStep s, ExecStep before) {
    steps.erase(std::find(steps.begin(), steps.end(), s));
    steps.insert(std::find(steps.begin(), steps.end(), before), s);
  };
  move_before(ExecStep::Coolant, ExecStep::Spindle);
  move_before(ExecStep::ChangeTool, ExecStep::Resync);
  const ExecutionOrder other{"test", steps};
  EXPECT_EQ(op_kinds(program, &other), "CSFST");
}

}  // namespace
}  // namespace usina::gcode
