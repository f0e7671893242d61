// Standard base64 (RFC 4648 §4, with padding) by OpenSSL's EVP coder: the
// import's `text_base64` and the forms' tool-path stream in JSON.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace usina::dnc {

std::string to_base64(std::string_view bytes);

// The bytes, or nothing when `text` is not padded standard base64 (no
// blanks, no line breaks, no URL-safe digits).
std::optional<std::string> from_base64(std::string_view text);

}  // namespace usina::dnc
