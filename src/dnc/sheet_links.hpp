// Short-lived signed links to a revision's setup sheet (docs/dnc-server.md,
// "Setup sheets"), so the page can show a sheet in a sandboxed frame: a
// frame's request carries no bearer token, so the link itself is the
// permission. It names the program, the revision, the format and when it
// expires, and carries an HMAC-SHA-256 of those under a key the server draws
// when it starts (libsodium): a link is good for that server's life, at
// most kSheetLinkSeconds, for that one sheet. Anything else is refused.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace usina::dnc {

inline constexpr std::int64_t kSheetLinkSeconds = 300;

struct SheetLinkFields {
  std::string_view program;
  std::string_view revision;
  std::string_view format;
  std::int64_t expires_s = 0;  // Unix seconds
};

class SheetLinks {
 public:
  using Key = std::array<unsigned char, 32>;

  SheetLinks();  // a fresh random key

  explicit SheetLinks(const Key& key) : key_(key) {}

  // The signature of `f`: 64 hex digits.
  std::string sign(const SheetLinkFields& f) const;
  // Whether `signature` is `f`'s (compared in constant time); the expiry is
  // the caller's to check.
  bool holds(const SheetLinkFields& f, std::string_view signature) const;

 private:
  Key key_;
};

}  // namespace usina::dnc
