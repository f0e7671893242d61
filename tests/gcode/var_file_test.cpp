#include "gcode/var_file.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/diagnostic.hpp"
#include "core/source.hpp"

namespace usina::gcode {
namespace {

using core::Code;
using core::Severity;
using Entries = std::vector<VarFileEntry>;

constexpr std::uint32_t kFileId = 2;

struct Read {
  std::unique_ptr<core::SourceFile> file;
  core::DiagnosticList diags;
  std::optional<Entries> entries;
};

std::unique_ptr<Read> read(std::string text) {
  auto r = std::make_unique<Read>();
  r->file = core::SourceFile::from_string("params.var", std::move(text));
  r->entries = read_var_file(*r->file, kFileId, r->diags);
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
                             Code code = Code::BadVarFile) {
  static const core::Diagnostic kNone{};
  EXPECT_EQ(r.diags.all().size(), 1u);
  const core::Diagnostic& d = r.diags.all().empty() ? kNone : r.diags.all().front();
  const core::Diagnostic want{code, severity, {kFileId, line, col, length, 0}, ""};
  EXPECT_EQ(where(d), where(want)) << d.message;
  return d;
}

// "5161 1" then a bad line: its error, and 5161 still read.
const core::Diagnostic& bad_second_line(const Read& r, std::uint32_t col, std::uint32_t length) {
  EXPECT_EQ(r.entries, (Entries{{5161, 1.0}}));
  return only(r, Severity::Error, 2, col, length);
}

TEST(VarFile, ReadsWhatLinuxCncWrites) {
  const auto r = read("5161\t0.000000\n5162\t-1.250000\n5220\t1.000000\n5221\t12.500000\n");
  EXPECT_TRUE(r->diags.all().empty());
  EXPECT_EQ(r->entries, (Entries{{5161, 0.0}, {5162, -1.25}, {5220, 1.0}, {5221, 12.5}}));
}

TEST(VarFile, SpacesNoDecimalPointCrLfAndNoFinalNewline) {
  // LinuxCNC docs, "Numbered Parameters Persistence": "a decimal point is not
  // required in the file".
  const auto r = read("  31   7\r\n5220 +2\r\n5221 1e1");
  EXPECT_TRUE(r->diags.all().empty());
  EXPECT_EQ(r->entries, (Entries{{31, 7.0}, {5220, 2.0}, {5221, 10.0}}));
}

TEST(VarFile, EmptyFileIsValid) {
  const auto r = read("");
  ASSERT_TRUE(r->entries.has_value());
  EXPECT_TRUE(r->entries->empty());
  EXPECT_TRUE(r->diags.all().empty());
  const auto b = read("\n  \n\t\n");
  ASSERT_TRUE(b->entries.has_value());
  EXPECT_TRUE(b->diags.all().empty());
}

TEST(VarFile, BoundsOfTheParameterRange) {
  const auto r = read("1 1\n5601 2\n");
  EXPECT_TRUE(r->diags.all().empty());
  EXPECT_EQ(r->entries, (Entries{{1, 1.0}, {5601, 2.0}}));
}

TEST(VarFile, ByteOrderMarkIsSkipped) {
  const auto r = read(
      "\xEF\xBB\xBF"
      "5161 1\n");
  EXPECT_TRUE(r->diags.all().empty());
  EXPECT_EQ(r->entries, (Entries{{5161, 1.0}}));
}

TEST(VarFile, NotAParameterLineIsAWarning) {
  const auto r = read("5161 1\n  # G54 offsets\n");
  EXPECT_EQ(r->entries, (Entries{{5161, 1.0}}));
  const auto& d = only(*r, Severity::Warning, 2, 3, 1, Code::VarFileLineSkipped);
  EXPECT_NE(d.message.find("not 'NUMBER VALUE'"), std::string::npos) << d.message;
}

TEST(VarFile, ParameterNumberZeroIsOutOfRange) {
  const auto r = read("5161 1\n0 1\n");
  const auto& d = bad_second_line(*r, 1, 1);
  EXPECT_NE(d.message.find("parameter number 0 is out of range; it must be 1..5601"),
            std::string::npos)
      << d.message;
}

TEST(VarFile, ParameterNumberAboveRange) {
  const auto r = read("5161 1\n5602 1\n");
  bad_second_line(*r, 1, 4);
}

TEST(VarFile, NegativeParameterNumber) {
  const auto r = read("5161 1\n -7 1\n");
  bad_second_line(*r, 2, 2);
}

TEST(VarFile, FractionalParameterNumber) {
  // sscanf("%d %lf") would read "5221.5" as 5221 and .5; say it instead.
  const auto r = read("5161 1\n5221.5 1\n");
  const auto& d = bad_second_line(*r, 1, 6);
  EXPECT_NE(d.message.find("'5221.5' is not an integer"), std::string::npos) << d.message;
}

TEST(VarFile, ParameterNumberTooLargeForAnInt) {
  const auto r = read("5161 1\n99999999999 1\n");
  bad_second_line(*r, 1, 11);
}

TEST(VarFile, MissingValue) {
  const auto r = read("5161 1\n5221\n");
  const auto& d = bad_second_line(*r, 1, 4);
  EXPECT_NE(d.message.find("parameter 5221 has no value"), std::string::npos) << d.message;
}

TEST(VarFile, MalformedValue) {
  const auto r = read("5161 1\n5221 1,5\n");
  const auto& d = bad_second_line(*r, 6, 3);
  EXPECT_NE(d.message.find("value '1,5' of parameter 5221"), std::string::npos) << d.message;
}

TEST(VarFile, NanAndInfinityAreRejected) {
  bad_second_line(*read("5161 1\n5221 nan\n"), 6, 3);
  bad_second_line(*read("5161 1\n5221 -inf\n"), 6, 4);
  bad_second_line(*read("5161 1\n5221 1e999\n"), 6, 5);
}

TEST(VarFile, OutOfOrderIsAnError) {
  const auto r = read("5161 1\n5221 2\n5220 3\n");
  EXPECT_EQ(r->entries, (Entries{{5161, 1.0}, {5221, 2.0}}));
  const auto& d = only(*r, Severity::Error, 3, 1, 4);
  EXPECT_NE(d.message.find("parameter 5220 comes after parameter 5221 (line 2)"), std::string::npos)
      << d.message;
}

TEST(VarFile, DuplicateNumberIsAnError) {
  const auto r = read("5161 1\n5162 2\n5161 3\n");
  EXPECT_EQ(r->entries, (Entries{{5161, 1.0}, {5162, 2.0}}));
  const auto& d = only(*r, Severity::Error, 3, 1, 4);
  EXPECT_NE(d.message.find("parameter 5161 is also on line 1"), std::string::npos) << d.message;
  const auto n = read("5161 1\n5161 3\n");
  only(*n, Severity::Error, 2, 1, 4);
}

TEST(VarFile, TextAfterValueWarnsAndValueIsKept) {
  const auto r = read("5221 1.5 ; G54 X  \n");
  EXPECT_EQ(r->entries, (Entries{{5221, 1.5}}));
  const auto& d = only(*r, Severity::Warning, 1, 10, 9, Code::VarFileExtraText);
  EXPECT_NE(d.message.find("after the value of parameter 5221"), std::string::npos) << d.message;
}

TEST(VarFile, NothingUsableIsNullopt) {
  const auto r = read("G0 X1\n0 0\n");
  EXPECT_FALSE(r->entries.has_value());
  EXPECT_EQ(r->diags.all().size(), 2u);
}

TEST(VarFile, DiagnosticRendersWithFileLineAndColumn) {
  core::SourceManager sources;
  const std::uint32_t id = sources.add(core::SourceFile::from_string("p.var", "5161 1\n5221 x\n"));
  core::DiagnosticList diags;
  ASSERT_TRUE(read_var_file(*sources.get(id), id, diags).has_value());
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(core::render(diags.all()[0], sources),
            "p.var:2:6: error: value 'x' of parameter 5221 is not a finite number "
            "[E_BAD_VAR_FILE]\n"
            "  5221 x\n"
            "       ^\n");
}

TEST(VarFile, WriteUsesLinuxCncFormat) {
  const Entries e{{5221, 12.5}, {5161, 0.0}, {31, -0.0000004}, {5220, 1.0}};
  EXPECT_EQ(write_var_file(e),
            "31\t-0.000000\n"
            "5161\t0.000000\n"
            "5220\t1.000000\n"
            "5221\t12.500000\n");
}

TEST(VarFile, WriteEmptyIsEmpty) {
  EXPECT_EQ(write_var_file({}), "");
}

TEST(VarFile, WriteLaterDuplicateWins) {
  const Entries e{{5221, 1.0}, {5161, 2.0}, {5221, 3.0}};
  EXPECT_EQ(write_var_file(e), "5161\t2.000000\n5221\t3.000000\n");
}

TEST(VarFile, WriteThenReadRoundTrips) {
  const Entries e{{1, 0.5}, {5161, -1.234567}, {5220, 1.0}, {5601, 1e6}};
  const auto r = read(write_var_file(e));
  EXPECT_TRUE(r->diags.all().empty());
  EXPECT_EQ(r->entries, e);
}

TEST(VarFile, WriteRejectsProgrammerErrors) {
  EXPECT_THROW(write_var_file(Entries{{0, 1.0}}), std::invalid_argument);
  EXPECT_THROW(write_var_file(Entries{{5602, 1.0}}), std::invalid_argument);
  EXPECT_THROW(write_var_file(Entries{{5221, std::nan("")}}), std::invalid_argument);
  EXPECT_THROW(write_var_file(Entries{{5221, std::numeric_limits<double>::infinity()}}),
               std::invalid_argument);
}

}  // namespace
}  // namespace usina::gcode
