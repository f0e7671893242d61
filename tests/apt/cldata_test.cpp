// Binary CLDATA: the bytes of each kind of word, records read back as they
// were written, and every way a file can break its layout.
#include "apt/cldata.hpp"

#include <cstring>

#include "apt/canon_out.hpp"
#include "apt_run.hpp"

namespace usina::apt::test {
namespace {

std::vector<ClRecord> sample() {
  return {ClRecord{cls::kSource, 7, {ClWord::number(0.0), ClWord::chars("")}, {}},
          ClRecord{cls::kPost, 1031, {ClWord::number(2000.0), ClWord::vocabulary(60)}, {}},
          ClRecord{cls::kPost, 1045, text_words("APT-1 PART", 11), {}},
          ClRecord{cls::kMotion,
                   5,
                   {symbol_word("L1"), ClWord::number(0.0), ClWord::number(3.875),
                    ClWord::number(-8.0517767), ClWord::number(1e-300)},
                   {}},
          ClRecord{cls::kFini, 0, {}, {}}};
}

std::string bytes_of(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
  std::string s;
  for (const std::uint32_t v : {a, b, c, d})
    for (int i = 0; i < 4; ++i)
      s.push_back(static_cast<char>((v >> (8 * i)) & 0xffu));
  return s;
}

TEST(AptCldata, HeaderIsFourLittleEndianIntegersThenEightByteWords) {
  const std::string b =
      write_cldata({ClRecord{cls::kPost,
                             1031,
                             {ClWord::number(1.0), ClWord::vocabulary(60), ClWord::chars("FANUC")},
                             {}}});
  ASSERT_EQ(b.size(), 16u + 3 * 8);
  EXPECT_EQ(b.substr(0, 16), bytes_of(1, 3, 2000, 1031));
  EXPECT_EQ(b.substr(16, 8), std::string("\x00\x00\x00\x00\x00\x00\xf0\x3f", 8));  // 1.0
  EXPECT_EQ(b.substr(24, 8), std::string("\x3c\x00\x00\x00\x00\x00\x00\x00", 8));  // #60
  EXPECT_EQ(b.substr(32, 8), "FANUC   ");
}

TEST(AptCldata, RecordsReadBackAsWritten) {
  core::DiagnosticList diags;
  const std::vector<ClRecord> in = sample();
  const std::vector<ClRecord> out = read_cldata(write_cldata(in), 3, diags);
  EXPECT_FALSE(diags.has_errors());
  // The text words come back padded to 6; the record print trims them.
  EXPECT_EQ(record_print(out), record_print(in));
  ASSERT_EQ(out.size(), 5u);
  EXPECT_EQ(out[1].words[1].kind, ClWord::Kind::Code);
  EXPECT_EQ(out[3].words[0].text, "    L1");
  EXPECT_EQ(out[3].words[3].real, -8.0517767);
  EXPECT_EQ(out[3].words[4].real, 0.0);  // 1e-300 is written as 0
  EXPECT_EQ(out[3].src.line, 4u);        // a record is located by its number
  EXPECT_EQ(out[3].src.file, 3u);
}

TEST(AptCldata, TextIsCutToSixCharacters) {
  core::DiagnosticList diags;
  const auto out = read_cldata(
      write_cldata({ClRecord{cls::kPost, 1015, {ClWord::chars("1STPECK")}, {}}}), 0, diags);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].words[0].text, "1STPEC");
}

void expect_broken(const std::string& bytes, std::size_t records, const std::string& why) {
  core::DiagnosticList diags;
  const auto out = read_cldata(bytes, 0, diags);
  EXPECT_EQ(out.size(), records);
  ASSERT_TRUE(diags.has_errors()) << why;
  EXPECT_EQ(diags.all()[0].code, core::Code::ClBadRecord);
  EXPECT_NE(diags.all()[0].message.find(why), std::string::npos) << diags.all()[0].message;
}

TEST(AptCldata, EveryBrokenLayoutIsAnErrorAtItsRecord) {
  const std::string good = write_cldata(sample());
  expect_broken(good.substr(0, good.size() - 16 - 3), 3, "ends inside the record's 5 words");
  expect_broken(good + std::string(5, '\0'), 5, "ends inside the record's header (5 of 16");
  expect_broken(good.substr(0, 56), 1, "ends inside the record's 2 words");
  expect_broken(bytes_of(2, 0, 14000, 0), 0, "numbered 2, expected 1");
  expect_broken(bytes_of(1, 5000, 5000, 5), 0, "5000 words; a record holds at most 4096");
  std::string nan = bytes_of(1, 1, 6000, 6);
  nan += std::string("\x00\x00\x00\x00\x00\x00\xf8\x7f", 8);
  expect_broken(nan, 0, "word 1 is not a finite number");
  std::string huge = bytes_of(1, 1, 6000, 6);
  huge += std::string("\x00\x00\x00\x00\x00\x00\xf0\x7e", 8);  // 2^1007
  expect_broken(huge, 0, "word 1 is 2.74306e+303, beyond 1e+12");
}

// A binary file's LOADTL of no tool a control has is tool 0, never an int
// out of range (fuzz_cl found it: regressions/cl/cldata_loadtl_int_overflow).
TEST(AptCldata, AToolNumberBeyondAnyToolIsToolZero) {
  struct Tools final : canon::Sink {
    void on(const canon::Op& op) override {
      if (const auto* t = std::get_if<canon::ToolChange>(&op.kind)) tools.push_back(t->tool);
    }

    std::vector<int> tools;
  } sink;

  to_canon({ClRecord{cls::kPost, 1055, {ClWord::number(1e12)}, {}},
            ClRecord{cls::kPost, 1055, {ClWord::number(7.0)}, {}}},
           1.0, sink);
  EXPECT_EQ(sink.tools, (std::vector<int>{0, 7}));
}

TEST(AptCldata, ReadingStopsWhenTheTakerSaysSo) {
  core::DiagnosticList diags;
  std::size_t seen = 0;
  read_cldata(write_cldata(sample()), 0, diags, [&seen](ClRecord&&) { return ++seen < 2; });
  EXPECT_EQ(seen, 2u);
}

}  // namespace
}  // namespace usina::apt::test
