// Numbers in exponent notation, which no dialect has: "X1e400" reads as X1
// and a word E400 (RS274NGC, Fanuc and the ROMI control all read E as a
// word). When the meant number cannot even be represented, the E word's
// complaint hides the real mistake; the readers ask here first.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include <tl/expected.hpp>

namespace usina::gcode {

// A number literal spans text[start, end). When an exponent (e or E, an
// optional sign, digits) follows at `end` with no blank, and the number it
// would make is beyond a double (1e400) or below the smallest one (1e-400):
// the message, as the error. Otherwise a value (the E reads as a word, as the
// control reads it).
tl::expected<void, std::string> exponent_out_of_range(std::string_view text, std::size_t start,
                                                      std::size_t end);

}  // namespace usina::gcode
