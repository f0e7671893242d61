#include "dnc/sheet_links.hpp"

#include <sodium.h>

#include <stdexcept>

#include <fmt/format.h>

namespace usina::dnc {
namespace {

// One field a line: names hold no newline (store_names.hpp), so no two
// links sign the same text.
std::string message(const SheetLinkFields& f) {
  return fmt::format("usina sheet link\n{}\n{}\n{}\n{}", f.program, f.revision, f.format,
                     f.expires_s);
}

std::array<unsigned char, crypto_auth_hmacsha256_BYTES> mac(const SheetLinks::Key& key,
                                                            const SheetLinkFields& f) {
  const std::string text = message(f);
  std::array<unsigned char, crypto_auth_hmacsha256_BYTES> out{};
  crypto_auth_hmacsha256(out.data(), reinterpret_cast<const unsigned char*>(text.data()),
                         text.size(), key.data());
  return out;
}

}  // namespace

SheetLinks::SheetLinks() : key_{} {
  if (sodium_init() < 0) throw std::runtime_error("libsodium cannot start");
  crypto_auth_hmacsha256_keygen(key_.data());
}

std::string SheetLinks::sign(const SheetLinkFields& f) const {
  const auto m = mac(key_, f);
  std::string hex(m.size() * 2 + 1, '\0');
  sodium_bin2hex(hex.data(), hex.size(), m.data(), m.size());
  hex.pop_back();
  return hex;
}

bool SheetLinks::holds(const SheetLinkFields& f, std::string_view signature) const {
  std::array<unsigned char, crypto_auth_hmacsha256_BYTES> given{};
  std::size_t length = 0;
  if (sodium_hex2bin(given.data(), given.size(), signature.data(), signature.size(), nullptr,
                     &length, nullptr) != 0 ||
      length != given.size() || signature.size() != given.size() * 2) {
    return false;
  }
  const auto expected = mac(key_, f);
  return sodium_memcmp(given.data(), expected.data(), given.size()) == 0;
}

}  // namespace usina::dnc
