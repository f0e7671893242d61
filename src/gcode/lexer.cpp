#include "gcode/lexer.hpp"

#include <array>
#include <charconv>

namespace usina::gcode {
namespace {

char upper(char c) {
  return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
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
