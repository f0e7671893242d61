// The rules of a program's text every dialect shares (gcode/program_text.hpp):
// the block-length limit and the UTF-8 byte-order mark, each checked through
// the four dialects' runners.
#include "gcode/program_text.hpp"

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gcode/parser.hpp"
#include "support/dialect_run.hpp"

namespace usina::gcode {
namespace {

using dialect_test::Run;
using dialect_test::run_in;

constexpr const char* kDialects[] = {"rs274ngc", "fanuc", "romi", "grbl"};

const core::Diagnostic* first(const Run& r, core::Code code) {
  for (const core::Diagnostic& d : r.diags.all())
    if (d.code == code) return &d;
  return nullptr;
}

// "G0 X1 (AAA...)" padded with the comment to exactly `length` characters.
std::string commented_block(std::size_t length) {
  std::string b = "G0 X1 (";
  b += std::string(length - b.size() - 1, 'A');
  b += ')';
  return b;
}

TEST(BlockLength, ALongLineIsAnErrorWithItsOwnCodeInEveryDialect) {
  std::string line = "G0 X1";
  while (line.size() <= kMaxBlockLength)
    line += " Y1";
  for (const char* dialect : kDialects) {
    SCOPED_TRACE(dialect);
    const auto r = run_in(dialect, line + "\nM30\n");
    EXPECT_FALSE(r->ok);
    const core::Diagnostic* d = first(*r, core::Code::BlockTooLong);
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->severity, core::Severity::Error);
    EXPECT_EQ(d->loc.line, 1u);
    EXPECT_NE(d->message.find(std::to_string(line.size())), std::string::npos) << d->message;
    EXPECT_NE(d->message.find("4096"), std::string::npos) << d->message;
    EXPECT_TRUE(r->ends().empty());
  }
}

TEST(BlockLength, ALongCommentIsAnErrorInEveryDialect) {
  const std::string program = commented_block(kMaxBlockLength + 1) + "\nM30\n";
  for (const char* dialect : kDialects) {
    SCOPED_TRACE(dialect);
    const auto r = run_in(dialect, program);
    EXPECT_FALSE(r->ok);
    EXPECT_EQ(r->first_error(), core::Code::BlockTooLong);
  }
}

TEST(BlockLength, ABlockOfExactlyTheLimitIsReadInEveryDialect) {
  const std::string program = commented_block(kMaxBlockLength) + "\nM30\n";
  ASSERT_EQ(program.find('\n'), kMaxBlockLength);
  for (const char* dialect : kDialects) {
    SCOPED_TRACE(dialect);
    const auto r = run_in(dialect, program);
    EXPECT_TRUE(r->ok) << r->first_error_text();
    EXPECT_FALSE(r->has(core::Code::BlockTooLong));
    ASSERT_EQ(r->ends().size(), 1u);
    EXPECT_DOUBLE_EQ(r->ends()[0].x, 1.0);
  }
}

TEST(BlockLength, TheCaretIsOnTheFirstCharacterBeyondTheLimit) {
  const auto r = run_in("rs274ngc", "G0 X1\n" + commented_block(kMaxBlockLength + 10) + "\nM30\n");
  const core::Diagnostic* d = first(*r, core::Code::BlockTooLong);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, 2u);
  EXPECT_EQ(d->loc.col, kMaxBlockLength + 1);
  EXPECT_EQ(d->loc.line_offset, 6u);
  // The block before it ran: the error stops the run where it is.
  EXPECT_EQ(r->ends().size(), 1u);
}

TEST(BlockLength, AFanucBlockCountsFromItsStartNotTheLine) {
  // ';' ends a Fanuc block: the long block starts at column 7.
  const auto r = run_in("fanuc", "G0 X1.;" + commented_block(kMaxBlockLength + 1) + "\nM30\n");
  const core::Diagnostic* d = first(*r, core::Code::BlockTooLong);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.col, 8 + kMaxBlockLength);
  // A line of many short blocks is no long block.
  std::string line;
  while (line.size() <= 2 * kMaxBlockLength)
    line += "G0 X1.;";
  const auto many = run_in("fanuc", line + "\nM30\n");
  EXPECT_TRUE(many->ok) << many->first_error_text();
}

TEST(BlockLength, DeepBracketsAreACleanErrorInEveryDialect) {
  const std::string deep = "G1 F100 X" + std::string(1000, '[') + "1" + std::string(1000, ']');
  const std::vector<std::pair<const char*, core::Code>> cases = {
      {"rs274ngc", core::Code::ExpectedExpression},  // nested more than 64 deep
      {"fanuc", core::Code::UnclosedBracket},        // Fanuc alarm 118: 5 levels
      {"romi", core::Code::UnexpectedCharacter},     // romi expressions live in ( )
      {"grbl", core::Code::GrblError},               // error:11, line overflow
  };
  for (const auto& [dialect, code] : cases) {
    SCOPED_TRACE(dialect);
    const auto r = run_in(dialect, deep + "\nM30\n");
    EXPECT_FALSE(r->ok);
    EXPECT_EQ(r->first_error(), code);
  }
}

TEST(BlockLength, AFileOfCrAloneLineEndsSaysSo) {
  std::string program;
  while (program.size() <= kMaxBlockLength)
    program += "G0 X1\r";
  const auto r = run_in("rs274ngc", program);
  const core::Diagnostic* d = first(*r, core::Code::BlockTooLong);
  ASSERT_NE(d, nullptr);
  EXPECT_NE(d->message.find("CR alone"), std::string::npos) << d->message;
  // CR LF line ends are no hint.
  const auto crlf =
      check_block_length(std::string(kMaxBlockLength + 1, 'A') + "\r", {1, 1, 1, 0, 0});
  ASSERT_FALSE(crlf.has_value());
  EXPECT_EQ(crlf.error().message.find("CR alone"), std::string::npos);
  EXPECT_TRUE(check_block_length(std::string(kMaxBlockLength, 'A'), {1, 1, 1, 0, 0}));
}

TEST(BlockLength, TooManyValuesInABlockIsABlockTooLongError) {
  // The parser's own bound, met by text the runners write for it (the
  // fanuc front end's blocks): past it, the block-length code, not
  // E_EXPECTED_EXPRESSION.
  std::string line = "#1=[1";
  for (int i = 0; i < 3000; ++i)
    line += "+1";
  line += "]";
  Block block;
  core::DiagnosticList diags;
  EXPECT_FALSE(parse_block(line, {1, 1, 0}, block, diags));
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(diags.all()[0].code, core::Code::BlockTooLong);
}

TEST(BlockLength, AnOWordLineOverTheLimitIsReportedNotIndexed) {
  const std::string name(kMaxBlockLength, 'a');
  const auto r = run_in("rs274ngc", "o<" + name + "> sub\nG0 X1\no<" + name + "> endsub\nM30\n");
  EXPECT_FALSE(r->ok);
  EXPECT_EQ(r->first_error(), core::Code::BlockTooLong);
}

TEST(ByteOrderMark, IsAWarningAndSkippedInEveryDialect) {
  for (const char* dialect : kDialects) {
    SCOPED_TRACE(dialect);
    const auto r = run_in(dialect, "\xEF\xBB\xBFG0 X1\nM30\n");
    EXPECT_TRUE(r->ok) << r->first_error_text();
    const core::Diagnostic* d = first(*r, core::Code::ByteOrderMark);
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->severity, core::Severity::Warning);
    EXPECT_EQ(d->loc.line, 1u);
    ASSERT_EQ(r->ends().size(), 1u);
    EXPECT_DOUBLE_EQ(r->ends()[0].x, 1.0);
  }
}

TEST(ByteOrderMark, FanucTapeAfterTheMarkStartsAtItsPercentLine) {
  const auto r = run_in("fanuc", "\xEF\xBB\xBF%\nO1000\nG0 X1.\nM30\n%\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  EXPECT_TRUE(r->has(core::Code::ByteOrderMark));
  ASSERT_EQ(r->ends().size(), 1u);
  EXPECT_DOUBLE_EQ(r->ends()[0].x, 1.0);
}

TEST(ByteOrderMark, OnlyAtTheStartOfTheText) {
  core::DiagnosticList diags;
  EXPECT_EQ(skip_byte_order_mark("G0 X1", 1, diags), 0u);
  EXPECT_EQ(skip_byte_order_mark("G0 \xEF\xBB\xBF", 1, diags), 0u);
  EXPECT_TRUE(diags.all().empty());
  EXPECT_EQ(skip_byte_order_mark("\xEF\xBB\xBFG0", 1, diags), 3u);
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(diags.all()[0].code, core::Code::ByteOrderMark);
}

// A called file with a mark: written to a scratch folder on the path.
class SubFolder {
 public:
  SubFolder() {
    char name[] = "/tmp/usina_bom_XXXXXX";
    const char* made = ::mkdtemp(name);
    EXPECT_NE(made, nullptr);
    path_ = made != nullptr ? made : "/tmp";
  }

  ~SubFolder() { std::filesystem::remove_all(path_); }

  SubFolder(const SubFolder&) = delete;
  SubFolder& operator=(const SubFolder&) = delete;

  void write(const std::string& name, const std::string& text) const {
    std::ofstream(path_ + "/" + name, std::ios::binary) << text;
  }

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

TEST(ByteOrderMark, ACalledFileWithAMarkRunsWithTheWarningInRs274ngcAndFanuc) {
  const SubFolder dir;
  dir.write("side.ngc", "\xEF\xBB\xBFo<side> sub\nG0 X2\no<side> endsub\n");
  dir.write("whole.ngc", "\xEF\xBB\xBFG0 Y3\n");
  dir.write("O1234.nc", "\xEF\xBB\xBF%\nO1234\nG0 Z4.\nM99\n%\n");
  InterpOptions opts;
  opts.subroutine_path = {dir.path()};
  const auto r = run_in("rs274ngc", "o<side> call\no<whole> call\no<side> call\nM30\n", opts);
  EXPECT_TRUE(r->ok) << r->first_error_text();
  ASSERT_EQ(r->ends().size(), 3u);
  EXPECT_DOUBLE_EQ(r->ends()[0].x, 2.0);
  EXPECT_DOUBLE_EQ(r->ends()[1].y, 3.0);
  int marks = 0;
  for (const core::Diagnostic& d : r->diags.all())
    marks += d.code == core::Code::ByteOrderMark ? 1 : 0;
  EXPECT_EQ(marks, 2);  // once a file, not once a call
  const auto f = run_in("fanuc", "M98 P1234\nM30\n", opts);
  EXPECT_TRUE(f->ok) << f->first_error_text();
  EXPECT_TRUE(f->has(core::Code::ByteOrderMark));
  ASSERT_EQ(f->ends().size(), 1u);
  EXPECT_DOUBLE_EQ(f->ends()[0].z, 4.0);
}

}  // namespace
}  // namespace usina::gcode
