// The one decimal reader of every dialect (gcode/decimal.hpp): the value is
// the correctly rounded one from_chars gives, whatever the digits' count.
#include "gcode/decimal.hpp"

#include <charconv>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

namespace usina::gcode {
namespace {

double from_chars_value(const std::string& s) {
  double v = 0.0;
  std::from_chars(s.data(), s.data() + s.size(), v);
  return v;
}

TEST(Decimal, ShortNumbersAreCorrectlyRounded) {
  // Digit-by-digit sums give 0.7500000000000001 and 1.4832999999999998.
  for (const std::string s : {"0.75", "1.4833", "0.1", "123.456", "99999.9999", "0.0001",
                              "12345678.1234567", "1.", ".5", "007.250"}) {
    const Decimal d = scan_decimal(s, 0);
    EXPECT_EQ(d.end, s.size()) << s;
    EXPECT_EQ(d.value, from_chars_value(s)) << s;
  }
}

TEST(Decimal, LongNumbersGoThroughFromChars) {
  const std::string s = "3.14159265358979323846264338327950288";
  const Decimal d = scan_decimal(s, 0);
  EXPECT_EQ(d.digits, s.size() - 1);
  EXPECT_EQ(d.value, from_chars_value(s));
}

TEST(Decimal, BeyondADoubleIsInfiniteAndBelowItIsZero) {
  EXPECT_TRUE(std::isinf(scan_decimal(std::string(400, '9'), 0).value));
  EXPECT_EQ(scan_decimal("0." + std::string(400, '0') + "1", 0).value, 0.0);
}

TEST(Decimal, ItStopsWhereTheNumberEnds) {
  const Decimal d = scan_decimal("X1.25.5Y", 1);
  EXPECT_EQ(d.end, 5u);
  EXPECT_TRUE(d.point);
  EXPECT_EQ(d.value, 1.25);
  const Decimal lone = scan_decimal(".Y", 0);
  EXPECT_EQ(lone.digits, 0u);
  EXPECT_TRUE(lone.point);
  EXPECT_EQ(scan_decimal("Y", 0).digits, 0u);
  EXPECT_EQ(scan_decimal("", 0).digits, 0u);
}

}  // namespace
}  // namespace usina::gcode
