#include "post/block_out.hpp"

#include <cmath>

#include <fmt/format.h>

namespace usina::post {

void BlockOut::block(std::string_view words) {
  if (line_numbers_) {
    out_ << fmt::format("N{:0{}} ", next_n_, control_.line_number_width);
    next_n_ += 10;
  }
  out_ << words << control_.block_end << '\n';
}

void BlockOut::raw(std::string_view line) {
  out_ << line << '\n';
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
  const double scale = std::pow(10.0, control_.decimals);
  const double r = std::round(v * scale) / scale;
  return r == 0.0 ? 0.0 : r;  // no negative zero
}

std::string BlockOut::number(double v) const {
  std::string s = fmt::format("{:.{}f}", rounded(v), control_.decimals);
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0')
      s.pop_back();
    if (s.back() == '.' && !control_.always_point) s.pop_back();
  } else if (control_.always_point) {
    s += '.';
  }
  if (s == "-0" || s == "-0.") s.erase(0, 1);
  return s;
}

}  // namespace usina::post
