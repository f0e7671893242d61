// The fanuc front end reads a block in one pass (docs/fanuc.md §1): the
// units a ROUND at an address rounds in are those of the block's words read
// so far, and a column after many comments is found by a search. These pin
// what the linear reading must keep; the length limit itself is in
// program_text_test.cpp.
#include <string>

#include <gtest/gtest.h>

#include "fanuc_test_support.hpp"
#include "gcode/program_text.hpp"

namespace usina::gcode::fanuc_test {
namespace {

using core::Code;

TEST(FanucLongBlock, RoundAtAnAddressUsesTheUnitsOfTheWordsBeforeIt) {
  // G20 before X in the block: 0.0001 in; G21 after G20 in the block: mm.
  auto inch = run_fanuc("#1 = 1.23456\nG20 X[ROUND[#1]]\nM30\n");
  ASSERT_TRUE(inch->ok) << inch->first_error_text();
  expect_end(*inch, {1.2346 * 25.4, 0, 0});
  auto back = run_fanuc("#1 = 1.23456\nG20\nG21 X[ROUND[#1]]\nM30\n");
  ASSERT_TRUE(back->ok) << back->first_error_text();
  expect_end(*back, {1.235, 0, 0});
  // G20 after the word comes too late for it: 0.001 mm... in inches.
  auto late = run_fanuc("#1 = 1.23456\nX[ROUND[#1]] G20\nM30\n");
  ASSERT_TRUE(late->ok) << late->first_error_text();
  expect_end(*late, {1.235 * 25.4, 0, 0});
}

TEST(FanucLongBlock, ColumnsAfterManyCommentsPointAtTheWord) {
  // Each comment is taken out of the block's copy; the column of the
  // bad word is found again after all of them.
  std::string line = "G0";
  for (int i = 0; i < 200; ++i)
    line += " X1. (c" + std::to_string(i) + ")";
  const std::size_t col = line.size() + 2;
  line += " $";
  auto r = run_fanuc(line + "\nM30\n");
  EXPECT_EQ(r->first_error(), Code::UnexpectedCharacter);
  bool seen = false;
  for (const core::Diagnostic& d : r->diags.all()) {
    if (d.code != Code::UnexpectedCharacter) continue;
    EXPECT_EQ(d.loc.col, col);
    seen = true;
  }
  EXPECT_TRUE(seen);
}

TEST(FanucLongBlock, AMacroExpressionUpToTheLimitRuns) {
  // A Macro B expression as long as a block may be: X[1+1+...+1].
  std::string line = "G0 X[1";
  int ones = 1;
  while (line.size() + 3 <= kMaxBlockLength) {
    line += "+1";
    ++ones;
  }
  line += "]";
  ASSERT_LE(line.size(), kMaxBlockLength);
  auto r = run_fanuc(line + "\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {static_cast<double>(ones), 0, 0});
}

}  // namespace
}  // namespace usina::gcode::fanuc_test
