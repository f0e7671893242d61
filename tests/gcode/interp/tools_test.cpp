// The RS274NGC interpreter, program text in, canon ops out. Tools, spindle, coolant, dwell, feed
// modes, comments and program end: each test runs a small program and checks the ops, the
// parameters or the one diagnostic (helpers: support/interp_run.hpp).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/interp_run.hpp"

namespace usina::gcode::interp_test {
namespace {

// ============================================================================
// Tool length offsets, tools, spindle, coolant, dwell
// ============================================================================

TEST(InterpTools, G43HShiftsProgramZByTheToolLength) {
  RUN_OK(r, "G43 H1\n#1=#<_z>\n#2=#<_tool_offset>\nG53 G0 Z0\nG49\n#3=#<_z>\nG53 G0 Z0\nM2\n",
         with_tools());
  EXPECT_DOUBLE_EQ(r->param(1), -10.0);
  EXPECT_DOUBLE_EQ(r->param(2), 1.0);
  EXPECT_DOUBLE_EQ(r->param(3), 0.0);
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 2u);
  // G53 Z0 puts the spindle at machine zero: the tip is a tool length below.
  EXPECT_VEC(e[0], 0, 0, -10);
  EXPECT_VEC(e[1], 0, 0, 0);
}

TEST(InterpTools, G43WithoutHUsesTheToolInTheSpindle) {
  RUN_OK(r, "T2 M6\nG43\n#1=#<_z>\nM2\n", with_tools());
  EXPECT_DOUBLE_EQ(r->param(1), -25.0);
}

TEST(InterpTools, G43InInchReadsZInInch) {
  RUN_OK(r, "G20\nG43 H1\n#1=#<_z>\nM2\n", with_tools());
  EXPECT_NEAR(r->param(1), -10.0 / kInch, kTol);
}

TEST(InterpTools, ToolTableInInchMachineUnits) {
  InterpOptions o = with_tools();
  o.machine_units = core::LengthUnit::Inch;
  ToolEntry t;
  t.number = 5;
  t.offset = {0, 0, kInch};  // tables are read into mm
  o.tools.set(t);
  RUN_OK(r, "G43 H5\nG53 G0 Z0\nM2\n", std::move(o));
  EXPECT_VEC(r->ends()[0], 0, 0, -kInch);
}

TEST(InterpTools, G10L1AddsAToolThatG43AndM6Use) {
  RUN_OK(r, "G10 L1 P3 Z7 R2\nT3 M6\nG43 H3\n#1=#<_z>\nM2\n");
  const auto t = r->all<canon::ToolChange>();
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].tool, 3);
  ASSERT_TRUE(t[0].diameter.has_value());
  EXPECT_DOUBLE_EQ(*t[0].diameter, 4.0);
  EXPECT_DOUBLE_EQ(r->param(1), -7.0);
}

TEST(InterpTools, G10L10SetsTheLengthThatMakesTheCurrentPointReadTheValue) {
  RUN_OK(r, "G0 Z5\nG10 L10 P3 Z0\nG43 H3\n#1=#<_z>\nM2\n");
  EXPECT_NEAR(r->param(1), 0.0, kTol);
}

TEST(InterpTools, M6EmitsTheToolWithItsDiameter) {
  RUN_OK(r, "T2 M6\n#1=#<_current_tool>\n#2=#5400\nM2\n", with_tools());
  const auto t = r->all<canon::ToolChange>();
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].tool, 2);
  EXPECT_DOUBLE_EQ(*t[0].diameter, 12.7);
  EXPECT_DOUBLE_EQ(r->param(1), 2.0);
  EXPECT_DOUBLE_EQ(r->param(2), 2.0);
}

TEST(InterpTools, ToolNotInTheTableHasNoDiameter) {
  RUN_OK(r, "T9 M6\nM2\n");
  const auto t = r->all<canon::ToolChange>();
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].tool, 9);
  EXPECT_FALSE(t[0].diameter.has_value());
}

TEST(InterpTools, TSelectsWithoutChanging) {
  RUN_OK(r, "T4\n#1=#<_selected_tool>\n#2=#<_current_tool>\nM2\n");
  EXPECT_TRUE(r->all<canon::ToolChange>().empty());
  EXPECT_DOUBLE_EQ(r->param(1), 4.0);
  EXPECT_DOUBLE_EQ(r->param(2), 0.0);
}

TEST(InterpTools, M6StopsARunningSpindleFirst) {
  RUN_OK(r, "S1000 M3\nT1 M6\nM2\n", with_tools());
  EXPECT_EQ(r->kinds(), "spindle spindle tool end");
  const auto s = r->all<canon::Spindle>();
  EXPECT_EQ(s[1].dir, canon::SpindleDir::Off);
}

TEST(InterpTools, M61SetsTheToolNumberFromQ) {
  RUN_OK(r, "M61 Q4\n#1=#<_current_tool>\nM2\n");
  EXPECT_DOUBLE_EQ(r->param(1), 4.0);
}

TEST(InterpSpindle, M3M4M5WithTheSpeed) {
  RUN_OK(r, "S1000 M3\n#1=#<_spindle_on>\nM4\nM5\n#2=#<_spindle_on>\nM2\n");
  const auto s = r->all<canon::Spindle>();
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].dir, canon::SpindleDir::Cw);
  EXPECT_DOUBLE_EQ(s[0].rpm, 1000.0);
  EXPECT_EQ(s[1].dir, canon::SpindleDir::Ccw);
  EXPECT_EQ(s[2].dir, canon::SpindleDir::Off);
  EXPECT_DOUBLE_EQ(r->param(1), 1.0);
  EXPECT_DOUBLE_EQ(r->param(2), 0.0);
}

TEST(InterpSpindle, SpeedWordInTheSameBlockAppliesToM3) {
  RUN_OK(r, "M3 S2400\nM2\n");
  EXPECT_DOUBLE_EQ(r->all<canon::Spindle>()[0].rpm, 2400.0);
}

TEST(InterpSpindle, ProgramEndStopsTheSpindle) {
  RUN_OK(r, "S500 M3\nM2\n");
  EXPECT_EQ(r->kinds(), "spindle spindle end");
  EXPECT_EQ(r->all<canon::Spindle>()[1].dir, canon::SpindleDir::Off);
}

TEST(InterpCoolant, M7MistM8FloodM9Off) {
  RUN_OK(r, "M7\nM8\nM9\nM2\n");
  const auto c = r->all<canon::Coolant>();
  ASSERT_EQ(c.size(), 3u);
  EXPECT_TRUE(c[0].mist);
  EXPECT_FALSE(c[0].flood);
  EXPECT_TRUE(c[1].mist);
  EXPECT_TRUE(c[1].flood);
  EXPECT_FALSE(c[2].mist);
  EXPECT_FALSE(c[2].flood);
}

TEST(InterpCoolant, M7AndM8InOneBlockTurnBothOn) {
  RUN_OK(r, "M8 M7\n#1=#<_mist>\n#2=#<_flood>\nM2\n");
  const auto c = r->all<canon::Coolant>();
  ASSERT_EQ(c.size(), 1u);
  EXPECT_TRUE(c[0].mist);
  EXPECT_TRUE(c[0].flood);
  EXPECT_DOUBLE_EQ(r->param(1), 1.0);
  EXPECT_DOUBLE_EQ(r->param(2), 1.0);
}

TEST(InterpDwell, G4PIsSeconds) {
  RUN_OK(r, "G4 P1.5\nM2\n");
  const auto d = r->all<canon::Dwell>();
  ASSERT_EQ(d.size(), 1u);
  EXPECT_DOUBLE_EQ(d[0].s, 1.5);
}

TEST(InterpDwell, DwellComesBeforeTheMotionOfItsBlock) {
  RUN_OK(r, "G4 P2 G0 X1\nM2\n");
  EXPECT_EQ(r->kinds(), "dwell traverse end");
}

// ============================================================================
// Feed modes
// ============================================================================

TEST(InterpFeedMode, InverseTimeFeedHasNoMmPerMinuteRate) {
  RUN_OK(r, "G93 G1 X1 F2\nG2 X3 I1 F4\nM2\n");
  const auto f = r->all<Feed>();
  ASSERT_EQ(f.size(), 1u);
  EXPECT_FALSE(f[0].f.has_value());
  EXPECT_FALSE(r->all<Arc>()[0].f.has_value());
}

TEST(InterpFeedMode, PerRevolutionFeedHasNoMmPerMinuteRate) {
  RUN_OK(r, "G95 G1 X1 F0.1\nG94 G1 X2 F100\nM2\n");
  const auto f = r->all<Feed>();
  ASSERT_EQ(f.size(), 2u);
  EXPECT_FALSE(f[0].f.has_value());
  ASSERT_TRUE(f[1].f.has_value());
  EXPECT_DOUBLE_EQ(*f[1].f, 100.0);
}

TEST(InterpFeedMode, InverseTimeNeedsFOnEveryMove) {
  auto r = run("G93 G1 X1 F2\nG1 X2\nM2\n");
  expect_error(*r, Code::NoFeedRate, 2, 1);
}

TEST(InterpFeedMode, EnteringInverseTimeForgetsTheFeed) {
  auto r = run("G1 X1 F100\nG93\nG94\nG1 X2\nM2\n");
  expect_error(*r, Code::NoFeedRate, 4, 1);
}

// ============================================================================
// Comments, messages, program end
// ============================================================================

TEST(InterpComment, CommentsBecomeCommentOps) {
  RUN_OK(r, "(Face the stock)\nG0 X1 ; rapid\nM2\n");
  EXPECT_EQ(r->kinds(), "comment comment traverse end");
  const auto c = r->all<canon::Comment>();
  EXPECT_EQ(c[0].text, "Face the stock");
  EXPECT_EQ(c[1].text, "rapid");
}

TEST(InterpComment, MessageIsANoteAndAComment) {
  RUN_OK(r, "G0 X1 (MSG,Load the vice jaws)\nM2\n");
  const auto notes = r->of_severity(core::Severity::Note);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(core::code_name(notes[0].code), core::code_name(Code::Message));
  EXPECT_EQ(notes[0].message, "Load the vice jaws");
  EXPECT_EQ(notes[0].loc.line, 1u);
  EXPECT_EQ(notes[0].loc.col, 7u);
  EXPECT_EQ(r->all<canon::Comment>()[0].text, "Load the vice jaws");
}

TEST(InterpComment, MessageKeywordIsCaseInsensitive) {
  RUN_OK(r, "(msg,hi)\nM2\n");
  EXPECT_EQ(r->of_severity(core::Severity::Note).size(), 1u);
}

TEST(InterpComment, OrdinaryCommentIsNotAMessage) {
  RUN_OK(r, "(message to self)\nM2\n");
  EXPECT_TRUE(r->of_severity(core::Severity::Note).empty());
}

TEST(InterpEnd, M2EndsTheProgramAndLaterBlocksDoNotRun) {
  RUN_OK(r, "G0 X1\nM2\nG0 X2\n");
  EXPECT_EQ(r->kinds(), "traverse end");
  EXPECT_TRUE(r->diags.all().empty());
}

TEST(InterpEnd, M30EndsTheProgram) {
  RUN_OK(r, "G0 X1\nM30\nG0 X2\n");
  EXPECT_EQ(r->kinds(), "traverse end");
}

TEST(InterpEnd, MissingEndIsAWarning) {
  RUN_OK(r, "G0 X1\nG0 X2\n");
  const auto w = r->of_severity(core::Severity::Warning);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(core::code_name(w[0].code), core::code_name(Code::NoProgramEnd));
  EXPECT_EQ(w[0].loc.line, 2u);
  EXPECT_EQ(r->kinds(), "traverse traverse");
}

TEST(InterpEnd, PercentLinesDelimitTheProgram) {
  RUN_OK(r, "%\nG0 X1\n%\nG0 X2\n");
  EXPECT_EQ(r->kinds(), "traverse");
  EXPECT_TRUE(r->diags.all().empty());
}

TEST(InterpEnd, M99InTheMainProgramEndsIt) {
  RUN_OK(r, "G0 X1\nM99\nG0 X2\n");
  EXPECT_EQ(r->kinds(), "traverse");
}

TEST(InterpEnd, ProgramStopsAreKeptAsComments) {
  RUN_OK(r, "M0\nM1\nM2\n");
  const auto c = r->all<canon::Comment>();
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].text, "M0 (program stop)");
}

TEST(InterpEnd, SlashBlocksRunUnlessBlockDeleteIsOn) {
  // The operator's block delete switch is off by default, as in LinuxCNC.
  RUN_OK(all, "/G0 X5\nG0 X1\nM2\n");
  EXPECT_EQ(all->ends().size(), 2u);
  InterpOptions o;
  o.block_delete = true;
  RUN_OK(r, "/G0 X5\nG0 X1\n/M2\nM2\n", std::move(o));
  EXPECT_EQ(r->kinds(), "traverse end");
  EXPECT_EQ(r->ops().back().src.line, 4u);
}

TEST(InterpEnd, ByteOrderMarkIsAWarningAndSkipped) {
  RUN_OK(r, "\xEF\xBB\xBFG0 X1\nM2\n");
  const auto w = r->of_severity(core::Severity::Warning);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(core::code_name(w[0].code), core::code_name(Code::ByteOrderMark));
  EXPECT_EQ(r->kinds(), "traverse end");
}

TEST(InterpEnd, LineNumbersAreIgnored) {
  RUN_OK(r, "N10 G0 X1\nN20 M2\n");
  EXPECT_EQ(r->kinds(), "traverse end");
}

}  // namespace
}  // namespace usina::gcode::interp_test
