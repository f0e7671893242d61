// SHA-256 of bytes as they pass (OpenSSL's EVP), for the hash of what a
// transfer put on the wire and of what a simulated control received.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace usina::dnc {

class Sha256 {
 public:
  Sha256();
  ~Sha256();
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;

  void update(std::span<const std::uint8_t> bytes);
  // The digest in lower-case hex; the hash goes on from the same state.
  std::string hex() const;

 private:
  void* ctx_;  // EVP_MD_CTX, kept out of the header
};

std::string sha256_hex(std::span<const std::uint8_t> bytes);
std::string sha256_hex(std::string_view text);

}  // namespace usina::dnc
