// Random blocks for the tests that hold a parser's shortcut for plain
// blocks to its whole road: often well-formed words (a letter, a sign now
// and then, digits with or without a point) with blanks between them,
// often any character of `chars`.
#pragma once

#include <random>
#include <string>
#include <string_view>

namespace usina::test {

inline std::string random_block(std::mt19937& rng, std::string_view chars,
                                std::string_view letters) {
  std::string block;
  const auto pieces = rng() % 8;
  for (std::size_t i = 0; i < pieces; ++i) {
    if (rng() % 3 != 0) {
      block += std::string(rng() % 3, ' ');
      block += letters[rng() % letters.size()];
      if (rng() % 3 == 0) block += "-+"[rng() % 2];
      if (rng() % 5 != 0) block += std::to_string(rng() % 1000);
      if (rng() % 2 == 0) block += ".";
      if (rng() % 2 == 0) block += std::to_string(rng() % 100);
    } else {
      block += chars[rng() % chars.size()];
    }
  }
  return block;
}

}  // namespace usina::test
