// What a name or a text field may hold before it reaches the store. A name
// (program, machine class, user) is never a path: it becomes a file name on
// export and a URL segment in the API, so it is 1 to 64 of the letters,
// digits and `_ - . +`, not starting with `.` or `-` (no `..`, no `/`, no
// NUL, no space). Free text (a reason, an origin) is UTF-8 without NUL or
// control characters other than tab and newline, within a size.
#pragma once

#include <cstddef>
#include <string_view>

#include "dnc/store_error.hpp"

namespace usina::dnc {

constexpr std::size_t kMaxNameBytes = 64;
constexpr std::size_t kMaxReasonBytes = 2000;
constexpr std::size_t kMaxOriginBytes = 200;

// `what` names the field in the message ("program name").
StoreResult<void> check_name(std::string_view what, std::string_view name);
StoreResult<void> check_text(std::string_view what, std::string_view text, std::size_t max_bytes);

bool valid_utf8(std::string_view s);
// The length of the UTF-8 sequence at s[i], 0 when malformed (overlong
// forms, surrogates and code points past U+10FFFF included).
std::size_t utf8_sequence_length(std::string_view s, std::size_t i);

}  // namespace usina::dnc
