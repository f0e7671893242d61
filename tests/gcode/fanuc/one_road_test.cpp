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

}  // namespace
}  // namespace usina::gcode::fanuc_test
