#include "post/block_out.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

namespace usina::post {

BlockOut::BlockOut(std::ostream& out, const Control& control, bool line_numbers)
    : out_(out),
      control_(control),
      line_numbers_(line_numbers || control.always_line_numbers),
      scale_(std::pow(10.0, control.decimals)) {}

void BlockOut::block(std::string_view words) {
  if (line_numbers_) {
    // "N0010 ": the number padded with zeros to the control's width, written
    // in place (a format string parsed for every block of a long program
    // was a tenth of romi's convert; issue 19).
    char digits[24];
    const auto [end, ec] = std::to_chars(digits, digits + sizeof digits, next_n_);
    const auto n = static_cast<std::size_t>(end - digits);
    const auto width = static_cast<std::size_t>(std::max(control_.line_number_width, 0));
    buffer_ += 'N';
    if (n < width) buffer_.append(width - n, '0');
    buffer_.append(digits, n);
    buffer_ += ' ';
    next_n_ += 10;
  }
  buffer_ += words;
  buffer_ += control_.block_end;
  buffer_ += '\n';
  if (buffer_.size() > (1u << 16)) flush();
}

void BlockOut::raw(std::string_view line) {
  buffer_ += line;
  buffer_ += '\n';
}

void BlockOut::flush() {
  out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  buffer_.clear();
}

std::string BlockOut::comment(std::string_view text) const {
  std::string clean;
  for (const char c : text) {
    // Parentheses would end or nest a comment; '#' ends a ROMI block; a
    // newline ends every block.
    if (c == '(' || c == ')' || c == '\n' || c == '\r' || (c == '#' && !control_.block_end.empty()))
      continue;
    if (c == ';' && control_.semicolon_comments) continue;
    clean += c;
  }
  return control_.semicolon_comments ? ";" + clean : "(" + clean + ")";
}

double BlockOut::rounded(double v) const {
  const double x = v * scale_;
  // Half away from zero, as std::round, without its library call (a post
  // rounds every coordinate of millions of blocks).
  const double whole = std::abs(x) < 1e15
                           ? static_cast<double>(static_cast<long long>(x + (x < 0 ? -0.5 : 0.5)))
                           : std::round(x);
  const double r = whole / scale_;
  return r == 0.0 ? 0.0 : r;  // no negative zero
}

std::string BlockOut::number(double v) const {
  std::string s;
  append_word(s, '\0', v);
  return s;
}

void BlockOut::append_word(std::string& words, char letter, double v) const {
  append_rounded(words, letter, rounded(v));
}

namespace {

// A rounded value's digits from the whole number of least increments it
// is (12.345 at 3 decimals: 12345), the point put in: what to_chars
// writes in fixed notation, without its general algorithm (a sixth of a
// long program's convert; issue 19). Only for a value that is exactly
// what rounded() makes of that whole number, below 1e15 increments (the
// whole number exact, the value's decimal expansion nearer to it than
// half an increment, so to_chars would write its digits); otherwise, or
// for a negative zero, nullptr.
char* fixed_from_increments(char* p, char* last, double r, double scale, int decimals) {
  const double x = r * scale;
  if (!(std::abs(x) < 1e15) || (r == 0.0 && std::signbit(r))) return nullptr;
  long long whole = static_cast<long long>(x + (x < 0 ? -0.5 : 0.5));
  // Predicted true: the division runs beside the digits, not before them.
  if (static_cast<double>(whole) / scale != r) return nullptr;
  if (whole < 0) {
    *p++ = '-';
    whole = -whole;
  }
  char digits[24];
  auto [end, ec] = std::to_chars(digits, digits + sizeof digits, whole);
  auto n = static_cast<std::size_t>(end - digits);
  const auto d = static_cast<std::size_t>(decimals);
  if (static_cast<std::size_t>(last - p) < n + d + 2) return nullptr;
  if (n <= d) {  // 0.005: zeros between the point and the digits
    *p++ = '0';
    if (d > 0) *p++ = '.';
    for (std::size_t k = n; k < d; ++k)
      *p++ = '0';
    return std::copy(digits, end, p);
  }
  p = std::copy(digits, digits + (n - d), p);
  if (d == 0) return p;
  *p++ = '.';
  return std::copy(digits + (n - d), end, p);
}

}  // namespace

void BlockOut::append_rounded(std::string& words, char letter, double r) const {
  // Room for any double in fixed notation (1e308: 309 digits, then the
  // decimals): a word never comes out without its number.
  char buf[400];
  char* p = buf;
  if (letter != '\0') {
    if (!words.empty()) *p++ = ' ';
    *p++ = letter;
  }
  char* end = fixed_from_increments(p, buf + sizeof buf, r, scale_, control_.decimals);
  if (end == nullptr) {
    const auto res =
        std::to_chars(p, buf + sizeof buf, r, std::chars_format::fixed, control_.decimals);
    end = res.ec == std::errc{} ? res.ptr : p;
  }
  if (control_.decimals > 0) {
    while (end[-1] == '0')
      --end;
    if (end[-1] == '.' && !control_.always_point) --end;
  } else if (control_.always_point) {
    *end++ = '.';
  }
  words.append(buf, static_cast<std::size_t>(end - buf));
}

}  // namespace usina::post
