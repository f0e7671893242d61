// base64 (dnc/base64.hpp): RFC 4648 §10's vectors both ways, every byte
// value, a text longer than one of OpenSSL's pieces, and what is refused.
#include "dnc/base64.hpp"

#include <string>

#include <gtest/gtest.h>

namespace usina::dnc {
namespace {

TEST(Base64, Rfc4648Vectors) {
  const std::pair<std::string, std::string> vectors[] = {{"", ""},
                                                         {"f", "Zg=="},
                                                         {"fo", "Zm8="},
                                                         {"foo", "Zm9v"},
                                                         {"foob", "Zm9vYg=="},
                                                         {"fooba", "Zm9vYmE="},
                                                         {"foobar", "Zm9vYmFy"}};
  for (const auto& [bytes, text] : vectors) {
    EXPECT_EQ(to_base64(bytes), text) << bytes;
    EXPECT_EQ(from_base64(text), bytes) << text;
  }
}

TEST(Base64, EveryByteValueRoundTrips) {
  std::string bytes;
  for (int i = 0; i < 256; ++i)
    bytes += static_cast<char>(i);
  bytes += std::string("\0\0", 2);  // zeros at the end look like padding to EVP
  EXPECT_EQ(from_base64(to_base64(bytes)), bytes);
}

TEST(Base64, ALongTextCrossesThePieces) {
  // 7 MiB: more than two of the coder's 3 MiB pieces; 7 MiB mod 3 = 1, two "=".
  std::string bytes(7u << 20, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i)
    bytes[i] = static_cast<char>((i * 131u) >> 3);
  const std::string text = to_base64(bytes);
  EXPECT_EQ(text.size(), (bytes.size() + 2) / 3 * 4);
  EXPECT_EQ(text.substr(text.size() - 2), "==");
  EXPECT_EQ(from_base64(text), bytes);
}

TEST(Base64, WhatIsNotPaddedStandardBase64IsRefused) {
  for (const char* bad :
       {"Zg", "Zg=", "Z===", "====", "Zm9v\n", " Zm9", "Zm-_", "Zm=v", "Zg==Zg=="}) {
    EXPECT_FALSE(from_base64(bad).has_value()) << bad;
  }
  EXPECT_FALSE(from_base64(std::string("Zm9v\0\0\0\0", 8)).has_value());
}

}  // namespace
}  // namespace usina::dnc
