// The fanuc tape read where it stands (fanuc_tape.hpp): blocks cut as they
// are read, O blocks found as far as a call needs, DO/END and GOTO targets
// found once per site.
#include <gtest/gtest.h>

#include "fanuc_test_support.hpp"

namespace usina::gcode {
namespace {

using core::Code;
using fanuc_test::run_fanuc;

TEST(FanucTape, ALeaderOfCommentsBeforeTheOBlockBelongsToTheProgram) {
  auto r = run_fanuc("%\n(HEADER)\n(POSTED BY CAM)\nO1000\nG0 X1.\nM30\n%\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  EXPECT_FALSE(r->has(Code::NoProgramEnd));
  ASSERT_EQ(r->ends().size(), 1u);
  EXPECT_NEAR(r->ends()[0].x, 1.0, 1e-9);
}

TEST(FanucTape, TheNextOBlockEndsTheMainProgram) {
  auto r = run_fanuc("%\nO1000\nG0 X1.\nO2000\nG0 X2.\nM99\n%\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  EXPECT_TRUE(r->has(Code::NoProgramEnd));
  ASSERT_EQ(r->ends().size(), 1u);
}

TEST(FanucTape, ASubprogramAfterTheMainProgramIsFoundAndRunsEachCall) {
  auto r = run_fanuc(
      "%\nO1000\nM98 P2000\nM98 P3000\nM98 P2000\nM30\n"
      "O2000\nG91 G0 X1.\nG90\nM99\nO3000\nG0 Y5.\nM99\n%\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  ASSERT_EQ(r->ends().size(), 3u);
  EXPECT_NEAR(r->ends()[1].y, 5.0, 1e-9);
  EXPECT_NEAR(r->ends()[2].x, 2.0, 1e-9);
}

TEST(FanucTape, AGotoSiteTakenManyTimesWithDifferentTargets) {
  // One GOTO site, two numbers: each target is its own.
  auto r = run_fanuc(
      "%\nO1000\n#1 = 0\nN10 #1 = #1 + 1\nIF [#1 GT 4] GOTO 30\n#2 = 20 - [#1 AND 0]\n"
      "GOTO [10 + 10 * [#1 EQ 3]]\nN20 G0 X#1\nGOTO 10\nN30 M30\n%\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  // #1 = 1, 2 reach N10 again at once; #1 = 3 goes to N20 (X3); 4 at once.
  ASSERT_EQ(r->ends().size(), 1u);
  EXPECT_NEAR(r->ends()[0].x, 3.0, 1e-9);
}

TEST(FanucTape, NestedLoopsRunFromTheirDoBlocks) {
  auto r = run_fanuc(
      "%\nO1000\n#1 = 0\n#3 = 0\nWHILE [#1 LT 3] DO 1\n#2 = 0\nWHILE [#2 LT 4] DO 2\n"
      "#3 = #3 + 1\n#2 = #2 + 1\nEND 2\n#1 = #1 + 1\nEND 1\nG0 X#3\nM30\n%\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  ASSERT_EQ(r->ends().size(), 1u);
  EXPECT_NEAR(r->ends()[0].x, 12.0, 1e-9);
}

TEST(FanucTape, M99PReturnsToItsBlockFromEachCallSite) {
  auto r = run_fanuc(
      "%\nO1000\nM98 P2000\nG0 X1.\nN5 G0 Y1.\nM98 P2000\nG0 X2.\nN5 G0 Y2.\nM30\n"
      "O2000\nM99 P5\n%\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  // M99 P5 returns to the first N5 after the call: X1 and X2 are skipped.
  ASSERT_EQ(r->ends().size(), 2u);
  EXPECT_NEAR(r->ends()[0].y, 1.0, 1e-9);
  EXPECT_NEAR(r->ends()[1].y, 2.0, 1e-9);
  EXPECT_NEAR(r->ends()[1].x, 0.0, 1e-9);
}

}  // namespace
}  // namespace usina::gcode
