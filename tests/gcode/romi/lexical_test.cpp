// The romi dialect's lexical rules and start state (spec/romi.md,
// "Lexical", "Modal state at start").
#include "gcode/romi/syntax.hpp"
#include "romi_test_support.hpp"

namespace usina::gcode::romi_test {
namespace {

using core::Code;

TEST(RomiLexical, HashEndsABlockAsANewlineDoes) {
  auto r = run_romi("G01 X10 F100#Y20#\nX5#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  expect_near(e[0], {10, 0, 0});
  expect_near(e[1], {10, 20, 0});
  expect_near(e[2], {5, 20, 0});
  // The second block of line 1 starts at column 17.
  EXPECT_EQ(r->path.ops()[1].src.line, 1u);
  EXPECT_EQ(r->path.ops()[1].src.col, 14u);
}

TEST(RomiLexical, SemicolonCommentRunsToTheBlockEnd) {
  auto r = run_romi("G00 X1;first#Y2;second\nM02");
  ASSERT_TRUE(r->ok);
  const auto c = r->all<canon::Comment>();
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].text, "first");
  EXPECT_EQ(c[1].text, "second");
  expect_near(r->ends().back(), {1, 2, 0});
}

TEST(RomiLexical, PercentLineIgnoredAndNOptional) {
  auto r = run_romi("%\nN10 G00 X1#G00 X2#N0030 X3#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  EXPECT_EQ(r->ends().size(), 3u);
}

TEST(RomiLexical, BareLetterMeansZero) {
  auto r = run_romi("G01 X5 F100#G X10#M02#");
  ASSERT_TRUE(r->ok);
  ASSERT_EQ(r->path.ops().size(), 3u);  // feed, traverse, end
  EXPECT_TRUE(std::holds_alternative<canon::Traverse>(r->path.ops()[1].kind));
}

TEST(RomiLexical, LowerCaseAxisIsIncrementalForThatWord) {
  auto r = run_romi("G00 X100 Y10#x50 Y20#M02#");
  ASSERT_TRUE(r->ok);
  expect_near(r->ends().back(), {150, 20, 0});
}

TEST(RomiLexical, LowerCaseIncrementalCanBeTurnedOff) {
  auto r = run_romi("G00 X100#x50#M02#", {}, {"lowercase_incremental=off"});
  ASSERT_TRUE(r->ok);
  expect_near(r->ends().back(), {50, 0, 0});
}

TEST(RomiLexical, TypographicDashIsAMinusWithAWarning) {
  for (const char* dash : {"\xE2\x80\x93", "\xE2\x80\x94", "\xE2\x88\x92"}) {
    auto r = run_romi(std::string("G00 Y") + dash + "250.#M02#");
    ASSERT_TRUE(r->ok);
    expect_near(r->ends().back(), {0, -250, 0});
    ASSERT_TRUE(r->has(Code::TypographicDash));
  }
}

TEST(RomiLexical, TypographicDashInAStatement) {
  auto r = run_romi(
      "(P1 = \xE2\x88\x92"
      "4 * 2)#G00 X P1#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_near(r->ends().back(), {-8, 0, 0});
  EXPECT_TRUE(r->has(Code::TypographicDash));
}

TEST(RomiLexical, ByteOrderMarkIsSkippedWithAWarning) {
  auto r = run_romi("\xEF\xBB\xBFG00 X1#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  EXPECT_TRUE(r->has(Code::ByteOrderMark));
  expect_near(r->ends().back(), {1, 0, 0});
}

TEST(RomiLexical, CrLfLineEnds) {
  auto r = run_romi("G00 X1#\r\nY2\r\nM02#\r\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_near(r->ends().back(), {1, 2, 0});
}

// A '#' with only the newline after it ("G01 X10#", how romi lines end):
// the next block starts on the next line, with no empty block between;
// a '#' with more after it ends only its block.
TEST(RomiLexical, HashBeforeTheNewlineEndsTheLine) {
  const std::string text = "G01 X1#\nY2#\r\nZ3# \nX4#Y5#";
  romi::LineEnd line;
  const std::vector<std::pair<std::string, bool>> want = {
      {"G01 X1", true}, {"Y2", true}, {"Z3", false}, {" ", true}, {"X4", false}, {"Y5", false}};
  std::uint64_t at = 0;
  for (const auto& [block, ends_line] : want) {
    const romi::BlockText b = romi::block_at(text, at, line);
    EXPECT_EQ(b.text, block) << at;
    EXPECT_EQ(b.ends_line, ends_line) << at;
    at = b.next;
  }
  EXPECT_EQ(at, text.size());
  // Each block's line is still its own.
  auto r = run_romi("G01 X1 F100#\r\nY2#\nZ3# \nG01 Q1#\nM02#\n");
  EXPECT_EQ(r->first_error(), Code::UnusedWord);
  ASSERT_FALSE(r->diags.all().empty());
  EXPECT_EQ(r->diags.all().front().loc.line, 4u);
  ASSERT_EQ(r->ends().size(), 3u);
  EXPECT_EQ(r->path.ops()[1].src.line, 2u);
}

TEST(RomiLexical, TypographicDashCanBeAnError) {
  auto r = run_romi(
      "G00 Y\xE2\x80\x93"
      "250.#M02#",
      {}, {"typographic_dash=error"});
  EXPECT_FALSE(r->ok);
  EXPECT_EQ(r->first_error(), Code::TypographicDash);
}

TEST(RomiLexical, NumbersWithoutPointAreMillimetres) {
  auto r = run_romi("G00 X500#M02#");
  expect_near(r->ends().back(), {500, 0, 0});
}

TEST(RomiLexical, StartsInG00G90MmAndG70IsInch) {
  auto r = run_romi("X10#G70 X1#G71 G91 X1#M02#");
  ASSERT_TRUE(r->ok);
  const auto e = r->ends();
  ASSERT_EQ(r->all<canon::Traverse>().size(), 3u);
  expect_near(e[1], {25.4, 0, 0});
  expect_near(e[2], {26.4, 0, 0});
}

TEST(RomiLexical, G99AndG98AreAccepted) {
  auto r = run_romi("G99#G98#G17#M02#");
  EXPECT_TRUE(r->ok) << r->first_error_text();
}

TEST(RomiLexical, UnknownCodeIsAnError) {
  auto r = run_romi("G18#M02#");
  EXPECT_EQ(r->first_error(), Code::UnknownGCode);
}

TEST(RomiLexical, UnusedWordIsAnError) {
  auto r = run_romi("G00 X1 L5#M02#");
  EXPECT_EQ(r->first_error(), Code::UnusedWord);
}

TEST(RomiLexical, ParameterAloneIsASyntaxError) {
  auto r = run_romi("P1#M02#");
  EXPECT_EQ(r->first_error(), Code::UnknownWord);
}

TEST(RomiLexical, UnclosedParenthesisIsAnError) {
  auto r = run_romi("(P1 = 2#M02#");
  EXPECT_EQ(r->first_error(), Code::UnclosedComment);
}

TEST(RomiLexical, NoProgramEndIsAWarning) {
  auto r = run_romi("G00 X1#");
  EXPECT_TRUE(r->ok);
  EXPECT_TRUE(r->has(Code::NoProgramEnd));
}

}  // namespace
}  // namespace usina::gcode::romi_test
