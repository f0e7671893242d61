#include "gcode/word_range.hpp"

#include <cmath>

#include <fmt/format.h>

#include "canon/limits.hpp"

namespace usina::gcode {

static_assert(kMinFeedWord == canon::kMinFeed);

std::string word_range_error(char letter, double value) {
  if (!std::isfinite(value))
    return fmt::format("{} value ({}) is not a finite number", letter, value);
  if (std::fabs(value) > kMaxWordValue) {
    return fmt::format(
        "{}{:g} is beyond ±{}, the range of a word's value (docs/rs274ngc.md, Numbers)", letter,
        value, canon::limit_text(kMaxWordValue));
  }
  // F is divided into a move's length to time it: a feed of 1e-300 would
  // make a time of infinity.
  return fmt::format("F{:g} is below {}, the smallest feed rate usina times", value,
                     canon::limit_text(canon::kMinFeed));
}

}  // namespace usina::gcode
