// The lexer of RS274NGC text: reads one block's characters from a view into
// the source (no copies). RS274NGC ignores spaces and tabs everywhere outside
// comments and is case-insensitive, so every read skips blanks and compares
// letters in upper case.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "gcode/decimal.hpp"

namespace usina::gcode {

class Lexer {
 public:
  explicit Lexer(std::string_view text) : text_(text) {}

  // Position of the next non-blank character (0-based), or the end.
  std::size_t pos() {
    skip_blanks();
    return i_;
  }

  bool at_end() { return pos() >= text_.size(); }

  // The next non-blank character in upper case, or 0 at the end.
  char peek() {
    skip_blanks();
    if (i_ >= text_.size()) return '\0';
    const char c = text_[i_];
    return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
  }

  // The character after the next non-blank one (blanks skipped), upper case.
  char peek_second();

  void advance() { ++i_; }

  // Consumes `c` (upper case) if it is next.
  bool accept(char c);
  // Consumes `keyword` (upper case letters) if the next letters spell it,
  // blanks allowed between them.
  bool accept_keyword(std::string_view keyword);

  // An unsigned decimal number: digits with at most one point (blanks
  // allowed inside). Nullopt, consuming nothing, when none is next.
  // Inline: the parser reads every word's value through it.
  std::optional<double> number() {
    double v = 0.0;
    if (!number(v)) return std::nullopt;
    return v;
  }

  // The same, the value in `out`: the parser's way, with no std::optional
  // built field by field and read back whole (a stalled store forward on
  // every word).
  bool number(double& out) {
    skip_blanks();
    // The shape of nearly every number in a program, read in one pass
    // (gcode/decimal.hpp); blanks inside it or more than 15 digits go the
    // slow way.
    const Decimal d = scan_decimal(text_, i_);
    if (d.digits > kExactDigits || blank_inside(d.end, d.point)) {
      const auto slow = number_slow(i_);
      if (slow) out = *slow;
      return slow.has_value();
    }
    if (d.digits == 0) return false;
    i_ = d.end;
    out = d.value;
    return true;
  }

  // Everything up to (not including) `close`, raw; consumes `close` too.
  // Nullopt (consuming the rest) if `close` never comes.
  std::optional<std::string_view> until(char close);
  // The rest of the text, raw.
  std::string_view rest();

  std::string_view text() const { return text_; }

  // Where the next character is, blanks not skipped.
  std::size_t offset() const { return i_; }

 private:
  // Hot: called before every token.
  void skip_blanks() {
    while (i_ < text_.size() && is_blank(text_[i_]))
      ++i_;
  }

  static bool is_digit(char c) { return c >= '0' && c <= '9'; }

  // Blanks inside a number ("1 . 5") are legal RS274NGC: true when blanks
  // at `j` are followed by more of the number (a digit, or the point if
  // there was none), which the slow path reads.
  bool blank_inside(std::size_t j, bool point) const {
    if (j >= text_.size() || !is_blank(text_[j])) return false;
    while (j < text_.size() && is_blank(text_[j]))
      ++j;
    return j < text_.size() && (is_digit(text_[j]) || (text_[j] == '.' && !point));
  }

  static bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

  static constexpr std::size_t kExactDigits = decimal_detail::kExactDigits;

  std::optional<double> number_slow(std::size_t start);
  std::string_view text_;
  std::size_t i_ = 0;
};

}  // namespace usina::gcode
