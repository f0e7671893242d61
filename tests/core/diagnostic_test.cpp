#include "core/diagnostic.hpp"

#include <memory>
#include <set>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "core/source.hpp"

namespace usina::core {
namespace {

// --- code names -------------------------------------------------------------

TEST(CodeName, NamesAreTheStableStrings) {
  EXPECT_EQ(code_name(Code::FileNotFound), "E_FILE_NOT_FOUND");
  EXPECT_EQ(code_name(Code::NoProgramEnd), "W_NO_PROGRAM_END");
  EXPECT_EQ(code_name(Code::ByteOrderMark), "W_BYTE_ORDER_MARK");
  EXPECT_EQ(code_name(Code::UnclosedComment), "E_UNCLOSED_COMMENT");
  EXPECT_EQ(code_name(Code::MisplacedOWord), "E_MISPLACED_O_WORD");
  EXPECT_EQ(code_name(Code::DivisionByZero), "E_DIVISION_BY_ZERO");
  EXPECT_EQ(code_name(Code::UnclosedBlock), "E_UNCLOSED_CONTROL_BLOCK");
  EXPECT_EQ(code_name(Code::ModalGroupConflict), "E_MODAL_GROUP_CONFLICT");
  EXPECT_EQ(code_name(Code::ArcRadiusMismatch), "E_ARC_RADIUS_MISMATCH");
  EXPECT_EQ(code_name(Code::ArcRadiusTooSmall), "E_ARC_RADIUS_TOO_SMALL");
  EXPECT_EQ(code_name(Code::UnknownTool), "E_UNKNOWN_TOOL");
  EXPECT_EQ(code_name(Code::Message), "N_MESSAGE");
  EXPECT_EQ(code_name(Code::Unsupported), "E_UNSUPPORTED");
}

TEST(CodeName, EnumeratorsKeepTheirOrderSoAppendedCodesDoNotRenumber) {
  // diagnostic_codes.hpp says "append only": the first codes keep their values.
  EXPECT_EQ(static_cast<int>(Code::FileNotFound), 0);
  EXPECT_EQ(static_cast<int>(Code::FileTooLarge), 1);
  EXPECT_EQ(static_cast<int>(Code::UnexpectedCharacter), 5);
}

TEST(CodeName, EveryCodeHasAUniquePrefixedName) {
  std::set<std::string_view> seen;
  int count = 0;
#define USINA_X(name, id)                                                                \
  {                                                                                      \
    const std::string_view n = code_name(Code::name);                                    \
    EXPECT_EQ(n, #id);                                                                   \
    EXPECT_TRUE(n.starts_with("E_") || n.starts_with("W_") || n.starts_with("N_")) << n; \
    EXPECT_TRUE(seen.insert(n).second) << "duplicate " << n;                             \
    ++count;                                                                             \
  }
  USINA_DIAGNOSTIC_CODES(USINA_X)
#undef USINA_X
  EXPECT_GT(count, 40);
}

TEST(SeverityName, LowerCaseWordsAsACompilerPrintsThem) {
  EXPECT_EQ(severity_name(Severity::Note), "note");
  EXPECT_EQ(severity_name(Severity::Warning), "warning");
  EXPECT_EQ(severity_name(Severity::Error), "error");
}

// --- DiagnosticList ---------------------------------------------------------

TEST(DiagnosticList, CountsOnlyErrors) {
  DiagnosticList list;
  EXPECT_FALSE(list.has_errors());
  list.report({Code::Message, Severity::Note, {}, "hello"});
  list.report({Code::NoProgramEnd, Severity::Warning, {}, "no end"});
  EXPECT_EQ(list.error_count(), 0);
  EXPECT_FALSE(list.has_errors());
  list.report({Code::BadNumber, Severity::Error, {}, "bad"});
  EXPECT_EQ(list.error_count(), 1);
  EXPECT_TRUE(list.has_errors());
  ASSERT_EQ(list.all().size(), 3u);
  EXPECT_EQ(list.all()[2].message, "bad");
}

TEST(DiagnosticList, ClearForgetsDiagnosticsAndErrors) {
  DiagnosticList list;
  list.report({Code::BadNumber, Severity::Error, {}, "bad"});
  list.clear();
  EXPECT_TRUE(list.all().empty());
  EXPECT_EQ(list.error_count(), 0);
  EXPECT_FALSE(list.has_errors());
}

// --- render -----------------------------------------------------------------

struct Rendered {
  SourceManager sources;
  std::uint32_t id = 0;
};

std::unique_ptr<Rendered> with_file(std::string name, std::string text) {
  auto r = std::make_unique<Rendered>();
  r->id = r->sources.add(SourceFile::from_string(std::move(name), std::move(text)));
  return r;
}

TEST(Render, FileLineColSeverityMessageCodeThenLineAndCaret) {
  auto r = with_file("part.ngc", "G0 X1\nG2 X5 R1\n");
  const Diagnostic d{Code::ArcRadiusTooSmall,
                     Severity::Error,
                     {r->id, 2, 7, 1, 6},
                     "arc radius 1 is smaller than half the chord 2.5"};
  EXPECT_EQ(render(d, r->sources),
            "part.ngc:2:7: error: arc radius 1 is smaller than half the chord 2.5 "
            "[E_ARC_RADIUS_TOO_SMALL]\n"
            "  G2 X5 R1\n"
            "        ^\n");
}

TEST(Render, CaretInColumnOneHasNoPadding) {
  auto r = with_file("p.ngc", "G1 X1\n");
  const Diagnostic d{Code::NoFeedRate, Severity::Error, {r->id, 1, 1, 0, 0}, "no feed"};
  EXPECT_EQ(render(d, r->sources), "p.ngc:1:1: error: no feed [E_NO_FEED_RATE]\n  G1 X1\n  ^\n");
}

TEST(Render, LengthDrawsTildesAfterTheCaret) {
  auto r = with_file("p.ngc", "G1 X[1+]\n");
  const Diagnostic d{Code::ExpectedExpression, Severity::Error, {r->id, 1, 4, 3, 0}, "m"};
  EXPECT_EQ(render(d, r->sources),
            "p.ngc:1:4: error: m [E_EXPECTED_EXPRESSION]\n  G1 X[1+]\n     ^~~\n");
}

TEST(Render, TabsBeforeTheColumnAreKeptSoTheCaretLinesUp) {
  auto r = with_file("t.ngc", "\tG1\tX1\n");
  const Diagnostic d{Code::NoFeedRate, Severity::Error, {r->id, 1, 5, 1, 0}, "m"};
  EXPECT_EQ(render(d, r->sources), "t.ngc:1:5: error: m [E_NO_FEED_RATE]\n  \tG1\tX1\n  \t  \t^\n");
}

TEST(Render, WarningAndNoteUseTheirSeverityWord) {
  auto r = with_file("w.ngc", "G0 X1\n");
  const Diagnostic w{Code::NoProgramEnd, Severity::Warning, {r->id, 1, 1, 0, 0}, "no end"};
  EXPECT_EQ(render(w, r->sources).substr(0, 23), "w.ngc:1:1: warning: no ");
  const Diagnostic n{Code::Message, Severity::Note, {r->id, 1, 1, 0, 0}, "hi"};
  EXPECT_EQ(render(n, r->sources).substr(0, 27), "w.ngc:1:1: note: hi [N_MESS");
}

TEST(Render, NoColumnShowsTheLineWithoutCaret) {
  auto r = with_file("p.ngc", "G0 X1\nG0 X2\n");
  const Diagnostic d{Code::NoProgramEnd, Severity::Warning, {r->id, 2, 0, 0, 6}, "no end"};
  EXPECT_EQ(render(d, r->sources), "p.ngc:2: warning: no end [W_NO_PROGRAM_END]\n  G0 X2\n");
}

TEST(Render, NoLineShowsOnlyTheHeadline) {
  auto r = with_file("p.ngc", "G0 X1\n");
  const Diagnostic d{Code::FileTooLarge, Severity::Error, {r->id, 0, 0, 0, 0}, "too big"};
  EXPECT_EQ(render(d, r->sources), "p.ngc: error: too big [E_FILE_TOO_LARGE]\n");
}

TEST(Render, UnknownFileIsCalledInput) {
  SourceManager none;
  const Diagnostic d{Code::BadNumber, Severity::Error, {7, 3, 2, 1, 0}, "bad"};
  EXPECT_EQ(render(d, none), "<input>:3:2: error: bad [E_BAD_NUMBER]\n");
}

TEST(Render, CarriageReturnOfTheLineIsNotShown) {
  auto r = with_file("dos.ngc", "G0 X1\r\nG1 X2\r\n");
  const Diagnostic d{Code::NoFeedRate, Severity::Error, {r->id, 2, 1, 1, 7}, "no feed"};
  EXPECT_EQ(render(d, r->sources), "dos.ngc:2:1: error: no feed [E_NO_FEED_RATE]\n  G1 X2\n  ^\n");
}

TEST(Render, CaretPastTheEndOfLineStopsJustAfterIt) {
  auto r = with_file("p.ngc", "G1 X[\n");
  const Diagnostic d{Code::UnclosedBracket, Severity::Error, {r->id, 1, 40, 1, 0}, "m"};
  EXPECT_EQ(render(d, r->sources),
            "p.ngc:1:40: error: m [E_UNCLOSED_BRACKET]\n  G1 X[\n       ^\n");
}

TEST(Render, SecondFileOfTheManagerIsNamed) {
  SourceManager sources;
  sources.add(SourceFile::from_string("main.ngc", "o<s> call\n"));
  const std::uint32_t sub = sources.add(SourceFile::from_string("s.ngc", "G2 X1\n"));
  const Diagnostic d{Code::NoFeedRate, Severity::Error, {sub, 1, 1, 1, 0}, "m"};
  EXPECT_EQ(render(d, sources).substr(0, 12), "s.ngc:1:1: e");
}

}  // namespace
}  // namespace usina::core
