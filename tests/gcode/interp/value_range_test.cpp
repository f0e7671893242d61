// Numbers out of range (issue 11, docs/rs274ngc.md "Numbers"): a word's
// value beyond ±1e9, an offset or a position beyond ±1e9 mm, an arc centre
// from a huge R, an arc too flat to tell from a full circle, a feed below
// 1e-6: each an E_VALUE_OUT_OF_RANGE at the word that made it (or at the
// block whose move leaves the range), and no op with such a number is sent.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "canon/limits.hpp"
#include "support/dialect_run.hpp"

namespace usina::gcode {
namespace {

using core::Code;
using dialect_test::Run;
using dialect_test::run_in;

// The first error of `r`: its code, line and column.
struct Where {
  Code code;
  std::uint32_t line;
  std::uint32_t col;
};

Where first_error(const Run& r) {
  for (const core::Diagnostic& d : r.diags.all()) {
    if (d.severity == core::Severity::Error) return {d.code, d.loc.line, d.loc.col};
  }
  return {Code::Message, 0, 0};
}

// `text` in dialect `dialect` stops with E_VALUE_OUT_OF_RANGE at (line, col),
// and every op it sent is in range.
void expect_out_of_range(const char* dialect, const std::string& text, std::uint32_t line,
                         std::uint32_t col) {
  SCOPED_TRACE(text);
  auto r = run_in(dialect, text);
  EXPECT_FALSE(r->ok);
  const Where w = first_error(*r);
  EXPECT_EQ(core::code_name(w.code), core::code_name(Code::ValueOutOfRange))
      << (r->diags.all().empty() ? "" : r->diags.all().front().message);
  EXPECT_EQ(w.line, line);
  if (col != 0) {
    EXPECT_EQ(w.col, col);
  }
  for (const canon::Op& op : r->path.ops()) {
    EXPECT_TRUE(canon::check_range(op.kind));
  }
}

void rs274(const std::string& text, std::uint32_t line, std::uint32_t col) {
  expect_out_of_range("rs274ngc", text, line, col);
}

TEST(ValueRange, IssueArcOfHugeRadiusIsAnErrorAtR) {
  // G2 X1 Y0 R[10**200]: check passed, trace printed a centre of (-nan, -inf).
  rs274("G2 X1 Y0 R[10**200] F100\nM2\n", 1, 10);
}

TEST(ValueRange, IssueHugeIncrementsTwiceAreAnErrorAtTheWord) {
  // G91 G0 X[10**308] twice gave "to":[inf,0,0].
  rs274("G91 G0 X[10**308]\nG0 X[10**308]\nM2\n", 1, 8);
}

TEST(ValueRange, IncrementsSummedBeyondTheRangeStopAtTheMove) {
  auto r = run_in("rs274ngc", "G91 G0 X900000000\nX900000000\nM2\n");
  const Where w = first_error(*r);
  EXPECT_EQ(w.code, Code::ValueOutOfRange);
  EXPECT_EQ(w.line, 2u);
  ASSERT_EQ(r->path.ops().size(), 1u);  // the first move, not the second, not the end
  EXPECT_EQ(std::get<canon::Traverse>(r->path.ops()[0].kind).to.x, 9e8);
}

TEST(ValueRange, WordBeyondTheRangeIsAnErrorAtTheWord) {
  rs274("G0 X1000000001\nM2\n", 1, 4);
  rs274("G0 Y-[2*10**9]\nM2\n", 1, 4);
  rs274("G4 P[10**10]\nM2\n", 1, 4);               // dwell
  rs274("S[10**10] M3\nM2\n", 1, 1);               // spindle speed
  rs274("G1 X1 F[10**12]\nM2\n", 1, 7);            // feed
  rs274("G1 X1 F0.0000001\nM2\n", 1, 7);           // a feed below 1e-6 gives infinite times
  rs274("G93 G1 X1 F0.0000001\nM2\n", 1, 11);      // inverse time
  rs274("G81 X0 R[10**10] Z-1 F100\nM2\n", 1, 8);  // canned cycle
}

TEST(ValueRange, ALargestValueIsInRange) {
  auto r = run_in("rs274ngc", "G0 X1000000000 Y-1000000000\nG1 X0 F0.000001\nM2\n");
  EXPECT_TRUE(r->ok) << first_error(*r).line;
  EXPECT_FALSE(r->diags.has_errors());
}

TEST(ValueRange, InchesBeyondTheRangeStopAtTheMove) {
  rs274("G20 G0 X999999999\nM2\n", 1, 0);  // 2.54e10 mm
}

TEST(ValueRange, OffsetsBeyondTheRangeAreAnErrorAtTheirWord) {
  rs274("G0 X999999999\nG92 X-999999999\nM2\n", 2, 5);  // G92: offset 2e9
  rs274("G52 X999999999\nG0 X999999999\nM2\n", 2, 0);   // G52 + move: at the move
  rs274("G0 X999999999\nG10 L20 P1 X-999999999\nM2\n", 2, 12);
  rs274("G43.1 Z999999999\nG20 G43.1 Z999999999\nM2\n", 2, 11);  // tool length in inches
  rs274("G0 X999999999\nG10 L10 P1 X-999999999\nM2\n", 2, 12);   // tool offset
}

TEST(ValueRange, HugeToolLengthFromTheTableIsAnErrorAtH) {
  InterpOptions o;
  ToolEntry t;
  t.number = 1;
  t.offset[2] = 5e9;
  o.tools.set(t);
  auto r = run_in("rs274ngc", "G43 H1\nM2\n", o);
  const Where w = first_error(*r);
  EXPECT_EQ(w.code, Code::ValueOutOfRange);
  EXPECT_EQ(w.col, 5u);
}

TEST(ValueRange, OffsetsInParametersStopAtTheMove) {
  // G55, not the G54 in use: re-selecting the system in use keeps its
  // offsets, as LinuxCNC's convert_coordinate_system.
  rs274("#5241=[10**300]\nG55 G0 X1\nM2\n", 2, 0);
}

TEST(ValueRange, ArcTooFlatToTellFromAFullCircleIsAnError) {
  // With a radius 1e8 times its chord the arc turns 1e-11 rad: the back
  // ends close so small an angle into a full turn of radius 1e8 mm.
  rs274("G2 X0.001 Y0 R100000000 F100\nM2\n", 1, 14);
  rs274("G2 X0.01 Y0 I-100000000 J0 F100\nM2\n", 1, 13);
  // A centre-format arc ending where it starts is a full circle, as meant.
  auto full = run_in("rs274ngc", "G2 X0 Y0 I100000000 J0 F100\nM2\n");
  EXPECT_TRUE(full->ok);
  // A flat arc that is still an arc.
  auto flat = run_in("rs274ngc", "G2 X1 Y0 R100000 F100\nM2\n");
  EXPECT_TRUE(flat->ok);
}

TEST(ValueRange, CannedCycleRepeatsBeyondTheRangeStopAtTheBlock) {
  rs274("G91 G81 X999999999 R1 Z-1 L3 F100\nM2\n", 1, 0);
}

TEST(ValueRange, RomiWordsAndScaleFactors) {
  expect_out_of_range("romi", "G0 X99999999999\nM30\n", 1, 4);
  expect_out_of_range("romi", "G72 K20\nG0 X900000000\nM30\n", 2, 0);  // scaled to 1.8e10
  expect_out_of_range("romi", "G91\nG0 X900000000\nG0 X900000000\nM30\n", 3, 0);
}

TEST(ValueRange, FanucWordsMacroValuesAndScaling) {
  expect_out_of_range("fanuc", "G0 X[10000000*100000000*100000]\nM30\n", 1, 4);
  expect_out_of_range("fanuc", "G51 X0 Y0 P999999999\nG0 X999999999.\nM30\n", 2, 4);
  expect_out_of_range("fanuc", "G91 G0 X999999999.\nX999999999.\nM30\n", 2, 0);
  auto r = run_in("fanuc", "#1=EXP[1000]\nG0 X#1\nM30\n");
  EXPECT_EQ(first_error(*r).code, Code::NumberOutOfRange);  // Fanuc alarm 111
  EXPECT_TRUE(r->path.ops().empty());
}

TEST(ValueRange, GrblMovesBeyondTheRange) {
  auto r = run_in("grbl", "G91 G0 X999999999\nG0 X999999999\nM2\n");
  bool out = false;
  for (const core::Diagnostic& d : r->diags.all())
    out = out || d.code == Code::ValueOutOfRange;
  EXPECT_TRUE(out);
  for (const canon::Op& op : r->path.ops())
    EXPECT_TRUE(canon::check_range(op.kind));
  auto f = run_in("grbl", "G1 X1 F0.0000001\nM2\n");
  EXPECT_EQ(first_error(*f).code, Code::ValueOutOfRange);
}

}  // namespace
}  // namespace usina::gcode
