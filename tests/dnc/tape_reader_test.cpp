#include "dnc/tape_reader.hpp"

#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dnc/tape_code.hpp"
#include "dnc/tape_writer.hpp"

namespace usina::dnc {
namespace {

std::vector<std::uint8_t> bytes(std::string_view s) {
  return {s.begin(), s.end()};
}

std::vector<std::uint8_t> encode(std::string_view text, TapeCode code, EndOfBlock eob) {
  TapeWriter w(TapeFormat{code, eob, 10, 10, false});
  std::vector<std::uint8_t> rows;
  std::vector<BlockMark> marks;
  EXPECT_TRUE(w.write(text, rows, marks));
  EXPECT_TRUE(w.finish(rows, marks));
  return rows;
}

TEST(TapeReader, StripsDc2Dc4AndLeaderAndStopsAtTheClosingPercent) {
  TapeReader r(TapeCode::Ascii, EndOfBlock::Lf, false, 1 << 20);
  const auto rows = bytes(std::string("\x12\0\0LABEL %\nO1000\nM30\n%\x14\0\0", 25));
  EXPECT_TRUE(r.feed(rows));
  EXPECT_EQ(r.text(), "O1000\nM30\n");
  EXPECT_EQ(r.rows_after_end(), 3U);  // DC4 and the trailer
  EXPECT_EQ(program_number(r.text()), "O1000");
}

TEST(TapeReader, APunchWithoutOpeningPercentEndsAtItsPercent) {
  TapeReader r(TapeCode::Ascii, EndOfBlock::Lf, false, 1 << 20);
  EXPECT_TRUE(r.feed(bytes("O22\nM30\n%")));
  EXPECT_EQ(r.text(), "O22\nM30\n");
}

TEST(TapeReader, EndOfBlockForms) {
  struct Case {
    EndOfBlock eob;
    std::string rows;
    std::string text;
  };

  const std::vector<Case> cases{
      {EndOfBlock::CrLf, "%\r\nO1\r\nM30\r\n%", "O1\nM30\n"},
      {EndOfBlock::Cr, "%\rO1\rM30\r%", "O1\nM30\n"},
      {EndOfBlock::Semicolon, "%;O1;M30;%", "O1\nM30\n"},
      {EndOfBlock::Semicolon, "%;\nO1;\r\nM30;\n%", "O1\nM30\n"},
      {EndOfBlock::Hash, "%#N10 G99#\nN20 G90#%", "N10 G99#\nN20 G90#\n"},
  };
  for (const Case& c : cases) {
    TapeReader r(TapeCode::Ascii, c.eob, false, 1 << 20);
    EXPECT_TRUE(r.feed(bytes(c.rows)));
    EXPECT_EQ(r.text(), c.text) << eob_name(c.eob);
  }
}

TEST(TapeReader, ParityErrorsAreCountedWithTheirOffsets) {
  auto rows = encode("O1\nG0 X12.5\nM30\n", TapeCode::Iso, EndOfBlock::Lf);
  rows[15] ^= 0x04;  // one wrong hole
  TapeReader r(TapeCode::Iso, EndOfBlock::Lf, true, 1 << 20);
  EXPECT_TRUE(r.feed(rows));
  EXPECT_EQ(r.bad_rows(), 1U);
  ASSERT_EQ(r.bad_offsets().size(), 1U);
  EXPECT_EQ(r.bad_offsets()[0], 15U);
}

TEST(TapeReader, BlankTapeInsideAnEiaProgramIsABadRow) {
  auto rows = encode("O1\nG0 X1\nM30\n", TapeCode::Eia, EndOfBlock::Cr);
  rows[14] = 0x00;  // '1' (one hole) lost its hole
  TapeReader r(TapeCode::Eia, EndOfBlock::Cr, true, 1 << 20);
  r.feed(rows);
  EXPECT_EQ(r.bad_rows(), 1U);
}

TEST(TapeReader, EiaDigitThreeIsNotTakenForXoff) {
  const auto rows = encode("G0 X3\n", TapeCode::Eia, EndOfBlock::Cr);
  TapeReader r(TapeCode::Eia, EndOfBlock::Cr, true, 1 << 20);
  EXPECT_TRUE(r.feed(rows));
  EXPECT_EQ(r.text(), "G0 X3\n");
}

TEST(TapeReader, StopsCollectingPastTheLimit) {
  TapeReader r(TapeCode::Ascii, EndOfBlock::Lf, false, 8);
  r.feed(bytes("%\nO1\nG0 X1 Y2\n"));
  EXPECT_TRUE(r.too_large());
  EXPECT_EQ(r.text().size(), 8U);
}

// Property: writer then reader gives the program back (upper case in EIA),
// for every code and end of block, parity checked, in random slices.
TEST(TapeReader, RoundTripEveryCodeAndEndOfBlock) {
  std::mt19937 rng(11);
  const std::string alphabet = "GXYZIJKFSTMN0123456789.-+ /()";
  for (int trial = 0; trial < 300; ++trial) {
    std::string program = "O" + std::to_string(trial) + "\n";
    const int lines = std::uniform_int_distribution<int>(1, 20)(rng);
    for (int l = 0; l < lines; ++l) {
      const int len = std::uniform_int_distribution<int>(1, 40)(rng);
      std::string block;
      for (int i = 0; i < len; ++i)
        block += alphabet[std::uniform_int_distribution<std::size_t>(0, alphabet.size() - 1)(rng)];
      if (block.find_first_not_of(' ') == std::string::npos) block = "G0";
      while (block.back() == ' ')
        block.pop_back();
      while (block.front() == ' ')
        block.erase(0, 1);
      if (block == "%") block = "G0";
      program += block + "\n";
    }
    for (const TapeCode code : {TapeCode::Ascii, TapeCode::Iso, TapeCode::Eia}) {
      for (const EndOfBlock eob :
           {EndOfBlock::Lf, EndOfBlock::CrLf, EndOfBlock::Cr, EndOfBlock::Semicolon}) {
        if (code == TapeCode::Eia && eob == EndOfBlock::Semicolon) continue;
        const auto rows = encode(program, code, eob);
        TapeReader r(code, eob, code != TapeCode::Ascii, 1 << 20);
        std::size_t at = 0;
        while (at < rows.size()) {
          const std::size_t n =
              std::min(rows.size() - at, std::uniform_int_distribution<std::size_t>(1, 64)(rng));
          r.feed(std::span<const std::uint8_t>(rows.data() + at, n));
          at += n;
        }
        ASSERT_TRUE(r.complete());
        ASSERT_EQ(r.bad_rows(), 0U);
        ASSERT_EQ(r.text(), program) << code_name(code) << " " << eob_name(eob);
        ASSERT_EQ(program_number(r.text()), "O" + std::to_string(trial));
      }
    }
  }
}

TEST(TapeReader, ProgramNumberForms) {
  EXPECT_EQ(program_number("\n:0123\nG0\n"), "O0123");
  EXPECT_EQ(program_number("(NO NUMBER)\nG0\n"), "");
  EXPECT_EQ(program_number("  O55 (X)\n"), "O55");
}

}  // namespace
}  // namespace usina::dnc
