// Grbl's line reader ([proto] of docs/grbl.md): what reaches the parser of a
// line streamed to the firmware, and the words it is read into.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>

#include "gcode/decimal.hpp"
#include "gcode/grbl/dialect.hpp"

namespace usina::gcode::grbl {
namespace {

bool is_realtime(unsigned char c) {
  // Picked out of the serial stream before the line buffer (status report,
  // cycle start, feed hold, soft reset).
  return c == '?' || c == '~' || c == '!' || c == 0x18;
}

// A character Grbl keeps as it is outside comments (upper-cased): most of
// a line, so the others are told apart once, by this table.
constexpr std::array<bool, 256> kPlain = [] {
  std::array<bool, 256> t{};
  for (int c = '!'; c < 0x80; ++c)
    t[static_cast<std::size_t>(c)] = true;
  for (const unsigned char c : std::string_view("?~!/(;"))
    t[c] = false;
  return t;
}();

}  // namespace

StrippedLine strip_line(std::string_view line) {
  StrippedLine out;
  strip_line(line, out);
  return out;
}

namespace {

// The characters of a plain line (most lines of a program): upper case,
// digits, signs, points and blanks; nothing to upper-case, no comment, no
// real-time or control character.
constexpr std::array<bool, 256> kPlainLine = [] {
  std::array<bool, 256> t = kPlain;
  for (int c = 'a'; c <= 'z'; ++c)
    t[static_cast<std::size_t>(c)] = false;
  t[' '] = true;
  return t;
}();

// A plain line's characters but the blanks into `out`; false (and `out`
// to be written again) when the line is not plain. Every character is
// written, and the next one written over it when it was a blank: a branch
// per character, taken at random, cost more than the stores (issue 19).
bool strip_plain_line(std::string_view line, StrippedLine& out) {
  char* text = out.text.data();
  std::uint32_t* cols = out.cols.data();
  bool plain = true;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    plain &= kPlainLine[static_cast<unsigned char>(c)];
    text[kept] = c;
    cols[kept] = static_cast<std::uint32_t>(i + 1);
    kept += c != ' ' ? 1 : 0;
  }
  if (!plain) return false;
  out.text.resize(kept);
  out.cols.resize(kept);
  return true;
}

}  // namespace

void strip_line(std::string_view line, StrippedLine& out) {
  out.text.resize(line.size());
  out.cols.resize(line.size());
  out.realtime_col = out.control_col = 0;
  out.control = 0;
  if (strip_plain_line(line, out)) return;
  std::size_t kept = 0;
  bool in_parens = false;
  bool in_semicolon = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const auto c = static_cast<unsigned char>(line[i]);
    const auto col = static_cast<std::uint32_t>(i + 1);
    if (kPlain[c] && !in_parens && !in_semicolon) {
      const char up =
          (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : static_cast<char>(c);
      out.text[kept] = up;
      out.cols[kept] = col;
      ++kept;
      continue;
    }
    if (is_realtime(c)) {
      if (out.realtime_col == 0) out.realtime_col = col;
      continue;
    }
    // Bytes above 0x7F are extended real-time commands or thrown away by
    // the serial interrupt: a UTF-8 comment never reaches the line.
    if (c >= 0x80 || in_semicolon) continue;
    if (in_parens) {
      if (c == ')') in_parens = false;
      continue;
    }
    // Blanks and control characters are dropped (a NUL too: X1<NUL>20 is
    // X120 to Grbl); no block delete.
    if (c < ' ' && c != '\t' && out.control_col == 0) {
      out.control_col = col;
      out.control = c;
    }
    // What is left besides blanks and '/' is '(' or ';': the rest is plain.
    if (c == '(') in_parens = true;
    if (c == ';') in_semicolon = true;
  }
  out.text.resize(kept);
  out.cols.resize(kept);
}

// Where the line starting at `at` ends: at the first LF or CR. Searched a
// piece at a time, so a file of CR ends is not searched to its end for an
// LF at every line.
std::size_t line_end(std::string_view text, std::size_t at) {
  constexpr std::size_t kPiece = 256;
  for (std::size_t from = at; from < text.size(); from += kPiece) {
    const char* p = text.data() + from;
    const std::size_t length = std::min(kPiece, text.size() - from);
    const auto* lf = static_cast<const char*>(std::memchr(p, '\n', length));
    const std::size_t before_lf = lf != nullptr ? static_cast<std::size_t>(lf - p) : length;
    const auto* cr = static_cast<const char*>(std::memchr(p, '\r', before_lf));
    if (cr != nullptr) return from + static_cast<std::size_t>(cr - p);
    if (lf != nullptr) return from + before_lf;
  }
  return text.size();
}

LineSpan read_line(std::string_view text, std::uint64_t offset) {
  const std::size_t at = static_cast<std::size_t>(offset);
  const std::size_t end = line_end(text, at);
  LineSpan out{offset, end - at, std::min<std::uint64_t>(end + 1, text.size())};
  // CR LF is one line end, and so is CR CR LF (a CR LF file converted
  // once more): an editor shows one line there, and Grbl skips the blank.
  std::size_t crs = end;
  while (crs < text.size() && text[crs] == '\r')
    ++crs;
  if (crs > end && crs < text.size() && text[crs] == '\n') out.next = crs + 1;
  return out;
}

namespace {

// Grbl's read_float: an optional sign, then digits with at most one point,
// at least one digit, read as every dialect reads them (gcode/decimal.hpp).
// Returns the characters read, 0 when it is no number or beyond a double.
// Aligned as gcode/parser.cpp's plain_number_at is (why there).
[[gnu::aligned(64)]] std::size_t read_number(std::string_view s, double& value) {
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
  const Decimal d = scan_decimal(s, i);
  // Up to 15 digits the value is finite: no test waits for the division.
  if (d.digits == 0 || (d.digits > decimal_detail::kExactDigits && !std::isfinite(d.value)))
    return 0;
  value = s[0] == '-' ? -d.value : d.value;
  return d.end;
}

std::string not_a_letter(char c) {
  std::string what = c == '#'   ? "'#' (Grbl has no parameters)"
                     : c == '[' ? "'[' (Grbl has no expressions)"
                     : c == '%' ? "'%' inside a line"
                                : std::string("'") + c + "'";
  return what + " where a word's letter must be";
}

}  // namespace

Checked read_words(std::string_view text, const std::vector<std::uint32_t>& cols,
                   std::vector<Word>& out) {
  out.clear();
  std::size_t i = 0;
  while (i < text.size()) {
    const char letter = text[i];
    const std::uint32_t col = cols[i];
    if (letter < 'A' || letter > 'Z') {
      return tl::unexpected(Failure{1, col, not_a_letter(letter)});
    }
    double value = 0.0;
    const std::size_t n = read_number(text.substr(i + 1), value);
    if (n == 0) {
      return tl::unexpected(
          Failure{2, col, std::string(1, letter) + " is not followed by a number"});
    }
    out.push_back({letter, value, col});
    i += 1 + n;
  }
  return {};
}

namespace {

// The words of a plain line, each handed to `word(letter, value, col)`
// (false from it: the line is not read on); `kept` the characters
// strip_line keeps. False for a line that is not plain.
template <class OnWord>
bool plain_line_words(std::string_view line, std::size_t& kept, OnWord&& word) {
  kept = 0;
  const std::size_t n = line.size();
  std::size_t i = 0;
  for (;;) {
    while (i < n && line[i] == ' ')
      ++i;
    if (i == n) return kept > 0;
    const char letter = line[i];
    if (letter < 'A' || letter > 'Z') return false;
    double value = 0.0;
    const std::size_t digits = read_number(line.substr(i + 1), value);
    const std::size_t end = i + 1 + digits;
    // A blank in a number, or a character Grbl drops after it, joins or
    // ends the word elsewhere: the general road reads it.
    if (digits == 0 || (end < n && line[end] != ' ' && (line[end] < 'A' || line[end] > 'Z')))
      return false;
    if (!word(letter, value, static_cast<std::uint32_t>(i + 1))) return false;
    kept += end - i;
    i = end;
  }
}

}  // namespace

bool read_plain_words(std::string_view line, std::vector<Word>& out, std::size_t& kept) {
  out.clear();
  return plain_line_words(line, kept, [&](char letter, double value, std::uint32_t col) {
    out.push_back({letter, value, col});
    return true;
  });
}

bool read_straight_line(std::string_view line, PlainMove& move, std::size_t& kept,
                        std::uint32_t& first_col) {
  StraightWords straight(move);
  first_col = 0;
  return plain_line_words(line, kept, [&](char letter, double value, std::uint32_t col) {
    if (first_col == 0) first_col = col;
    return straight.add(letter, value);
  });
}

}  // namespace usina::gcode::grbl
