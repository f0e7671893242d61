// base64 by OpenSSL (base64.hpp). EVP_EncodeBlock and EVP_DecodeBlock take
// an int length, so long inputs go in pieces that keep the 3-byte / 4-digit
// grouping: the pieces' outputs join into the whole's.
#include "dnc/base64.hpp"

#include <algorithm>

#include <openssl/evp.h>

namespace usina::dnc {
namespace {

constexpr std::size_t kPieceBytes = 3u << 20;   // a multiple of 3
constexpr std::size_t kPieceDigits = 4u << 20;  // a multiple of 4

const unsigned char* bytes_of(std::string_view s) {
  return reinterpret_cast<const unsigned char*>(s.data());
}

bool is_digit(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '+' ||
         c == '/';
}

// The digits before the padding ('=' at the end, at most two).
std::size_t digits_of(std::string_view text) {
  return text.find_last_not_of('=') + 1;  // npos + 1 == 0: all padding
}

// Only the alphabet, then the padding: EVP_DecodeBlock itself skips blanks
// around the text and reads '=' anywhere.
bool well_formed(std::string_view text) {
  const std::size_t digits = digits_of(text);
  return text.size() % 4 == 0 && text.size() - digits <= 2 &&
         std::all_of(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(digits), is_digit);
}

}  // namespace

std::string to_base64(std::string_view bytes) {
  std::string out((bytes.size() + 2) / 3 * 4 + 1, '\0');  // EVP writes a final NUL
  std::size_t written = 0;
  for (std::size_t at = 0; at < bytes.size(); at += kPieceBytes) {
    const std::string_view piece = bytes.substr(at, kPieceBytes);
    written += static_cast<std::size_t>(
        EVP_EncodeBlock(reinterpret_cast<unsigned char*>(out.data() + written), bytes_of(piece),
                        static_cast<int>(piece.size())));
  }
  out.resize(written);
  return out;
}

std::optional<std::string> from_base64(std::string_view text) {
  if (!well_formed(text)) return std::nullopt;
  std::string out(text.size() / 4 * 3, '\0');
  std::size_t written = 0;
  for (std::size_t at = 0; at < text.size(); at += kPieceDigits) {
    const std::string_view piece = text.substr(at, kPieceDigits);
    const int n = EVP_DecodeBlock(reinterpret_cast<unsigned char*>(out.data() + written),
                                  bytes_of(piece), static_cast<int>(piece.size()));
    if (n < 0) return std::nullopt;
    written += static_cast<std::size_t>(n);
  }
  // EVP_DecodeBlock counts the padding's zero bytes: take them off.
  written -= text.size() - digits_of(text);
  out.resize(written);
  return out;
}

}  // namespace usina::dnc
