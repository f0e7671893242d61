// What Grbl 1.1's line reader (protocol_main_loop) does with the bytes of a
// line that are not G-code: a control character such as NUL is dropped like
// a blank (reported), CR ends a line as LF does.
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "gcode/grbl/dialect.hpp"
#include "grbl_test_support.hpp"

namespace usina::gcode {
namespace {

using testing::run_grbl;

// The lines of `text` as the runner reads them, one after the other.
std::vector<grbl::LineSpan> lines_of(std::string_view text) {
  std::vector<grbl::LineSpan> out;
  for (std::uint64_t at = 0; at < text.size(); at = out.back().next)
    out.push_back(grbl::read_line(text, at));
  return out;
}

TEST(GrblText, NulInsideALineIsDroppedAsGrblDoesAndReported) {
  const auto r =
      run_grbl(std::string("G0 X1\0"
                           "20\nM30\n",
                           13));
  EXPECT_TRUE(r->ok);
  const auto moves = r->moves();
  ASSERT_EQ(moves.size(), 1u);
  EXPECT_DOUBLE_EQ(moves[0].second.x, 120.0);
  const auto warnings = r->with(core::Code::GrblWarning);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0]->severity, core::Severity::Warning);
  EXPECT_EQ(warnings[0]->loc.line, 1u);
  EXPECT_EQ(warnings[0]->loc.col, 6u);
  EXPECT_NE(warnings[0]->message.find("0x00"), std::string::npos) << warnings[0]->message;
}

TEST(GrblText, ControlCharacterInACommentOrTabIsNotReported) {
  const auto r = run_grbl(std::string("G0\tX1 (a\0b)\nM30\n", 16));
  EXPECT_TRUE(r->ok);
  EXPECT_FALSE(r->has(core::Code::GrblWarning));
  EXPECT_EQ(grbl::strip_line(std::string("X1\x01"
                                         "2",
                                         4))
                .control_col,
            3u);
  EXPECT_EQ(grbl::strip_line("X1\t2").control_col, 0u);
}

TEST(GrblText, CrAloneEndsALine) {
  const auto r = run_grbl("G0 X1\rG0 X2\rG5 X3\rM30\r");
  const auto moves = r->moves();
  ASSERT_EQ(moves.size(), 2u);
  EXPECT_DOUBLE_EQ(moves[1].second.x, 2.0);
  // G5 is refused on its own line, the third.
  ASSERT_EQ(r->errors().size(), 1u);
  EXPECT_EQ(r->errors()[0].first, 3u);
}

TEST(GrblText, CrLfIsOneLineEnd) {
  const auto r = run_grbl("G0 X1\r\nG5 X2\r\nM30\r\n");
  ASSERT_EQ(r->errors().size(), 1u);
  EXPECT_EQ(r->errors()[0].first, 2u);
}

TEST(GrblText, LinesEndAtLfCrAndCrLf) {
  const auto lines = lines_of("a\rbb\r\nc\n\nd");
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines[0].offset, 0u);
  EXPECT_EQ(lines[0].length, 1u);
  EXPECT_EQ(lines[1].offset, 2u);
  EXPECT_EQ(lines[1].length, 2u);
  EXPECT_EQ(lines[2].offset, 6u);
  EXPECT_EQ(lines[3].length, 0u);
  EXPECT_EQ(lines[4].offset, 9u);
  EXPECT_EQ(lines[4].length, 1u);
}

}  // namespace
}  // namespace usina::gcode

namespace usina::gcode {
namespace {

// A CR LF file converted once more (CR CR LF, as in UGS's ShapeOko test
// file): one line end, so the line numbers are the editor's.
TEST(GrblText, CrCrLfIsOneLineEnd) {
  const auto r = run_grbl("G0 X1\r\r\nG5 X2\r\r\nM30\r\r\n");
  ASSERT_EQ(r->errors().size(), 1u);
  EXPECT_EQ(r->errors()[0].first, 2u);
  const auto lines = lines_of("a\r\r\nb\r\rc");
  ASSERT_EQ(lines.size(), 4u);  // a, b, the blank between two lone CRs, c
  EXPECT_EQ(lines[1].offset, 4u);
  EXPECT_EQ(lines[3].offset, 7u);
}

}  // namespace
}  // namespace usina::gcode
