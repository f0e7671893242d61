// The fanuc tape read where it stands (fanuc/tape.hpp): blocks cut as they
// are read, O blocks found as far as a call needs, DO/END and GOTO targets
// found once per site.
#include "gcode/fanuc/tape.hpp"

#include <string>

#include <gtest/gtest.h>

#include "fanuc_test_support.hpp"

namespace usina::gcode {
namespace {

using core::Code;
using fanuc_test::run_fanuc;

// The tape is scanned several characters at a time for the characters that
// end or interrupt a block: each of them is found wherever it stands after
// a block's words, at every offset a scan step may leave it.
TEST(FanucTape, ABlockEndsWhereverItsEndStands) {
  const std::string kWords = "G1X2Y3Z4F5G1X2Y3Z4F5G1X2Y3";
  for (std::size_t n = 1; n <= 24; ++n) {
    const std::string words = kWords.substr(0, n);
    for (const char* end : {";", "\n"}) {
      const std::string text = words + end + "G0";
      fanuc::Tape tape;
      const fanuc::TapeBlock b = tape.cut(tape.add_file(0, text));
      EXPECT_EQ(b.text, words) << text;
      EXPECT_EQ(b.next.offset, n + 1) << text;
      EXPECT_EQ(tape.cut(b.next).text, "G0") << text;
    }
    fanuc::Tape commented;
    const std::string with_comment = words + "(NOTE;1)  \nG0";
    const fanuc::TapeBlock c = commented.cut(commented.add_file(0, with_comment));
    EXPECT_EQ(c.text, words) << with_comment;
    EXPECT_EQ(c.comment, "NOTE;1") << with_comment;
    EXPECT_EQ(commented.cut(c.next).text, "G0") << with_comment;
    fanuc::Tape closed;
    const std::string with_percent = words + "%G0";
    const fanuc::TapeBlock p = closed.cut(closed.add_file(0, with_percent));
    EXPECT_EQ(p.text, words) << with_percent;
    const fanuc::TapeBlock after = closed.cut(p.next);
    EXPECT_TRUE(after.end && after.closed) << with_percent;
  }
}

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

namespace usina::gcode {
namespace {

// A block of letters and plain numbers is read without the macro reader
// (fanuc/nc.cpp): its values are the macro reader's, to the last bit.
TEST(FanucPlainWords, APlainBlockReadsAsTheMacroReaderReadsIt) {
  const char* plain = "G1 X1.4833 Y-0.0167 Z-.3 F600.\nX123.4567 Y2 Z0.0001\nM30\n";
  const char* macro =
      "G1 X[1.4833] Y-[0.0167] Z-[.3] (C) F600.\nX1 23.4567 Y#0 Y2 Z[0.0001]\nM30\n";
  auto a = fanuc_test::run_fanuc(plain);
  auto b = fanuc_test::run_fanuc(macro);
  ASSERT_TRUE(a->ok) << a->first_error_text();
  ASSERT_TRUE(b->ok) << b->first_error_text();
  ASSERT_EQ(a->ends().size(), 2u);
  ASSERT_EQ(b->ends().size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(a->ends()[i].x, b->ends()[i].x);
    EXPECT_EQ(a->ends()[i].y, b->ends()[i].y);
    EXPECT_EQ(a->ends()[i].z, b->ends()[i].z);
  }
}

TEST(FanucPlainWords, AWordBeyondTheRangeIsAnErrorAtItsWord) {
  auto r = fanuc_test::run_fanuc("G1 X1. F100.\nG1 X99999999999999999999.\nM30\n");
  EXPECT_EQ(r->first_error(), core::Code::ValueOutOfRange);
}

}  // namespace
}  // namespace usina::gcode
