// Decimal numbers as every dialect's reader reads them: digits with at
// most one point ("12", "1.5", "1.", ".5"), the value correctly rounded, the
// one std::from_chars gives. One routine, so the same digits give the same
// double in rs274ngc, fanuc, grbl and romi (fanuc's readers once added
// digit by digit: "0.75" read as 0.7500000000000001).
//
// Most numbers of a program have at most 15 significant digits: then the
// value is mantissa / 10^k, two exact operands and one correctly rounded
// division, read in one pass (hot: every word of every block). Longer ones
// go to from_chars.
#pragma once

#include <array>
#include <charconv>
#include <cstdint>
#include <limits>
#include <string_view>

namespace usina::gcode {

struct Decimal {
  std::size_t end = 0;     // one past the number's last digit or point
  std::size_t digits = 0;  // before and after the point; 0: no number here
  bool point = false;
  // Correctly rounded; +infinity beyond the range of a double, 0 below it.
  double value = 0.0;
};

namespace decimal_detail {

// Digits a double holds exactly, and the powers of ten that are exact.
inline constexpr std::size_t kExactDigits = 15;
inline constexpr std::array<double, kExactDigits + 1> kPow10 = {
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};

// What c is worth as a digit; above 9 when it is none. The digit is the
// loop's test and its value at once: nine instructions a digit, not twelve.
inline unsigned digit_value(char c) {
  return static_cast<unsigned>(static_cast<unsigned char>(c)) - unsigned{'0'};
}

// More than 15 digits: from_chars, and out of range said as a value.
inline double long_value(const char* first, const char* last) {
  double v = 0.0;
  const auto r = std::from_chars(first, last, v);
  if (r.ec != std::errc::result_out_of_range) return v;
  // Out of range: too large if a digit before the point is not 0, else too small.
  for (const char* p = first; p < last && *p != '.'; ++p) {
    if (*p != '0') return std::numeric_limits<double>::infinity();
  }
  return 0.0;
}

}  // namespace decimal_detail

// The number at s[i]: digits with at most one point, no blanks. Its
// `digits` is 0 when none is there (a lone point has no digits).
inline Decimal scan_decimal(std::string_view s, std::size_t i) {
  using namespace decimal_detail;
  const char* p = s.data();
  const std::size_t n = s.size();
  std::uint64_t mantissa = 0;  // wraps past 19 digits, but then unused
  std::size_t j = i;
  for (; j < n; ++j) {
    const unsigned digit = digit_value(p[j]);
    if (digit > 9) break;
    mantissa = mantissa * 10 + digit;
  }
  Decimal d;
  d.digits = j - i;
  std::size_t decimals = 0;
  d.point = j < n && p[j] == '.';
  if (d.point) {
    const std::size_t first = ++j;
    for (; j < n; ++j) {
      const unsigned digit = digit_value(p[j]);
      if (digit > 9) break;
      mantissa = mantissa * 10 + digit;
    }
    decimals = j - first;
    d.digits += decimals;
  }
  d.end = j;
  if (d.digits == 0) return d;
  d.value = d.digits <= kExactDigits ? static_cast<double>(mantissa) / kPow10[decimals]
                                     : long_value(p + i, p + j);
  return d;
}

}  // namespace usina::gcode
