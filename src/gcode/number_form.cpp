#include "gcode/number_form.hpp"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

namespace usina::gcode {
namespace {

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

}  // namespace

tl::expected<void, std::string> exponent_out_of_range(std::string_view text, std::size_t start,
                                                      std::size_t end) {
  if (end >= text.size() || (text[end] != 'e' && text[end] != 'E')) return {};
  std::size_t k = end + 1;
  const bool negative = k < text.size() && text[k] == '-';
  if (k < text.size() && (text[k] == '+' || text[k] == '-')) ++k;
  const std::size_t digits = k;
  while (k < text.size() && is_digit(text[k]))
    ++k;
  if (k == digits) return {};
  while (start < end &&
         (text[start] == '+' || text[start] == '-' || text[start] == ' ' || text[start] == '\t'))
    ++start;
  // The literal without the blanks RS274NGC allows inside numbers.
  std::string literal;
  bool nonzero = false;
  for (std::size_t i = start; i < k; ++i) {
    if (text[i] == ' ' || text[i] == '\t') continue;
    literal.push_back(text[i]);
    if (i < end && text[i] >= '1' && text[i] <= '9') nonzero = true;
  }
  double v = 0.0;
  const auto r = std::from_chars(literal.data(), literal.data() + literal.size(), v);
  const bool read = r.ec == std::errc() && r.ptr == literal.data() + literal.size();
  const bool out = r.ec == std::errc::result_out_of_range ||
                   (read && (!std::isfinite(v) || (v == 0.0 && nonzero)));
  if (!out) return {};
  const auto shown = [](std::string_view s) {
    return s.size() <= 40 ? std::string(s) : fmt::format("{}...", s.substr(0, 37));
  };
  return tl::unexpected(fmt::format(
      "number {} is out of range: {} (a double holds about ±1.8e308, down to 2.2e-308; a "
      "word's value must be within ±1e9). A program has no exponent notation: this reads as "
      "{} and an E word",
      shown(literal), negative ? "too small for any number but 0" : "too large for any number",
      shown(text.substr(start, end - start))));
}

}  // namespace usina::gcode
