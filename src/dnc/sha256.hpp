// SHA-256 (OpenSSL's EVP) as 64 lower-case hex digits: a revision's address,
// a blob's check, a link of the audit chain, a session token's stored form,
// and the hash of what a transfer put on the wire or a control received.
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
  Sha256& add(std::string_view bytes);  // the audit chain hashes fields without joining them
  // The digest in lower-case hex; the hash goes on from the same state.
  std::string hex() const;

 private:
  void* ctx_;  // EVP_MD_CTX, kept out of the header
};

std::string sha256_hex(std::span<const std::uint8_t> bytes);
std::string sha256_hex(std::string_view text);

// True for 64 lower-case hex digits: what a revision address looks like.
bool is_sha256_hex(std::string_view s);

}  // namespace usina::dnc
