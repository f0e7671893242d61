// A romi block's evaluated words (romi/words.hpp): what a handler takes,
// what is left for the move, and that nothing of an earlier block shows
// through (a letter the block did not give reads 0, column 0).
#include "gcode/romi/words.hpp"

#include <gtest/gtest.h>

#include "romi_test_support.hpp"

namespace usina::gcode::romi {
namespace {

TEST(RomiWords, ALetterOfAnEarlierBlockIsNotGiven) {
  Words w;
  w.set('R', 5.0, true, 17);
  w.reset();
  EXPECT_FALSE(w.has('R'));
  EXPECT_EQ(w.get('R'), 0.0);
  EXPECT_EQ(w.col('R'), 0u);
  EXPECT_FALSE(w.incremental('R'));
  EXPECT_FALSE(w.take('R').has_value());
}

TEST(RomiWords, TakenLettersAreForgottenButKeepTheirColumn) {
  Words w;
  w.set('X', 1.0, false, 3);
  w.set('Z', 2.0, true, 9);
  ASSERT_EQ(w.take('Z'), 2.0);
  EXPECT_TRUE(w.has('Z'));
  EXPECT_FALSE(w.open('Z'));
  EXPECT_EQ(w.untaken(), 'X');
  w.forget_taken();
  EXPECT_FALSE(w.has('Z'));
  EXPECT_EQ(w.col('Z'), 9u);
  EXPECT_TRUE(w.incremental('Z'));
  EXPECT_TRUE(w.open('X'));
  w.take('X');
  EXPECT_EQ(w.untaken(), 0);
}

TEST(RomiWords, AnErrorAboutALetterTheBlockLacksPointsAtTheBlock) {
  // G81's R (column 17) must not lend its column to the G26 block, whose
  // corner radius defaults to the tool's.
  const std::string text = "T1 M06 ;d20#G81 R2 Z5#G80 F100#G26 X5 Y5 Z-5#M02#";
  auto r = romi_test::run_romi(text);
  ASSERT_EQ(r->first_error(), core::Code::BadWordValue);
  for (const core::Diagnostic& d : r->diags.all()) {
    if (d.severity != core::Severity::Error) continue;
    EXPECT_EQ(d.loc.col, text.find("G26") + 1);
  }
}

TEST(RomiWords, TheBlockIsEvaluatedWholeBeforeItsCodesAreChecked) {
  // As the interpreter does (the entry below the text): X's value, out of
  // range, is found in step 1, before the unknown G99 of step 2.
  const std::string text = "(P1 = 1000000 * 1000000)#G99 X P1#M02#";
  auto r = romi_test::run_romi(text);
  ASSERT_EQ(r->first_error(), core::Code::ValueOutOfRange);
  EXPECT_EQ(r->diags.all().front().loc.col, text.find("X P1") + 1);
}

TEST(RomiWords, ALowerCaseWordIsAnIncrementForItsBlockAlone) {
  auto r = romi_test::run_romi("G00 X10#G00 x5 Y2#G00 X1#M02#");
  ASSERT_TRUE(r->ok);
  const auto t = r->all<canon::Traverse>();
  ASSERT_EQ(t.size(), 3u);
  EXPECT_DOUBLE_EQ(t[1].to.x, 15.0);
  EXPECT_DOUBLE_EQ(t[1].to.y, 2.0);
  EXPECT_DOUBLE_EQ(t[2].to.x, 1.0);
}

}  // namespace
}  // namespace usina::gcode::romi
