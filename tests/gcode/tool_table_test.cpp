#include "gcode/tool_table.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/diagnostic.hpp"
#include "core/source.hpp"
#include "core/units.hpp"

namespace usina::gcode {
namespace {

using core::Code;
using core::Severity;

constexpr double kInch = core::kMmPerInch;
constexpr std::uint32_t kFileId = 3;

struct Read {
  std::unique_ptr<core::SourceFile> file;
  core::DiagnosticList diags;
  std::optional<ToolTable> table;
};

// Reads `text` as a tool table of an inch machine unless told otherwise.
std::unique_ptr<Read> read(std::string text, double mm_per_unit = kInch) {
  auto r = std::make_unique<Read>();
  r->file = core::SourceFile::from_string("tools.tbl", std::move(text));
  r->table = read_tool_table(*r->file, kFileId, mm_per_unit, r->diags);
  return r;
}

std::unique_ptr<Read> read_shared(const std::string& name) {
  auto r = std::make_unique<Read>();
  std::string error;
  r->file = core::SourceFile::open(USINA_SHARED_DIR "/conformance/rs274ngc/tools/" + name, error);
  EXPECT_NE(r->file, nullptr) << error;
  if (r->file != nullptr) r->table = read_tool_table(*r->file, kFileId, kInch, r->diags);
  return r;
}

// A diagnostic's code, severity and place, as one comparable line.
std::string where(const core::Diagnostic& d) {
  return fmt::format("{} {} file {} line {} col {} length {}", core::code_name(d.code),
                     core::severity_name(d.severity), d.loc.file, d.loc.line, d.loc.col,
                     d.loc.length);
}

// The only diagnostic of `r`, checked for code, severity, place and length.
const core::Diagnostic& only(const Read& r, Severity severity, std::uint32_t line,
                             std::uint32_t col, std::uint32_t length,
                             Code code = Code::BadToolTable) {
  static const core::Diagnostic kNone{};
  EXPECT_EQ(r.diags.all().size(), 1u);
  const core::Diagnostic& d = r.diags.all().empty() ? kNone : r.diags.all().front();
  const core::Diagnostic want{code, severity, {kFileId, line, col, length, 0}, ""};
  EXPECT_EQ(where(d), where(want)) << d.message;
  return d;
}

// A table of one good line and one bad: the bad line's error, the good tool kept.
const core::Diagnostic& bad_second_line(const Read& r, std::uint32_t col, std::uint32_t length) {
  EXPECT_TRUE(r.table.has_value());
  if (r.table) {
    EXPECT_EQ(r.table->size(), 1u);
    EXPECT_NE(r.table->find(1), nullptr);
  }
  return only(r, Severity::Error, 2, col, length);
}

TEST(ToolTable, GenericTableFromConformanceSet) {
  const auto r = read_shared("generic.tbl");
  ASSERT_TRUE(r->table.has_value());
  EXPECT_TRUE(r->diags.all().empty());
  EXPECT_EQ(r->table->size(), 23u);
  const ToolEntry* t1 = r->table->find(1);
  ASSERT_NE(t1, nullptr);
  EXPECT_EQ(t1->pocket, 1);
  EXPECT_DOUBLE_EQ(t1->offset.z, 0.511 * kInch);
  EXPECT_DOUBLE_EQ(t1->diameter, 0.125 * kInch);
  EXPECT_EQ(t1->comment, "1/8 end mill");
  const ToolEntry* t4 = r->table->find(4);
  ASSERT_NE(t4, nullptr);
  EXPECT_DOUBLE_EQ(t4->diameter, 0.005 * kInch);  // written "D.005"
  EXPECT_EQ(t4->offset.z, 0.0);
  const ToolEntry* big = r->table->find(98876);
  ASSERT_NE(big, nullptr);
  EXPECT_EQ(big->pocket, 543);
  EXPECT_DOUBLE_EQ(big->offset.z, 0.1 * kInch);  // written "Z+0.100000"
  EXPECT_EQ(big->diameter, 0.0);
  EXPECT_EQ(big->comment, "big tool number");
  ASSERT_NE(r->table->find(99999), nullptr);
  EXPECT_EQ(r->table->find(99999)->pocket, 99999);
  EXPECT_EQ(r->table->find(21), nullptr);
}

TEST(ToolTable, SimTableAsLinuxCncWritesIt) {
  const auto r = read_shared("sim.tbl");
  ASSERT_TRUE(r->table.has_value());
  EXPECT_TRUE(r->diags.all().empty());
  ASSERT_EQ(r->table->size(), 4u);
  const ToolEntry* t3 = r->table->find(3);
  ASSERT_NE(t3, nullptr);
  EXPECT_DOUBLE_EQ(t3->diameter, 0.201 * kInch);
  EXPECT_DOUBLE_EQ(t3->offset.z, 1.273 * kInch);
  EXPECT_EQ(t3->comment, "#7 tap drill");
}

TEST(ToolTable, InchLengthsBecomeMmAnglesStay) {
  const auto r = read("T7 P2 X1 Y-2 Z0.5 A10 B20 C30 U1 V2 W3 D0.25 I80 J-5 Q3 ;lathe\n");
  ASSERT_TRUE(r->table.has_value());
  EXPECT_TRUE(r->diags.all().empty());
  const ToolEntry* t = r->table->find(7);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->number, 7);
  EXPECT_EQ(t->pocket, 2);
  EXPECT_DOUBLE_EQ(t->offset.x, 25.4);
  EXPECT_DOUBLE_EQ(t->offset.y, -50.8);
  EXPECT_DOUBLE_EQ(t->offset.z, 12.7);
  EXPECT_EQ(t->abc_offset, (std::array<double, 3>{10, 20, 30}));
  EXPECT_DOUBLE_EQ(t->uvw_offset[0], 25.4);
  EXPECT_DOUBLE_EQ(t->uvw_offset[1], 50.8);
  EXPECT_DOUBLE_EQ(t->uvw_offset[2], 76.2);
  EXPECT_DOUBLE_EQ(t->diameter, 6.35);
  EXPECT_EQ(t->front_angle, 80.0);
  EXPECT_EQ(t->back_angle, -5.0);
  EXPECT_EQ(t->orientation, 3);
  EXPECT_EQ(t->comment, "lathe");
}

TEST(ToolTable, MetricMachineKeepsValues) {
  const auto r = read("T5 P5 Z12.5 D6\n", 1.0);
  ASSERT_TRUE(r->table.has_value());
  EXPECT_EQ(r->table->find(5)->offset.z, 12.5);
  EXPECT_EQ(r->table->find(5)->diameter, 6.0);
}

// A job reading the table as its tool library reports at the tool's line.
TEST(ToolTable, EachToolKeepsTheLineItWasReadFrom) {
  const auto r = read("; header\nT5 P5 D6\n\nT2 P2 D3\nT5 P5 D6.8 ;again\n", 1.0);
  ASSERT_TRUE(r->table.has_value());
  EXPECT_EQ(r->table->find(2)->line, 4u);
  EXPECT_EQ(r->table->find(5)->line, 5u);  // the line that replaced it
}

TEST(ToolTable, WordsAreCaseInsensitiveAndInAnyOrder) {
  const auto r = read("d0.5 z1 p3 t9 q2 ;any order\n");
  ASSERT_TRUE(r->table.has_value());
  EXPECT_TRUE(r->diags.all().empty());
  const ToolEntry* t = r->table->find(9);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->pocket, 3);
  EXPECT_DOUBLE_EQ(t->diameter, 12.7);
  EXPECT_DOUBLE_EQ(t->offset.z, 25.4);
  EXPECT_EQ(t->orientation, 2);
}

TEST(ToolTable, BlankAndCommentLinesAreSkipped) {
  const auto r = read(
      ";Tool Pocket X Offset Z Offset Diameter Remark\n"
      "\n"
      "   \t\n"
      "  ; indented comment\n"
      "T1 P1 Z1\n"
      ";\n");
  ASSERT_TRUE(r->table.has_value());
  EXPECT_TRUE(r->diags.all().empty());
  EXPECT_EQ(r->table->size(), 1u);
}

TEST(ToolTable, TabsCrLfAndNoFinalNewline) {
  const auto r = read("T1\tP1\tZ1 ;one\r\nT2  P2 \t Z2\r\nT3 P3 Z3");
  ASSERT_TRUE(r->table.has_value());
  EXPECT_TRUE(r->diags.all().empty());
  ASSERT_EQ(r->table->size(), 3u);
  EXPECT_EQ(r->table->find(1)->comment, "one");
  EXPECT_DOUBLE_EQ(r->table->find(3)->offset.z, 3 * kInch);
}

TEST(ToolTable, CommentKeptTrimmedWithItsSemicolonsAndParentheses) {
  const auto r = read("T1 P1 ;  (6mm; 2 flute) carbide  \nT2 P2 ;\nT3 P3\n");
  ASSERT_TRUE(r->table.has_value());
  EXPECT_EQ(r->table->find(1)->comment, "(6mm; 2 flute) carbide");
  EXPECT_EQ(r->table->find(2)->comment, "");
  EXPECT_EQ(r->table->find(3)->comment, "");
}

TEST(ToolTable, PlusSignAndExponentNumbers) {
  const auto r = read("T+4 P+4 Z-0.5 D2.5e-1 X+.5\n");
  ASSERT_TRUE(r->table.has_value());
  EXPECT_TRUE(r->diags.all().empty());
  const ToolEntry* t = r->table->find(4);
  ASSERT_NE(t, nullptr);
  EXPECT_DOUBLE_EQ(t->offset.z, -12.7);
  EXPECT_DOUBLE_EQ(t->diameter, 6.35);
  EXPECT_DOUBLE_EQ(t->offset.x, 12.7);
}

TEST(ToolTable, ByteOrderMarkIsSkipped) {
  const auto r = read("\xEF\xBB\xBFT1 P1 Z1\n");
  ASSERT_TRUE(r->table.has_value());
  EXPECT_TRUE(r->diags.all().empty());
  EXPECT_NE(r->table->find(1), nullptr);
}

TEST(ToolTable, ToolZeroIsAllowed) {
  const auto r = read("T0 P0 Z0\n");
  ASSERT_TRUE(r->table.has_value());
  EXPECT_TRUE(r->diags.all().empty());
  EXPECT_NE(r->table->find(0), nullptr);
}

TEST(ToolTable, EmptyFileIsAnEmptyTable) {
  const auto r = read("");
  ASSERT_TRUE(r->table.has_value());
  EXPECT_TRUE(r->table->empty());
  EXPECT_TRUE(r->diags.all().empty());
  const auto c = read("; only a comment\n\n");
  ASSERT_TRUE(c->table.has_value());
  EXPECT_TRUE(c->table->empty());
}

TEST(ToolTable, UnknownWordLetter) {
  const auto r = read("T1 P1\nT2 P2 K5 Z1\n");
  const auto& d = bad_second_line(*r, 7, 1);
  EXPECT_NE(d.message.find("unknown word K"), std::string::npos) << d.message;
}

TEST(ToolTable, LowercaseUnknownWordNamedAsWritten) {
  const auto r = read("T1 P1\nT2 P2 r5\n");
  const auto& d = bad_second_line(*r, 7, 1);
  EXPECT_NE(d.message.find("unknown word r"), std::string::npos) << d.message;
}

TEST(ToolTable, WordWithoutNumber) {
  const auto r = read("T1 P1\nT2 P2 D Z1\n");
  const auto& d = bad_second_line(*r, 7, 1);
  EXPECT_NE(d.message.find("D has no number"), std::string::npos) << d.message;
}

TEST(ToolTable, BlankBetweenLetterAndNumberIsTwoErrors) {
  const auto r = read("T1 P1\nT 2 P2\n");
  ASSERT_TRUE(r->table.has_value());
  ASSERT_EQ(r->diags.all().size(), 2u);
  EXPECT_EQ(r->diags.all()[0].loc.col, 1u);
  EXPECT_NE(r->diags.all()[0].message.find("T has no number"), std::string::npos);
  EXPECT_EQ(r->diags.all()[1].loc.col, 3u);
  EXPECT_NE(r->diags.all()[1].message.find("'2' has no word letter"), std::string::npos);
}

TEST(ToolTable, MalformedRealNumber) {
  const auto r = read("T1 P1\nT2 P2 Z1.2.3\n");
  const auto& d = bad_second_line(*r, 8, 5);  // the value after the letter
  EXPECT_NE(d.message.find("Z value '1.2.3' is not a number"), std::string::npos) << d.message;
}

TEST(ToolTable, TrailingGarbageAfterNumber) {
  const auto r = read("T1 P1\nT2 P2 D0.25mm\n");
  const auto& d = bad_second_line(*r, 8, 6);
  EXPECT_NE(d.message.find("'0.25mm'"), std::string::npos) << d.message;
}

TEST(ToolTable, InfinityAndNanAreNotNumbers) {
  const auto r = read("T1 P1\nT2 P2 Dinf\n");
  bad_second_line(*r, 8, 3);
  const auto n = read("T1 P1\nT2 P2 Znan\n");
  bad_second_line(*n, 8, 3);
}

TEST(ToolTable, DoubleSignIsMalformed) {
  const auto r = read("T1 P1\nT2 P2 Z+-1\n");
  bad_second_line(*r, 8, 3);
}

TEST(ToolTable, RealOutOfRange) {
  const auto r = read("T1 P1\nT2 P2 Z1e999\n");
  const auto& d = bad_second_line(*r, 8, 5);
  EXPECT_NE(d.message.find("out of the range"), std::string::npos) << d.message;
}

TEST(ToolTable, FractionalToolNumber) {
  const auto r = read("T1 P1\nT2.5 P2\n");
  const auto& d = bad_second_line(*r, 2, 3);
  EXPECT_NE(d.message.find("tool number '2.5' is not an integer"), std::string::npos) << d.message;
}

TEST(ToolTable, ToolNumberTooLarge) {
  const auto r = read("T1 P1\nT99999999999 P2\n");
  const auto& d = bad_second_line(*r, 2, 11);
  EXPECT_NE(d.message.find("too large"), std::string::npos) << d.message;
}

TEST(ToolTable, NegativeToolNumber) {
  const auto r = read("T1 P1\n  T-3 P2 Z1\n");
  const auto& d = bad_second_line(*r, 4, 2);
  EXPECT_NE(d.message.find("tool number -3 is out of range; it must be 0 or more"),
            std::string::npos)
      << d.message;
}

TEST(ToolTable, NegativePocket) {
  const auto r = read("T1 P1\nT2 P-1\n");
  const auto& d = bad_second_line(*r, 5, 2);
  EXPECT_NE(d.message.find("pocket number -1"), std::string::npos) << d.message;
}

TEST(ToolTable, OrientationOutOfRange) {
  const auto r = read("T1 P1\nT2 P2 Q10\n");
  const auto& d = bad_second_line(*r, 8, 2);
  EXPECT_NE(d.message.find("orientation 10 is out of range; it must be 0..9"), std::string::npos)
      << d.message;
}

TEST(ToolTable, OrientationNotInteger) {
  const auto r = read("T1 P1\nT2 P2 Q1.5\n");
  bad_second_line(*r, 8, 3);
}

TEST(ToolTable, RepeatedWordOnOneLine) {
  const auto r = read("T1 P1\nT2 P2 Z1 z2\n");
  const auto& d = bad_second_line(*r, 10, 2);
  EXPECT_NE(d.message.find("Z given twice"), std::string::npos) << d.message;
}

TEST(ToolTable, LineWithoutToolNumber) {
  const auto r = read("T1 P1\n P2 Z1 ;no tool\n");
  const auto& d = bad_second_line(*r, 2, 5);
  EXPECT_NE(d.message.find("no T word"), std::string::npos) << d.message;
}

TEST(ToolTable, OldColumnFormatIsExplained) {
  const auto r = read("T1 P1\n2 2 0.5 0.25 ;pre-2.4\n");
  const auto& d = bad_second_line(*r, 1, 1);
  EXPECT_NE(d.message.find("before 2.4"), std::string::npos) << d.message;
}

TEST(ToolTable, StrayCharacter) {
  const auto r = read("T1 P1\nT2 P2 # Z1\n");
  const auto& d = bad_second_line(*r, 7, 1);
  EXPECT_NE(d.message.find("'#' has no word letter"), std::string::npos) << d.message;
}

TEST(ToolTable, EveryErrorOfALineIsReported) {
  const auto r = read("T1 P1\nTx P2 K1 Q12\n");
  ASSERT_TRUE(r->table.has_value());
  EXPECT_EQ(r->table->size(), 1u);
  ASSERT_EQ(r->diags.all().size(), 3u);
  EXPECT_EQ(r->diags.all()[0].loc.col, 2u);
  EXPECT_EQ(r->diags.all()[1].loc.col, 7u);
  EXPECT_EQ(r->diags.all()[2].loc.col, 11u);
  EXPECT_EQ(r->diags.error_count(), 3);
}

TEST(ToolTable, DuplicateToolWarnsAndLaterLineWins) {
  const auto r = read("T1 P1 Z1 ;first\nT2 P2\nT1 P3 Z2 ;second\n");
  ASSERT_TRUE(r->table.has_value());
  const auto& d = only(*r, Severity::Warning, 3, 1, 8, Code::ToolRedefined);
  EXPECT_NE(d.message.find("tool 1 is also on line 1"), std::string::npos) << d.message;
  EXPECT_EQ(r->table->size(), 2u);
  const ToolEntry* t = r->table->find(1);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->pocket, 3);
  EXPECT_EQ(t->comment, "second");
  EXPECT_FALSE(r->diags.has_errors());
}

TEST(ToolTable, ThirdCopyNamesTheLineItReplaces) {
  const auto r = read("T1 P1\nT1 P2\nT1 P3\n");
  ASSERT_EQ(r->diags.all().size(), 2u);
  EXPECT_NE(r->diags.all()[1].message.find("also on line 2"), std::string::npos);
  EXPECT_EQ(r->table->find(1)->pocket, 3);
}

TEST(ToolTable, MissingPocketWarns) {
  const auto r = read("T4 Z1 D0.5\n");
  ASSERT_TRUE(r->table.has_value());
  const auto& d = only(*r, Severity::Warning, 1, 1, 10, Code::ToolWithoutPocket);
  EXPECT_NE(d.message.find("tool 4 has no P word"), std::string::npos) << d.message;
  EXPECT_EQ(r->table->find(4)->pocket, 0);
}

TEST(ToolTable, NothingUsableIsNullopt) {
  const auto r = read("; a program, not a tool table\nG0 X1\nM2\n");
  EXPECT_FALSE(r->table.has_value());
  EXPECT_EQ(r->diags.error_count(), 2);
}

TEST(ToolTable, DiagnosticRendersWithFileLineAndColumn) {
  core::SourceManager sources;
  const std::uint32_t id =
      sources.add(core::SourceFile::from_string("tools.tbl", "T1 P1\nT2 P2 Z1.2.3 ;bad\n"));
  core::DiagnosticList diags;
  const auto table = read_tool_table(*sources.get(id), id, kInch, diags);
  ASSERT_TRUE(table.has_value());
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(core::render(diags.all()[0], sources),
            "tools.tbl:2:8: error: Z value '1.2.3' is not a number; write e.g. Z0.25 "
            "[E_BAD_TOOL_TABLE]\n"
            "  T2 P2 Z1.2.3 ;bad\n"
            "         ^~~~~\n");
}

TEST(ToolTable, LongGarbageIsQuotedShort) {
  const auto r = read("T1 P1\nT2 P2 Z" + std::string(200, '9') + "x\n");
  ASSERT_EQ(r->diags.all().size(), 1u);
  EXPECT_LT(r->diags.all()[0].message.size(), 100u);
}

TEST(ToolTable, BadMmPerUnitIsAProgrammerError) {
  const auto file = core::SourceFile::from_string("t.tbl", "T1 P1\n");
  core::DiagnosticList diags;
  EXPECT_THROW(read_tool_table(*file, 0, 0.0, diags), std::invalid_argument);
  EXPECT_THROW(read_tool_table(*file, 0, -25.4, diags), std::invalid_argument);
  EXPECT_THROW(read_tool_table(*file, 0, std::nan(""), diags), std::invalid_argument);
}

TEST(ToolTable, SetReplacesAndKeepsNumbersSorted) {
  ToolTable table;
  table.set({.number = 5, .pocket = 1});
  table.set({.number = 2, .pocket = 2});
  table.set({.number = 9, .pocket = 3});
  table.set({.number = 5, .pocket = 4, .comment = "new"});
  ASSERT_EQ(table.size(), 3u);
  EXPECT_EQ(table.entries()[0].number, 2);
  EXPECT_EQ(table.entries()[1].number, 5);
  EXPECT_EQ(table.entries()[2].number, 9);
  EXPECT_EQ(table.find(5)->pocket, 4);
  EXPECT_EQ(table.find(5)->comment, "new");
  EXPECT_EQ(table.find(3), nullptr);
  EXPECT_EQ(table.find(10), nullptr);
  EXPECT_EQ(ToolTable{}.find(1), nullptr);
}

}  // namespace
}  // namespace usina::gcode
