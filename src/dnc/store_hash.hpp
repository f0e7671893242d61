// SHA-256 (OpenSSL) as 64 lower-case hex digits: a revision's address, a
// blob's check, a link of the audit chain, a session token's stored form.
#pragma once

#include <string>
#include <string_view>

namespace usina::dnc {

std::string sha256_hex(std::string_view bytes);

// Hashes in pieces (the audit chain hashes fields without joining them).
class Sha256 {
 public:
  Sha256();
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;
  ~Sha256();

  Sha256& add(std::string_view bytes);
  std::string hex();  // ends the hash

 private:
  void* ctx_;  // EVP_MD_CTX, kept out of the header
};

// True for 64 lower-case hex digits: what a revision address looks like.
bool is_sha256_hex(std::string_view s);

}  // namespace usina::dnc
