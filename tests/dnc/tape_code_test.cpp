#include "dnc/tape_code.hpp"

#include <random>
#include <set>
#include <string>

#include <gtest/gtest.h>

namespace usina::dnc {
namespace {

constexpr std::string_view kEiaAlphabet =
    "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz +-/.,()\n";

TEST(TapeCode, IsoRowsHaveEvenParityAndDecodeBack) {
  for (unsigned c = 1; c < 0x7F; ++c) {
    const auto row = encode_char(TapeCode::Iso, static_cast<unsigned char>(c));
    ASSERT_TRUE(row.has_value()) << c;
    EXPECT_TRUE(even_parity(*row)) << c;
    EXPECT_EQ(*row & 0x7FU, c);
    const DecodedRow d = decode_row(TapeCode::Iso, *row, true);
    EXPECT_EQ(d.kind, DecodedRow::Kind::Char);
    EXPECT_EQ(static_cast<unsigned char>(d.ch), c);
  }
}

TEST(TapeCode, IsoHasNoCodeAboveSevenBits) {
  EXPECT_FALSE(encode_char(TapeCode::Iso, 0xE2).has_value());  // the first byte of U+2013
}

TEST(TapeCode, EiaRowsHaveOddParityButEndOfBlock) {
  std::set<std::uint8_t> rows;
  for (const char c : kEiaAlphabet) {
    const auto row = encode_char(TapeCode::Eia, static_cast<unsigned char>(c));
    ASSERT_TRUE(row.has_value()) << c;
    if (c == '\n') {
      EXPECT_EQ(*row, kEiaEndOfBlock);
      continue;
    }
    EXPECT_FALSE(even_parity(*row)) << c;
    EXPECT_EQ(*row & 0x80U, 0U) << "channel 8 is the end of block's alone: " << c;
    if (c < 'a' || c > 'z') {
      EXPECT_TRUE(rows.insert(*row).second) << "two characters share " << c;
    }
  }
  EXPECT_EQ(encode_char(TapeCode::Eia, '%'), kEiaEndOfRecord);
}

TEST(TapeCode, EiaRefusesWhatItCannotPunch) {
  for (const char c : std::string_view("=#[]*;:_!?\"'<>")) {
    EXPECT_FALSE(encode_char(TapeCode::Eia, static_cast<unsigned char>(c)).has_value()) << c;
  }
}

TEST(TapeCode, EiaRoundTripIsUpperCase) {
  for (const char c : kEiaAlphabet) {
    const auto row = encode_char(TapeCode::Eia, static_cast<unsigned char>(c));
    const DecodedRow d = decode_row(TapeCode::Eia, *row, true);
    ASSERT_EQ(d.kind, DecodedRow::Kind::Char) << c;
    const char want = (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
    EXPECT_EQ(d.ch, want);
  }
}

// Property: any single wrong hole in a row is caught by the parity check,
// in both codes (but EIA's end of block losing its one hole: blank tape).
TEST(TapeCode, EverySingleBitErrorIsDetected) {
  for (const TapeCode code : {TapeCode::Iso, TapeCode::Eia}) {
    for (const char c : kEiaAlphabet) {
      const std::uint8_t row = *encode_char(code, static_cast<unsigned char>(c));
      for (unsigned bit = 0; bit < 8; ++bit) {
        const auto bad = static_cast<std::uint8_t>(row ^ (1U << bit));
        if (bad == 0) continue;
        const DecodedRow d = decode_row(code, bad, true);
        EXPECT_NE(d.kind, DecodedRow::Kind::Char)
            << code_name(code) << " '" << c << "' bit " << bit;
      }
    }
  }
}

TEST(TapeCode, SevenBitLinkSkipsTheParityCheck) {
  // On 7 data bits the UART strips channel 8: ISO '1' (0xB1 on tape) arrives as 0x31.
  const DecodedRow d = decode_row(TapeCode::Iso, 0x31, false);
  EXPECT_EQ(d.kind, DecodedRow::Kind::Char);
  EXPECT_EQ(d.ch, '1');
  EXPECT_EQ(decode_row(TapeCode::Iso, 0x31, true).kind, DecodedRow::Kind::BadParity);
}

TEST(TapeCode, FeedRowsAreIgnored) {
  EXPECT_EQ(decode_row(TapeCode::Iso, 0x00, true).kind, DecodedRow::Kind::Feed);
  EXPECT_EQ(decode_row(TapeCode::Iso, 0xFF, true).kind, DecodedRow::Kind::Feed);  // DEL
  EXPECT_EQ(decode_row(TapeCode::Eia, 0x00, true).kind, DecodedRow::Kind::Feed);
  EXPECT_EQ(decode_row(TapeCode::Eia, 0x7F, true).kind, DecodedRow::Kind::Feed);
}

TEST(TapeCode, RandomIsoBytesRoundTrip) {
  std::mt19937 rng(13);
  std::uniform_int_distribution<int> byte(1, 0x7E);
  for (int i = 0; i < 10000; ++i) {
    const auto c = static_cast<unsigned char>(byte(rng));
    const DecodedRow d = decode_row(TapeCode::Iso, *encode_char(TapeCode::Iso, c), true);
    ASSERT_EQ(static_cast<unsigned char>(d.ch), c);
  }
}

}  // namespace
}  // namespace usina::dnc
