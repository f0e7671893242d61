#include "gcode/lexer.hpp"

#include <array>
#include <charconv>

namespace usina::gcode {
namespace {

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

char upper(char c) {
  return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
}

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

}  // namespace

char Lexer::peek_second() {
  skip_blanks();
  std::size_t j = i_ + 1;
  while (j < text_.size() && is_blank(text_[j]))
    ++j;
  return j < text_.size() ? upper(text_[j]) : '\0';
}

bool Lexer::accept(char c) {
  if (peek() != c) return false;
  ++i_;
  return true;
}

bool Lexer::accept_keyword(std::string_view keyword) {
  std::size_t j = pos();
  for (const char k : keyword) {
    while (j < text_.size() && is_blank(text_[j]))
      ++j;
    if (j >= text_.size() || upper(text_[j]) != k) return false;
    ++j;
  }
  i_ = j;
  return true;
}

std::optional<double> Lexer::number() {
  const std::size_t start = pos();
  // Fast path, the shape of nearly every number in a program: digits with
  // at most one point, no blanks, at most 15 significant digits. The value
  // is mantissa / 10^k, exact operands and one correctly rounded division,
  // so it equals what from_chars gives.
  static constexpr std::array<double, 16> kPow10 = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                                    1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
  std::uint64_t mantissa = 0;
  int digits = 0;
  int decimals = 0;
  bool point = false;
  std::size_t j = start;
  for (; j < text_.size(); ++j) {
    const char c = text_[j];
    if (is_digit(c)) {
      if (++digits > 15) return number_slow(start);
      mantissa = mantissa * 10 + static_cast<std::uint64_t>(c - '0');
      if (point) ++decimals;
    } else if (c == '.' && !point) {
      point = true;
    } else {
      break;
    }
  }
  // Blanks inside a number ("1 . 5") are legal RS274NGC: the slow path.
  if (j < text_.size() && is_blank(text_[j])) {
    std::size_t k = j;
    while (k < text_.size() && is_blank(text_[k]))
      ++k;
    if (k < text_.size() && (is_digit(text_[k]) || (text_[k] == '.' && !point))) {
      return number_slow(start);
    }
  }
  if (digits == 0) return std::nullopt;
  i_ = j;
  return static_cast<double>(mantissa) / kPow10[static_cast<std::size_t>(decimals)];
}

std::optional<double> Lexer::number_slow(std::size_t start) {
  std::size_t j = start;
  std::array<char, 64> buf{};
  std::size_t n = 0;
  bool point = false;
  bool digits = false;
  while (j < text_.size()) {
    const char c = text_[j];
    if (is_digit(c)) {
      digits = true;
    } else if (c == '.' && !point) {
      point = true;
    } else if (is_blank(c)) {
      ++j;
      continue;
    } else {
      break;
    }
    if (n == buf.size()) return std::nullopt;  // longer than any real number
    buf[n++] = c;
    ++j;
  }
  if (!digits) return std::nullopt;
  // Trailing blanks belong to nobody; leave them to be skipped.
  while (j > start && is_blank(text_[j - 1]))
    --j;
  double v = 0.0;
  const auto res = std::from_chars(buf.data(), buf.data() + n, v);
  if (res.ec != std::errc()) return std::nullopt;
  i_ = j;
  return v;
}

std::optional<std::string_view> Lexer::until(char close) {
  const std::size_t start = i_;
  const std::size_t end = text_.find(close, start);
  if (end == std::string_view::npos) {
    i_ = text_.size();
    return std::nullopt;
  }
  i_ = end + 1;
  return text_.substr(start, end - start);
}

std::string_view Lexer::rest() {
  const std::string_view r = text_.substr(i_);
  i_ = text_.size();
  return r;
}

}  // namespace usina::gcode
