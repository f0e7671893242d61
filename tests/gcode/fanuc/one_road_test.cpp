// The fanuc dialect on the one road below the text (issue 12): comments
// are read where they stand, words reach the interpreter as numbers with
// the columns the user wrote them at.
#include <gtest/gtest.h>

#include "fanuc_test_support.hpp"

namespace usina::gcode::fanuc_test {
namespace {

using core::Code;

const core::Diagnostic* first_error(const Run& r) {
  for (const core::Diagnostic& d : r.diags.all())
    if (d.severity == core::Severity::Error) return &d;
  return nullptr;
}

TEST(FanucComments, ACommentInsideANumberReadsAsABlank) {
  auto r = run_fanuc("G0 X1(NOTE)2. Y[2*(C)3] Z(A (B) C)4.\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {12, 6, 4});
}

TEST(FanucComments, CommentsAroundMacroKeywordsAndSequenceNumbers) {
  auto r = run_fanuc(
      "#1=0\nN1(C)0 #1=#1+1\n(C)IF(C)[#1 LT 3](C)GOTO(C)10\n"
      "(C)WHILE(C)[#1 LT 5](C)DO(C)1\n#1=#1+1\nEND(C)1\nG0 X#1\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {5, 0, 0});
}

TEST(FanucComments, AMacroErrorAfterACommentPointsAtItsColumn) {
  auto r = run_fanuc("#1 = (NOTE) [1/0]\nM30\n");
  const core::Diagnostic* e = first_error(*r);
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->code, Code::DivisionByZero);
  EXPECT_EQ(e->loc.col, 17u);
  auto v = run_fanuc("G0 X1.(A (B) C)Y[2*(C)3] Z#7(C) 7\nM30\n");
  e = first_error(*v);
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->code, Code::ParameterOutOfRange);  // #77: the comment is a blank
  EXPECT_EQ(e->loc.col, 34u);
}

TEST(FanucComments, TheFirstCommentIsTheAlarmText) {
  auto r = run_fanuc("#3000=7 (TOOL (T1) BROKEN) (SECOND)\nM30\n");
  EXPECT_EQ(r->first_error(), Code::MacroAlarm);
  EXPECT_EQ(r->first_error_text(), "alarm 3007: TOOL (T1) BROKEN");
}

TEST(FanucComments, AnUnclosedCommentEndsAtTheLineEnd) {
  auto r = run_fanuc("G0 X1. (NOT CLOSED; Y9.\nG0 Y2.\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {1, 2, 0});
}

// Fanuc reads a number as every dialect does (gcode/decimal.hpp): the same
// digits give the same double as in rs274ngc, so the two traces agree to
// the last bit (digit-by-digit sums once gave 0.7500000000000001).
TEST(FanucNumbers, TheSameDigitsGiveTheSameValueAsRs274ngc) {
  const std::string program = "G1 X0.75 Y1.4833 Z-0.7487 F1500.\nG1 X[1.4833] Y0.1\nM30\n";
  auto fanuc = run_fanuc(program);
  auto ngc = dialect_test::run_in("rs274ngc", program, {}, {});
  ASSERT_TRUE(fanuc->ok) << fanuc->first_error_text();
  ASSERT_TRUE(ngc->ok);
  ASSERT_EQ(fanuc->ends().size(), 2u);
  EXPECT_EQ(fanuc->ends()[0].x, 0.75);
  EXPECT_EQ(fanuc->ends()[0].y, 1.4833);
  EXPECT_EQ(fanuc->ends()[0].z, -0.7487);
  EXPECT_EQ(fanuc->ends()[1].x, 1.4833);
  EXPECT_EQ(fanuc->ends(), ngc->ends());
  // Blanks and a comment inside a number read as nothing.
  auto spaced = run_fanuc("G1 X1 4.7(C)5 F1.\nM30\n");
  ASSERT_TRUE(spaced->ok) << spaced->first_error_text();
  EXPECT_EQ(spaced->ends().back().x, 14.75);
}

}  // namespace
}  // namespace usina::gcode::fanuc_test
