#include "dnc/tape_writer.hpp"

#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dnc/tape_code.hpp"

namespace usina::dnc {
namespace {

struct Written {
  bool ok = true;
  std::vector<std::uint8_t> rows;
  std::vector<BlockMark> marks;
  TapeWriter writer;
};

std::string as_text(const std::vector<std::uint8_t>& rows) {
  return std::string(rows.begin(), rows.end());
}

Written write_all(std::string_view text, TapeFormat f) {
  Written w{true, {}, {}, TapeWriter(f)};
  w.ok = w.writer.write(text, w.rows, w.marks) && w.writer.finish(w.rows, w.marks);
  return w;
}

TapeFormat ascii(EndOfBlock eob, std::uint32_t leader = 0, std::uint32_t trailer = 0) {
  return TapeFormat{TapeCode::Ascii, eob, leader, trailer, false};
}

TEST(TapeWriter, FramesTheProgramWithPercentAndFeedOutside) {
  const Written w = write_all("O1000\nG0 X1\nM30\n", ascii(EndOfBlock::Lf, 3, 2));
  ASSERT_TRUE(w.ok);
  EXPECT_EQ(as_text(w.rows), std::string("\0\0\0%\nO1000\nG0 X1\nM30\n%\0\0", 24));
}

TEST(TapeWriter, TheProgramsOwnPercentIsNotSentTwice) {
  const Written w = write_all("%\nO1000\nM30\n%\n", ascii(EndOfBlock::Lf));
  EXPECT_EQ(as_text(w.rows), "%\nO1000\nM30\n%");
}

TEST(TapeWriter, WhatFollowsTheClosingPercentIsNotSentButCounted) {
  const Written w = write_all("%\nO1\nM30\n%\nG0 X9\n", ascii(EndOfBlock::Lf));
  EXPECT_EQ(as_text(w.rows), "%\nO1\nM30\n%");
  EXPECT_EQ(w.writer.ignored_bytes(), 5U);
}

TEST(TapeWriter, EveryEndOfBlock) {
  const std::string program = "O1\r\nG0 X1\rM30";  // CRLF, CR and no end at all
  EXPECT_EQ(as_text(write_all(program, ascii(EndOfBlock::Lf)).rows), "%\nO1\nG0 X1\nM30\n%");
  EXPECT_EQ(as_text(write_all(program, ascii(EndOfBlock::CrLf)).rows),
            "%\r\nO1\r\nG0 X1\r\nM30\r\n%");
  EXPECT_EQ(as_text(write_all(program, ascii(EndOfBlock::Cr)).rows), "%\rO1\rG0 X1\rM30\r%");
  EXPECT_EQ(as_text(write_all(program, ascii(EndOfBlock::Semicolon)).rows), "%;O1;G0 X1;M30;%");
  EXPECT_EQ(as_text(write_all(program, ascii(EndOfBlock::Hash)).rows), "%#O1#G0 X1#M30#%");
}

TEST(TapeWriter, ARomiBlockEndingInHashGetsNoSecondOne) {
  const Written w = write_all("N0010 G99#\nN0020 G90#\n", ascii(EndOfBlock::Hash));
  EXPECT_EQ(as_text(w.rows), "%#N0010 G99#N0020 G90#%");
}

TEST(TapeWriter, BlankLinesInsideTheFrameAreNotSent) {
  EXPECT_EQ(as_text(write_all("O1\n\n  \nM30\n", ascii(EndOfBlock::Lf)).rows), "%\nO1\nM30\n%");
}

TEST(TapeWriter, IsoRowsCarryEvenParity) {
  const Written w = write_all("O1\nM30\n", TapeFormat{TapeCode::Iso, EndOfBlock::Lf, 2, 2, false});
  ASSERT_TRUE(w.ok);
  for (const std::uint8_t r : w.rows)
    EXPECT_TRUE(even_parity(r));
  EXPECT_EQ(w.rows[2], 0xA5);  // '%' 0x25 has three holes: channel 8 added
}

TEST(TapeWriter, EiaUsesErAndItsEndOfBlock) {
  const Written w = write_all("o1\nm30\n", TapeFormat{TapeCode::Eia, EndOfBlock::Cr, 0, 0, false});
  ASSERT_TRUE(w.ok);
  const std::vector<std::uint8_t> want{kEiaEndOfRecord, kEiaEndOfBlock, 0x46, 0x01,
                                       kEiaEndOfBlock,  0x54,           0x13, 0x20,
                                       kEiaEndOfBlock,  kEiaEndOfRecord};
  EXPECT_EQ(w.rows, want);
}

TEST(TapeWriter, ACharacterWithoutCodeIsAnErrorNamingLineAndColumn) {
  const Written w = write_all("O1\n#1=5\n", TapeFormat{TapeCode::Eia, EndOfBlock::Lf, 0, 0, false});
  EXPECT_FALSE(w.ok);
  EXPECT_EQ(w.writer.diagnostic().code, core::Code::TapeNoCode);
  EXPECT_NE(w.writer.diagnostic().message.find("line 2 column 1"), std::string::npos)
      << w.writer.diagnostic().message;
}

TEST(TapeWriter, ATypographicDashHasNoIsoCode) {
  const Written w = write_all(
      "N0120 G1 Y\xE2\x80\x93"
      "250.\n",
      TapeFormat{TapeCode::Iso, EndOfBlock::Lf, 0, 0, false});
  EXPECT_FALSE(w.ok);
  EXPECT_EQ(w.writer.diagnostic().code, core::Code::TapeNoCode);
}

TEST(TapeWriter, ASevenBitAsciiLinkRefusesHighBytes) {
  EXPECT_FALSE(write_all("X\xE9\n", TapeFormat{TapeCode::Ascii, EndOfBlock::Lf, 0, 0, true}).ok);
  EXPECT_TRUE(write_all("X\xE9\n", TapeFormat{TapeCode::Ascii, EndOfBlock::Lf, 0, 0, false}).ok);
}

TEST(TapeWriter, ABlockLongerThanTheLimitIsAnError) {
  const Written w = write_all(std::string(kMaxTapeBlock + 10, 'X') + "\n", ascii(EndOfBlock::Lf));
  EXPECT_FALSE(w.ok);
  EXPECT_EQ(w.writer.diagnostic().code, core::Code::BlockTooLong);
}

TEST(TapeWriter, MarksGiveLineAndBlockNumberAtEachBlockEnd) {
  const Written w = write_all("%\nO1\nN10 G0\n/N20 X1\nM30\n", ascii(EndOfBlock::Lf));
  ASSERT_EQ(w.marks.size(), 4U);
  EXPECT_EQ(w.marks[0].line, 2U);
  EXPECT_EQ(w.marks[0].n_number, -1);
  EXPECT_EQ(w.marks[1].line, 3U);
  EXPECT_EQ(w.marks[1].n_number, 10);
  EXPECT_EQ(w.marks[2].n_number, 20);
  EXPECT_EQ(w.marks[1].wire_end, std::string("%\nO1\nN10 G0\n").size());
}

// Property: the rows do not depend on how the text is cut into slices.
TEST(TapeWriter, SlicesGiveTheSameRowsAsTheWhole) {
  const std::string program = "%\r\nO1234 (PART)\r\nN10 G0 X1\r\n\r\nN20 G1 Y-2 F100\rM30\r\n%\r\n";
  std::mt19937 rng(7);
  for (const EndOfBlock eob : {EndOfBlock::Lf, EndOfBlock::CrLf, EndOfBlock::Hash}) {
    const TapeFormat f{TapeCode::Iso, eob, 5, 5, false};
    const Written whole = write_all(program, f);
    for (int trial = 0; trial < 200; ++trial) {
      TapeWriter w(f);
      std::vector<std::uint8_t> rows;
      std::vector<BlockMark> marks;
      std::size_t at = 0;
      while (at < program.size()) {
        const std::size_t n = std::uniform_int_distribution<std::size_t>(1, 7)(rng);
        ASSERT_TRUE(w.write(std::string_view(program).substr(at, n), rows, marks));
        at += n;
      }
      ASSERT_TRUE(w.finish(rows, marks));
      ASSERT_EQ(rows, whole.rows) << "trial " << trial;
    }
  }
}

TEST(TapeWriter, BlockNumber) {
  EXPECT_EQ(block_number("N0120 G1"), 120);
  EXPECT_EQ(block_number(" / n5"), 5);
  EXPECT_EQ(block_number("G1 N5"), -1);
  EXPECT_EQ(block_number("N"), -1);
}

}  // namespace
}  // namespace usina::dnc
