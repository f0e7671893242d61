// Text from outside (programs, drawings, file names) is shown on terminals
// and written into JSON: these say which bytes are valid UTF-8 and make the
// rest visible, so a program can neither break a JSON file nor send escape
// sequences to an operator's terminal.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace usina::core {

// The length (1-4) of the valid UTF-8 sequence that starts at s[i], or 0
// when the byte there starts none (overlong forms and surrogates are not
// valid).
std::size_t utf8_sequence_at(std::string_view s, std::size_t i);

// `s` with every control character and every byte that is not valid UTF-8
// written as \xNN (a tab as \t), so it is safe to print and to read.
std::string printable(std::string_view s);

}  // namespace usina::core
