#include "gcode/lexer.hpp"

#include <charconv>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

namespace usina::gcode {
namespace {

TEST(Lexer, PeekSkipsBlanksAndUpperCases) {
  Lexer lex(" \t g1");
  EXPECT_EQ(lex.peek(), 'G');
  EXPECT_EQ(lex.pos(), 3u);
}

TEST(Lexer, CarriageReturnIsABlank) {
  Lexer lex("\r\rx");
  EXPECT_EQ(lex.peek(), 'X');
}

TEST(Lexer, PeekAtTheEndIsNul) {
  Lexer lex("   ");
  EXPECT_EQ(lex.peek(), '\0');
  EXPECT_TRUE(lex.at_end());
}

TEST(Lexer, PeekSecondSkipsBlanksBetween) {
  Lexer lex("o  1");
  EXPECT_EQ(lex.peek_second(), '1');
  Lexer one("x");
  EXPECT_EQ(one.peek_second(), '\0');
}

TEST(Lexer, AcceptConsumesOnlyTheGivenCharacter) {
  Lexer lex("  [1]");
  EXPECT_FALSE(lex.accept(']'));
  EXPECT_TRUE(lex.accept('['));
  EXPECT_EQ(lex.peek(), '1');
}

TEST(Lexer, AcceptUpperCaseMatchesLowerCaseText) {
  Lexer lex("g");
  EXPECT_TRUE(lex.accept('G'));
  EXPECT_TRUE(lex.at_end());
}

TEST(Lexer, NumberPlainDecimal) {
  Lexer lex("12.5X");
  const auto v = lex.number();
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(*v, 12.5);
  EXPECT_EQ(lex.peek(), 'X');
}

TEST(Lexer, NumberWithBlanksInsideIsOneNumber) {
  // RS274NGC ignores blanks everywhere outside comments: "1 . 5" is 1.5.
  Lexer lex("1 . 5 Y");
  const auto v = lex.number();
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(*v, 1.5);
  EXPECT_EQ(lex.peek(), 'Y');
}

TEST(Lexer, DigitsSeparatedByBlanksJoin) {
  Lexer lex("1 2 3");
  const auto v = lex.number();
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(*v, 123.0);
  EXPECT_TRUE(lex.at_end());
}

TEST(Lexer, NumberLeadingAndTrailingPoint) {
  Lexer a(".5");
  EXPECT_EQ(a.number(), 0.5);
  Lexer b("5.");
  EXPECT_EQ(b.number(), 5.0);
}

TEST(Lexer, NumberStopsAtASecondPoint) {
  Lexer lex("1.2.3");
  EXPECT_EQ(lex.number(), 1.2);
  EXPECT_EQ(lex.peek(), '.');
}

TEST(Lexer, NumberWithoutDigitsConsumesNothing) {
  Lexer lex(" . X");
  EXPECT_FALSE(lex.number().has_value());
  EXPECT_EQ(lex.peek(), '.');
}

TEST(Lexer, NumberIsUnsigned) {
  Lexer lex("-1");
  EXPECT_FALSE(lex.number().has_value());
  EXPECT_EQ(lex.peek(), '-');
}

TEST(Lexer, TrailingBlanksAfterANumberAreLeft) {
  Lexer lex("12   ");
  EXPECT_EQ(lex.number(), 12.0);
  EXPECT_EQ(lex.pos(), 5u);
  EXPECT_TRUE(lex.at_end());
}

// Whatever path the lexer takes, a number is the double nearest its decimal
// text, as std::from_chars gives it.
double nearest(const std::string& text) {
  double v = 0.0;
  std::from_chars(text.data(), text.data() + text.size(), v);
  return v;
}

TEST(Lexer, NumbersAreCorrectlyRounded) {
  for (const std::string t : {"0.1", "0.3", "25.4", "3.14159265358979", "123456789012345",
                              "1234567890123456.7", "0.000000000000000001", "9007199254740993",
                              "99999.999999999999", "1.0000000000000002220446"}) {
    Lexer lex(t);
    const auto v = lex.number();
    ASSERT_TRUE(v.has_value()) << t;
    EXPECT_EQ(*v, nearest(t)) << t;
    EXPECT_TRUE(lex.at_end()) << t;
  }
}

TEST(Lexer, NumberWithBlanksIsCorrectlyRounded) {
  Lexer lex("0 . 1 2 3 4 5 6 7 8 9 0 1 2 3 4 5 6 7");
  EXPECT_EQ(lex.number(), nearest("0.12345678901234567"));
}

TEST(Lexer, NumberOfSixtyFourCharactersIsRead) {
  const std::string t = std::string(62, '0') + "15";
  Lexer lex(t);
  EXPECT_EQ(lex.number(), 15.0);
}

TEST(Lexer, NumberLongerThanSixtyFourCharactersIsRefusedNotTruncated) {
  // A longer number is no real program's; it must not be read as a prefix.
  const std::string t = std::string(70, '0') + "15";
  Lexer lex(t);
  EXPECT_FALSE(lex.number().has_value());
  EXPECT_EQ(lex.pos(), 0u);
}

// The one-pass reader of plain numbers (lexer.hpp) and its edges: what it
// leaves to the slow path must read the same.
TEST(Lexer, NumberEdgesOfTheFastPath) {
  struct Case {
    const char* text;
    double value;
    std::size_t end;  // where the lexer stands after it
  };

  for (const Case c : {Case{"1.", 1.0, 2}, Case{".5", 0.5, 2}, Case{"0", 0.0, 1},
                       Case{"0.0000", 0.0, 6}, Case{"007.250", 7.25, 7}, Case{"1e5", 1.0, 1},
                       Case{"2.5E-3", 2.5, 3}, Case{"12 X", 12.0, 2}, Case{"1. 5", 1.5, 4},
                       Case{". 5", 0.5, 3}, Case{"1.5 .5", 1.5, 3}, Case{"3\t", 3.0, 1}}) {
    Lexer lex(c.text);
    const auto v = lex.number();
    ASSERT_TRUE(v.has_value()) << c.text;
    EXPECT_EQ(*v, c.value) << c.text;
    EXPECT_EQ(lex.offset(), c.end) << c.text;
  }
}

TEST(Lexer, ZeroIsPositiveZero) {
  Lexer lex("0.000");
  const auto v = lex.number();
  ASSERT_TRUE(v.has_value());
  EXPECT_FALSE(std::signbit(*v));
}

TEST(Lexer, FifteenAndSixteenDigitsAreCorrectlyRounded) {
  // Fifteen digits are the fast path's, sixteen and more the slow path's.
  for (const std::string t : {"999999999999999", "9999999999999999", "0.123456789012345",
                              "0.1234567890123456", "12345678.9012345", "12345678.90123456"}) {
    Lexer lex(t);
    EXPECT_EQ(lex.number(), nearest(t)) << t;
    EXPECT_TRUE(lex.at_end()) << t;
  }
}

TEST(Lexer, DigitsBeyondAnyIntegerAreReadNotWrapped) {
  // Twenty digits overflow a 64-bit mantissa: the value must not wrap.
  const std::string t = "99999999999999999999";
  Lexer lex(t);
  EXPECT_EQ(lex.number(), nearest(t));
  const std::string tail = "0.00000000000000000001";
  Lexer small(tail);
  EXPECT_EQ(small.number(), nearest(tail));
}

TEST(Lexer, AVeryLongDigitStringIsRefusedWhole) {
  const std::string t = std::string(4000, '7') + " X";
  Lexer lex(t);
  EXPECT_FALSE(lex.number().has_value());
  EXPECT_EQ(lex.pos(), 0u);
  const std::string points = "1." + std::string(4000, '5');
  Lexer fraction(points);
  EXPECT_FALSE(fraction.number().has_value());
  EXPECT_EQ(fraction.pos(), 0u);
}

TEST(Lexer, AVeryLongNumberOfZerosBeforeItsDigitsIsTheSlowPaths) {
  const std::string t = std::string(40, '0') + "25.5";
  Lexer lex(t);
  EXPECT_EQ(lex.number(), 25.5);
  EXPECT_TRUE(lex.at_end());
}

TEST(Lexer, AcceptKeywordIsCaseInsensitiveAndAllowsBlanks) {
  Lexer lex("e n d S u B rest");
  EXPECT_TRUE(lex.accept_keyword("ENDSUB"));
  EXPECT_EQ(lex.peek(), 'R');
}

TEST(Lexer, FailedKeywordConsumesNothing) {
  Lexer lex("ENDWHILE");
  EXPECT_FALSE(lex.accept_keyword("ENDSUB"));
  EXPECT_EQ(lex.pos(), 0u);
  EXPECT_TRUE(lex.accept_keyword("ENDWHILE"));
}

TEST(Lexer, KeywordLongerThanTheTextFails) {
  Lexer lex("MO");
  EXPECT_FALSE(lex.accept_keyword("MOD"));
  EXPECT_EQ(lex.peek(), 'M');
}

TEST(Lexer, UntilReturnsRawTextAndConsumesTheClose) {
  Lexer lex("(  Hello World)G1");
  lex.advance();
  const auto t = lex.until(')');
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(*t, "  Hello World");
  EXPECT_EQ(lex.peek(), 'G');
}

TEST(Lexer, UntilWithoutCloseConsumesTheRest) {
  Lexer lex("(open");
  lex.advance();
  EXPECT_FALSE(lex.until(')').has_value());
  EXPECT_TRUE(lex.at_end());
}

TEST(Lexer, RestIsRawAndEndsTheText) {
  Lexer lex(";  Keep Case ");
  lex.advance();
  EXPECT_EQ(lex.rest(), "  Keep Case ");
  EXPECT_TRUE(lex.at_end());
}

TEST(Lexer, TextIsTheWholeInput) {
  const std::string s = "G1 X2";
  Lexer lex(s);
  lex.advance();
  EXPECT_EQ(lex.text(), s);
}

}  // namespace
}  // namespace usina::gcode
