// The romi parser's shortcut for plain blocks (parse_plain_romi_block): the
// same block the whole parser makes, or no shortcut at all.
#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "core/diagnostic.hpp"
#include "gcode/romi/syntax.hpp"
#include "support/random_block.hpp"

namespace usina::gcode::romi {
namespace {

std::size_t first_non_blank(std::string_view s) {
  std::size_t i = 0;
  while (i < s.size() && (s[i] == ' ' || s[i] == '\t'))
    ++i;
  return i;
}

// The whole parser's reading is the same block with a ';' comment after
// it, which the shortcut never takes.
TEST(RomiSyntaxShortcut, ReadsAsTheWholeParser) {
  std::mt19937 rng(5);
  int shortcut = 0;
  for (int n = 0; n < 20000; ++n) {
    const std::string text =
        test::random_block(rng, "GXYZFNPEex0123456789.-+ \t()[];", "NGXYZFEAP");
    RomiBlock plain;
    if (!parse_plain_romi_block(text, 3, first_non_blank(text), plain)) continue;
    ++shortcut;
    const std::string with_comment = text + ";";
    RomiBlock whole;
    core::DiagnosticList diags;
    ASSERT_TRUE(parse_romi_block(with_comment, {0, 1, 0}, 3, whole, diags)) << text;
    EXPECT_EQ(plain.base.line_number, whole.base.line_number) << text;
    ASSERT_EQ(plain.words.size(), whole.words.size()) << text;
    // The shortcut keeps a value in its word where the whole parser makes
    // a number node.
    EXPECT_TRUE(plain.base.exprs.empty()) << text;
    for (std::size_t i = 0; i < plain.words.size(); ++i) {
      const RomiWord& a = plain.words[i];
      const RomiWord& b = whole.words[i];
      EXPECT_EQ(a.letter, b.letter) << text;
      EXPECT_EQ(a.lower, b.lower) << text;
      EXPECT_EQ(a.col, b.col) << text;
      ASSERT_EQ(a.value, kPlainNumber) << text;
      ASSERT_LT(b.value, whole.base.exprs.size()) << text;
      const ExprNode& y = whole.base.exprs[b.value];
      ASSERT_EQ(y.kind, ExprKind::Number) << text;
      EXPECT_EQ(std::signbit(a.number), std::signbit(y.value)) << text;
      EXPECT_EQ(a.number, y.value) << text;
    }
  }
  EXPECT_GT(shortcut, 3000);
}

TEST(RomiSyntaxShortcut, LeavesTheRestToTheWholeParser) {
  for (const std::string text : {"",
                                 "   ",
                                 "N10",
                                 "G1 X1 5",
                                 "G1 X 1",
                                 "G1 X- 1",
                                 "G1 X1E3",
                                 "G1 X1E400",
                                 "g1 x1",
                                 "G1 x1",
                                 "G1 XP1",
                                 "G1 X1 (c)",
                                 "G1 X1 ;c",
                                 "N10 P1",
                                 "G1 N10",
                                 "%",
                                 "G1 X.",
                                 "G1 X",
                                 "G1 X1.2.3",
                                 "G1 X1234567890.1234567",
                                 "G1 X\xE2\x88\x92"
                                 "1",
                                 "n10 G1"}) {
    RomiBlock b;
    EXPECT_FALSE(parse_plain_romi_block(text, 1, first_non_blank(text), b)) << text;
  }
  RomiBlock b;
  ASSERT_TRUE(parse_plain_romi_block("N20 G1X45.75  Y4 Z-1.4104\r", 5, 0, b));
  EXPECT_EQ(b.base.line_number, 20.0);
  ASSERT_EQ(b.words.size(), 4u);
  EXPECT_EQ(b.words[1].letter, 'X');
  EXPECT_EQ(b.words[1].col, 11u);  // column 5 is the block's first character
  EXPECT_EQ(b.words[3].value, kPlainNumber);
  EXPECT_EQ(b.words[3].number, -1.4104);
}

}  // namespace
}  // namespace usina::gcode::romi
