#include "post/block_out.hpp"

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
    buffer_ += fmt::format("N{:0{}} ", next_n_, control_.line_number_width);
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

void BlockOut::append_rounded(std::string& words, char letter, double r) const {
  char buf[64];
  char* p = buf;
  if (letter != '\0') {
    if (!words.empty()) *p++ = ' ';
    *p++ = letter;
  }
  const auto res =
      std::to_chars(p, buf + sizeof buf, r, std::chars_format::fixed, control_.decimals);
  char* end = res.ec == std::errc{} ? res.ptr : p;
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
