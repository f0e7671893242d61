// The lexer of RS274NGC text: reads one block's characters from a view into
// the source (no copies). RS274NGC ignores spaces and tabs everywhere outside
// comments and is case-insensitive, so every read skips blanks and compares
// letters in upper case.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

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
  std::optional<double> number();
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
    while (i_ < text_.size() && (text_[i_] == ' ' || text_[i_] == '\t' || text_[i_] == '\r'))
      ++i_;
  }

  std::optional<double> number_slow(std::size_t start);
  std::string_view text_;
  std::size_t i_ = 0;
};

}  // namespace usina::gcode
