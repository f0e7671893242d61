// post/block_out.hpp: numbers as a control reads them. A rounded number's
// digits are written from its whole number of increments, not by
// std::to_chars: every value must come out as to_chars writes it.
#include "post/block_out.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>

namespace usina::post {
namespace {

// The reference: to_chars in fixed notation at the control's decimals,
// trailing zeros and a bare point left out (the point kept where the
// control always writes one).
std::string by_to_chars(const Control& c, double r) {
  char buf[400];
  const auto res = std::to_chars(buf, buf + sizeof buf, r, std::chars_format::fixed, c.decimals);
  char* end = res.ptr;
  if (c.decimals > 0) {
    while (end[-1] == '0')
      --end;
    if (end[-1] == '.' && !c.always_point) --end;
  } else if (c.always_point) {
    *end++ = '.';
  }
  return "X" + std::string(buf, end);
}

std::vector<double> values() {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> v = {0.0,          -0.0,
                           0.0005,       -0.0005,
                           0.00049999,   0.5,
                           -0.5,         1.0,
                           -1.0,         10.0,
                           123.4565,     -123.4565,
                           1e-7,         -1e-7,
                           999.9995,     1e9,
                           -1e9,         1e15,
                           -1e15,        9.99999e14,
                           1e20,         -1e300,
                           inf,          -inf,
                           std::nan(""), 4503599627370496.0,
                           0.1 + 0.2,    2.675,
                           1.005};
  std::mt19937_64 rng(19);  // fixed: the same values every run
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-8, 16);
  for (int i = 0; i < 20000; ++i)
    v.push_back(mantissa(rng) * std::pow(10.0, exponent(rng)));
  return v;
}

TEST(BlockOut, NumbersAreWrittenAsToCharsWritesThem) {
  const std::vector<double> vs = values();
  for (int decimals = 0; decimals <= 6; ++decimals) {
    for (const bool point : {false, true}) {
      Control c;
      c.decimals = decimals;
      c.always_point = point;
      std::ostringstream sink;
      const BlockOut out(sink, c, false);
      for (const double v : vs) {
        const double r = out.rounded(v);
        std::string words;
        out.append_rounded(words, 'X', r);
        ASSERT_EQ(words, by_to_chars(c, r)) << v << " at " << decimals << " decimals";
        // A value rounded() did not make goes by to_chars too.
        std::string raw;
        out.append_rounded(raw, 'X', v);
        ASSERT_EQ(raw, by_to_chars(c, v)) << v << " at " << decimals << " decimals";
      }
    }
  }
}

}  // namespace
}  // namespace usina::post
