#include "dnc/store_names.hpp"

#include <fmt/format.h>

namespace usina::dnc {
namespace {

bool name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-' || c == '.' || c == '+';
}

// A shown form of a refused name: printable, short.
std::string shown(std::string_view s) {
  std::string out;
  for (const char c : s.substr(0, kMaxNameBytes)) {
    const auto b = static_cast<unsigned char>(c);
    out += (b >= 0x20 && b < 0x7f) ? std::string(1, c) : fmt::format("\\x{:02x}", b);
  }
  if (s.size() > kMaxNameBytes) out += "...";
  return out;
}

}  // namespace

std::size_t utf8_sequence_length(std::string_view s, std::size_t i) {
  const auto b0 = static_cast<unsigned char>(s[i]);
  if (b0 < 0x80) return 1;
  std::size_t n = 0;
  unsigned min = 0;
  unsigned cp = 0;
  if ((b0 & 0xE0) == 0xC0) {
    n = 2, min = 0x80, cp = b0 & 0x1Fu;
  } else if ((b0 & 0xF0) == 0xE0) {
    n = 3, min = 0x800, cp = b0 & 0x0Fu;
  } else if ((b0 & 0xF8) == 0xF0) {
    n = 4, min = 0x10000, cp = b0 & 0x07u;
  } else {
    return 0;
  }
  if (i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    const auto b = static_cast<unsigned char>(s[i + k]);
    if ((b & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (b & 0x3Fu);
  }
  if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
  return n;
}

bool valid_utf8(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    const std::size_t n = utf8_sequence_length(s, i);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

StoreResult<void> check_name(std::string_view what, std::string_view name) {
  if (name.empty()) return store_error(StoreErrorKind::Invalid, fmt::format("{} is empty", what));
  if (name.size() > kMaxNameBytes) {
    return store_error(StoreErrorKind::Invalid,
                       fmt::format("{} '{}' has {} bytes; at most {}", what, shown(name),
                                   name.size(), kMaxNameBytes));
  }
  for (const char c : name) {
    if (!name_char(c)) {
      return store_error(StoreErrorKind::Invalid,
                         fmt::format("{} '{}' holds '{}'; a name is letters, digits and _ - . + "
                                     "(never a path)",
                                     what, shown(name), shown(std::string_view(&c, 1))));
    }
  }
  if (name.front() == '.' || name.front() == '-') {
    return store_error(StoreErrorKind::Invalid,
                       fmt::format("{} '{}' starts with '{}'; start it with a letter or a digit",
                                   what, shown(name), name.front()));
  }
  return {};
}

StoreResult<void> check_text(std::string_view what, std::string_view text, std::size_t max_bytes) {
  if (text.size() > max_bytes) {
    return store_error(StoreErrorKind::TooLarge,
                       fmt::format("{} has {} bytes; at most {}", what, text.size(), max_bytes));
  }
  if (!valid_utf8(text))
    return store_error(StoreErrorKind::Invalid, fmt::format("{} is not valid UTF-8", what));
  for (const char c : text) {
    const auto b = static_cast<unsigned char>(c);
    if ((b < 0x20 && c != '\t' && c != '\n') || b == 0x7f) {
      return store_error(StoreErrorKind::Invalid,
                         fmt::format("{} holds the control character 0x{:02x}", what, b));
    }
  }
  return {};
}

}  // namespace usina::dnc
