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

void Lexer::skip_blanks() {
  while (i_ < text_.size() && is_blank(text_[i_]))
    ++i_;
}

std::size_t Lexer::pos() {
  skip_blanks();
  return i_;
}

char Lexer::peek() {
  skip_blanks();
  return i_ < text_.size() ? upper(text_[i_]) : '\0';
}

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
  std::size_t j = start;
  std::array<char, 64> buf{};
  std::size_t n = 0;
  bool point = false;
  bool digits = false;
  bool blanks = false;
  while (j < text_.size()) {
    const char c = text_[j];
    if (is_digit(c)) {
      digits = true;
    } else if (c == '.' && !point) {
      point = true;
    } else if (is_blank(c)) {
      blanks = true;
      ++j;
      continue;
    } else {
      break;
    }
    if (n < buf.size()) buf[n++] = c;
    ++j;
  }
  if (!digits || (blanks && n >= buf.size())) return std::nullopt;
  // Trailing blanks belong to nobody; leave them to be skipped.
  while (j > start && is_blank(text_[j - 1]))
    --j;
  double v = 0.0;
  const char* first = blanks ? buf.data() : text_.data() + start;
  const char* last = blanks ? buf.data() + n : text_.data() + j;
  const auto res = std::from_chars(first, last, v);
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
