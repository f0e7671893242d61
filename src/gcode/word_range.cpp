#include "gcode/word_range.hpp"

#include <cmath>

#include <fmt/format.h>

#include "canon/limits.hpp"

namespace usina::gcode {

tl::expected<void, std::string> word_out_of_range(char letter, double value) {
  if (letter == 'G' || letter == 'M') return {};
  if (!std::isfinite(value))
    return tl::unexpected(fmt::format("{} value ({}) is not a finite number", letter, value));
  if (std::fabs(value) > kMaxWordValue) {
    return tl::unexpected(
        fmt::format("{}{:g} is beyond ±{}, the range of a word's value (docs/rs274ngc.md, "
                    "Numbers)",
                    letter, value, canon::limit_text(kMaxWordValue)));
  }
  // F is divided into a move's length to time it: a feed of 1e-300 would
  // make a time of infinity.
  if (letter == 'F' && value > 0.0 && value < canon::kMinFeed) {
    return tl::unexpected(fmt::format("F{:g} is below {}, the smallest feed rate usina times",
                                      value, canon::limit_text(canon::kMinFeed)));
  }
  return {};
}

}  // namespace usina::gcode
