// The words of a plain block: letters and signed numbers only ("G1 X-1.25
// Y0.5"), most blocks of a long program, read without the macro reader,
// with the values it gives (nc.cpp's list of words, plain_move.cpp's
// straight move).
#pragma once

#include <cstddef>
#include <string_view>

#include "gcode/fanuc/macro.hpp"

namespace usina::gcode::fanuc {

// Whether a plain word may end at text[i]: at the end, a blank, or the
// next word's letter (not an exponent of the number).
inline bool plain_word_ends(std::string_view text, std::size_t i) {
  if (i >= text.size()) return true;
  const char c = text[i];
  return c == ' ' || c == '\t' || (c >= 'A' && c <= 'Z' && c != 'E');
}

// Each word of a plain block handed to `word(letter, value, had_point,
// pos)`, which answers false to stop. False for any other block
// (variables, brackets, functions, comments, lower case...) or when a word
// stopped it.
template <class OnWord>
bool plain_words(std::string_view text, OnWord&& word) {
  std::size_t i = 0;
  while (i < text.size()) {
    const char l = text[i];
    if (l == ' ' || l == '\t') {
      ++i;
      continue;
    }
    if (l < 'A' || l > 'Z') return false;
    std::size_t j = i + 1;
    const bool negative = j < text.size() && text[j] == '-';
    if (j < text.size() && (text[j] == '-' || text[j] == '+')) ++j;
    double value = 0;
    bool point = false;
    if (!plain_digits(text, j, value, point) || !plain_word_ends(text, j)) return false;
    if (!word(l, negative ? -value : value, point, i)) return false;
    i = j;
  }
  return true;
}

}  // namespace usina::gcode::fanuc
