// Grbl's line reader ([proto] of docs/grbl.md): what reaches the parser of a
// line streamed to the firmware, and the words it is read into.
#include <algorithm>
#include <charconv>
#include <cmath>

#include "gcode/dialects/grbl.hpp"

namespace usina::gcode::grbl {
namespace {

bool is_realtime(unsigned char c) {
  // Picked out of the serial stream before the line buffer (status report,
  // cycle start, feed hold, soft reset).
  return c == '?' || c == '~' || c == '!' || c == 0x18;
}

}  // namespace

StrippedLine strip_line(std::string_view line) {
  StrippedLine out;
  strip_line(line, out);
  return out;
}

void strip_line(std::string_view line, StrippedLine& out) {
  out.text.clear();
  out.cols.clear();
  out.blanked.assign(line.size(), ' ');
  out.realtime_col = out.control_col = 0;
  out.control = 0;
  bool in_parens = false;
  bool in_semicolon = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const auto c = static_cast<unsigned char>(line[i]);
    const auto col = static_cast<std::uint32_t>(i + 1);
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
    if (c <= ' ' || c == '/') continue;
    if (c == '(') {
      in_parens = true;
      continue;
    }
    if (c == ';') {
      in_semicolon = true;
      continue;
    }
    const char up =
        (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : static_cast<char>(c);
    out.text.push_back(up);
    out.cols.push_back(col);
    out.blanked[i] = up;
  }
}

LineSpan read_line(std::string_view text, std::uint64_t offset) {
  const std::size_t at = static_cast<std::size_t>(offset);
  const std::size_t end = std::min(text.find_first_of("\r\n", at), text.size());
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
// at least one digit. Returns the characters read, 0 when it is no number.
std::size_t read_number(std::string_view s, double& value) {
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
  std::size_t digits = 0;
  bool point = false;
  while (i < s.size()) {
    if (s[i] >= '0' && s[i] <= '9') {
      ++digits;
    } else if (s[i] == '.' && !point) {
      point = true;
    } else {
      break;
    }
    ++i;
  }
  if (digits == 0) return 0;
  // from_chars takes no sign and wants a digit before the point.
  const bool negative = s[0] == '-';
  const std::size_t first = (s[0] == '-' || s[0] == '+') ? 1 : 0;
  std::string text = s[first] == '.' ? std::string("0") : std::string();
  text.append(s.substr(first, i - first));
  double v = 0.0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc{} || !std::isfinite(v)) return 0;
  value = negative ? -v : v;
  return i;
}

std::string not_a_letter(char c) {
  std::string what = c == '#'   ? "'#' (Grbl has no parameters)"
                     : c == '[' ? "'[' (Grbl has no expressions)"
                     : c == '%' ? "'%' inside a line"
                                : std::string("'") + c + "'";
  return what + " where a word's letter must be";
}

}  // namespace

std::optional<Failure> read_words(std::string_view text, const std::vector<std::uint32_t>& cols,
                                  std::vector<Word>& out) {
  out.clear();
  std::size_t i = 0;
  while (i < text.size()) {
    const char letter = text[i];
    const std::uint32_t col = cols[i];
    if (letter < 'A' || letter > 'Z') {
      return Failure{1, col, not_a_letter(letter)};
    }
    double value = 0.0;
    const std::size_t n = read_number(text.substr(i + 1), value);
    if (n == 0) {
      return Failure{2, col, std::string(1, letter) + " is not followed by a number"};
    }
    out.push_back({letter, value, col});
    i += 1 + n;
  }
  return std::nullopt;
}

}  // namespace usina::gcode::grbl
