// The range of a word's value (docs/rs274ngc.md, "Numbers"): every dialect
// checks each word as it is read, so a value no machine could use is an
// error at the word that holds it, before any arithmetic builds on it.
// Values computed from in-range words (offsets added, increments summed,
// scale factors applied) are checked again at the canon boundary
// (canon/limits.hpp, CanonMachine).
#pragma once

#include <cmath>
#include <string>

#include <tl/expected.hpp>

namespace usina::gcode {

// Bound of every word's value in its program units (mm or inch, degrees,
// seconds, rev/min): the canon range, so a word within it never overflows
// what it is multiplied or added into.
inline constexpr double kMaxWordValue = 1e9;

// The smallest F that is not 0 (canon::kMinFeed, the smallest feed usina
// times: a feed of 1e-300 would make a move's time infinite).
inline constexpr double kMinFeedWord = 1e-6;

// Why `letter`'s word of `value` is out of range (the message of
// word_out_of_range).
std::string word_range_error(char letter, double value);

// Whether the value of `letter`'s word is in range. G and M words are
// codes, checked as codes. Inline, and a bool: every word of every block
// asks, and the message is built only for a word out of range.
inline bool word_value_in_range(char letter, double value) {
  if (letter == 'G' || letter == 'M') return true;
  // NaN fails the first comparison.
  return std::fabs(value) <= kMaxWordValue &&
         (letter != 'F' || !(value > 0.0 && value < kMinFeedWord));
}

// Why the value of `letter`'s word is out of range, as the error; a value
// when it is in range.
inline tl::expected<void, std::string> word_out_of_range(char letter, double value) {
  if (word_value_in_range(letter, value)) return {};
  return tl::unexpected(word_range_error(letter, value));
}

}  // namespace usina::gcode
