#include "gcode/parser.hpp"

#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "core/source.hpp"
#include "gcode/block.hpp"
#include "gcode/expr.hpp"
#include "gcode/program_index.hpp"
#include "gcode/program_text.hpp"
#include "support/random_block.hpp"

namespace usina::gcode {
namespace {

using core::Code;

// A parsed line; the block's views point into `text`, so this is not moved.
struct Parsed {
  std::string text;
  Block block;
  core::DiagnosticList diags;
  bool ok = false;
};

std::unique_ptr<Parsed> parse(std::string text, LinePos where = {0, 1, 0}) {
  auto p = std::make_unique<Parsed>();
  p->text = std::move(text);
  p->ok = parse_block(p->text, where, p->block, p->diags);
  return p;
}

class NoParams final : public ParameterSource {
 public:
  double numbered(int index) const override { return index == 7 ? 70.0 : 0.0; }

  std::optional<double> named(std::string_view name) const override {
    if (name == "x") return 5.0;
    return std::nullopt;
  }
};

// The value of `ref` in `block`, NaN on an evaluation error.
double value(const Block& b, ExprRef ref) {
  NoParams params;
  EvalError err;
  const auto v = evaluate(b, ref, params, err);
  return v ? *v : std::nan("");
}

// A word's value: its plain number or its expression's.
double value(const Block& b, const Word& word) {
  NoParams params;
  EvalError err;
  const auto v = evaluate_word(b, word, params, err);
  return v ? *v : std::nan("");
}

// The value of the only word of `text`'s block.
double word_value(const std::string& text) {
  auto p = parse(text);
  EXPECT_TRUE(p->ok) << text;
  EXPECT_EQ(p->block.words.size(), 1u) << text;
  if (!p->ok || p->block.words.size() != 1) return std::nan("");
  return value(p->block, p->block.words[0]);
}

// The one syntax error of `text`: its code and column.
struct SyntaxErr {
  Code code;
  std::uint32_t col;
};

SyntaxErr syntax_error(const std::string& text) {
  auto p = parse(text);
  EXPECT_FALSE(p->ok) << text;
  EXPECT_EQ(p->diags.all().size(), 1u) << text;
  if (p->diags.all().empty()) return {Code::Unsupported, 0};
  const core::Diagnostic& d = p->diags.all()[0];
  EXPECT_EQ(d.severity, core::Severity::Error);
  EXPECT_EQ(d.loc.length, 1u);
  return {d.code, d.loc.col};
}

#define EXPECT_SYNTAX_ERROR(text, code_, col_)                            \
  do {                                                                    \
    const SyntaxErr e = syntax_error(text);                               \
    EXPECT_EQ(core::code_name(e.code), core::code_name(code_)) << (text); \
    EXPECT_EQ(e.col, col_##u) << (text);                                  \
  } while (0)

// --- words ------------------------------------------------------------------

TEST(Parser, WordsHaveUpperCaseLettersValuesAndColumns) {
  auto p = parse("g1 x2.5 Y-3");
  ASSERT_TRUE(p->ok);
  const auto& w = p->block.words;
  ASSERT_EQ(w.size(), 3u);
  EXPECT_EQ(w[0].letter, 'G');
  EXPECT_EQ(w[0].col, 1u);
  EXPECT_EQ(value(p->block, w[0]), 1.0);
  EXPECT_EQ(w[1].letter, 'X');
  EXPECT_EQ(w[1].col, 4u);
  EXPECT_EQ(value(p->block, w[1]), 2.5);
  EXPECT_EQ(w[2].letter, 'Y');
  EXPECT_EQ(w[2].col, 9u);
  EXPECT_EQ(value(p->block, w[2]), -3.0);
}

// A number's value is kept whole and its exponent, which no dialect has,
// asked about only when an E follows the digits.
TEST(Parser, NumberEdges) {
  EXPECT_EQ(word_value("X1."), 1.0);
  EXPECT_EQ(word_value("X.5"), 0.5);
  EXPECT_EQ(word_value("X-.5"), -0.5);
  EXPECT_TRUE(std::signbit(word_value("X-0")));
  EXPECT_FALSE(std::signbit(word_value("X+0")));
  EXPECT_EQ(word_value("X-12345678.90123456"), -12345678.90123456);
  auto p = parse("X1e5");  // X1 and an E word, as the control reads it
  ASSERT_TRUE(p->ok);
  ASSERT_EQ(p->block.words.size(), 2u);
  EXPECT_EQ(value(p->block, p->block.words[0]), 1.0);
  EXPECT_EQ(p->block.words[1].letter, 'E');
  EXPECT_EQ(value(p->block, p->block.words[1]), 5.0);
  EXPECT_SYNTAX_ERROR("X1e400", Code::NumberOutOfRange, 2);
  EXPECT_SYNTAX_ERROR("X-1E-400", Code::NumberOutOfRange, 3);
  EXPECT_SYNTAX_ERROR("G1 X1 E1e999", Code::NumberOutOfRange, 8);
}

TEST(Parser, AValueBeyondTheNodeLimitIsAnError) {
  // Every value is a node; a block has at most kMaxBlockLength of them.
  std::string line = "X[0";
  for (std::size_t i = 0; i < kMaxBlockLength; ++i)
    line += "+1";
  line += "]";
  auto p = parse(line);
  EXPECT_FALSE(p->ok);
  ASSERT_EQ(p->diags.all().size(), 1u);
  EXPECT_EQ(p->diags.all()[0].code, Code::BlockTooLong);
}

TEST(Parser, BlanksAnywhereOutsideComments) {
  auto p = parse("G 0 1 X 1 . 5");
  ASSERT_TRUE(p->ok);
  ASSERT_EQ(p->block.words.size(), 2u);
  EXPECT_EQ(p->block.words[0].letter, 'G');
  EXPECT_EQ(value(p->block, p->block.words[0]), 1.0);
  EXPECT_EQ(p->block.words[1].letter, 'X');
  EXPECT_EQ(p->block.words[1].col, 7u);
  EXPECT_EQ(value(p->block, p->block.words[1]), 1.5);
}

TEST(Parser, WordsWithoutBlanksBetween) {
  auto p = parse("G1X10Y20F300");
  ASSERT_TRUE(p->ok);
  ASSERT_EQ(p->block.words.size(), 4u);
  EXPECT_EQ(p->block.words[3].letter, 'F');
  EXPECT_EQ(value(p->block, p->block.words[3]), 300.0);
}

TEST(Parser, PlusSignIsAccepted) {
  EXPECT_EQ(word_value("X+2"), 2.0);
}

TEST(Parser, PolarWordsAreWords) {
  auto p = parse("G1 @10 ^90");
  ASSERT_TRUE(p->ok);
  ASSERT_EQ(p->block.words.size(), 3u);
  EXPECT_EQ(p->block.words[1].letter, '@');
  EXPECT_EQ(p->block.words[2].letter, '^');
}

TEST(Parser, BlockLocationIsTheFirstNonBlankCharacter) {
  auto p = parse("  \tG0 X1", {4, 12, 345});
  ASSERT_TRUE(p->ok);
  EXPECT_EQ(p->block.loc.file, 4u);
  EXPECT_EQ(p->block.loc.line, 12u);
  EXPECT_EQ(p->block.loc.col, 4u);
  EXPECT_EQ(p->block.loc.line_offset, 345u);
}

TEST(Parser, EmptyAndBlankLinesAreEmptyBlocks) {
  EXPECT_TRUE(parse("")->block.empty());
  EXPECT_TRUE(parse("   \t ")->block.empty());
  EXPECT_TRUE(parse("")->ok);
}

TEST(Parser, BlockIsClearedBeforeParsing) {
  auto p = parse("G1 X1 (c)");
  ASSERT_TRUE(p->ok);
  const std::string second = "M2";
  ASSERT_TRUE(parse_block(second, {0, 2, 0}, p->block, p->diags));
  ASSERT_EQ(p->block.words.size(), 1u);
  EXPECT_EQ(p->block.words[0].letter, 'M');
  EXPECT_TRUE(p->block.comments.empty());
}

// --- comments ---------------------------------------------------------------

TEST(Parser, ParenthesisCommentKeepsItsTextAndColumn) {
  auto p = parse("G1 ( Rough Pass ) X2");
  ASSERT_TRUE(p->ok);
  ASSERT_EQ(p->block.comments.size(), 1u);
  EXPECT_EQ(p->block.comments[0].text, " Rough Pass ");
  EXPECT_EQ(p->block.comments[0].col, 4u);
  ASSERT_EQ(p->block.words.size(), 2u);
  EXPECT_EQ(p->block.words[1].letter, 'X');
}

TEST(Parser, SemicolonCommentRunsToTheEndOfLine) {
  auto p = parse("G0 X1 ; go (home) X9");
  ASSERT_TRUE(p->ok);
  ASSERT_EQ(p->block.words.size(), 2u);
  ASSERT_EQ(p->block.comments.size(), 1u);
  EXPECT_EQ(p->block.comments[0].text, " go (home) X9");
  EXPECT_EQ(p->block.comments[0].col, 7u);
}

TEST(Parser, MessageCommentIsAnOrdinaryCommentToTheParser) {
  auto p = parse("(MSG, Change to tool 2)");
  ASSERT_TRUE(p->ok);
  ASSERT_EQ(p->block.comments.size(), 1u);
  EXPECT_EQ(p->block.comments[0].text, "MSG, Change to tool 2");
  EXPECT_FALSE(p->block.empty());
}

TEST(Parser, SeveralCommentsInOneBlock) {
  auto p = parse("(a)G0(b)X1(c)");
  ASSERT_TRUE(p->ok);
  ASSERT_EQ(p->block.comments.size(), 3u);
  EXPECT_EQ(p->block.comments[2].text, "c");
  EXPECT_EQ(p->block.comments[2].col, 11u);
}

TEST(Parser, CommentTextIsNotLowerCasedOrSqueezed) {
  auto p = parse("(Tool  T1: 6mm)");
  ASSERT_TRUE(p->ok);
  EXPECT_EQ(p->block.comments[0].text, "Tool  T1: 6mm");
}

// --- block delete, %, N -----------------------------------------------------

TEST(Parser, SlashMarksBlockDelete) {
  auto p = parse("/G0 X1");
  ASSERT_TRUE(p->ok);
  EXPECT_TRUE(p->block.deleted);
  EXPECT_EQ(p->block.words.size(), 2u);
  EXPECT_FALSE(parse("G0 X1")->block.deleted);
}

TEST(Parser, SlashThenLineNumber) {
  auto p = parse(" / N20 G0");
  ASSERT_TRUE(p->ok);
  EXPECT_TRUE(p->block.deleted);
  ASSERT_TRUE(p->block.line_number.has_value());
  EXPECT_EQ(*p->block.line_number, 20.0);
}

TEST(Parser, PercentLine) {
  auto p = parse("%");
  ASSERT_TRUE(p->ok);
  EXPECT_TRUE(p->block.percent);
  EXPECT_FALSE(parse("G0")->block.percent);
}

TEST(Parser, LineNumberIsKeptApartFromTheWords) {
  auto p = parse("n 1 0 G1 X1");
  ASSERT_TRUE(p->ok);
  ASSERT_TRUE(p->block.line_number.has_value());
  EXPECT_EQ(*p->block.line_number, 10.0);
  ASSERT_EQ(p->block.words.size(), 2u);
  EXPECT_EQ(p->block.words[0].letter, 'G');
}

TEST(Parser, LineNumberWithDecimals) {
  auto p = parse("N10.5");
  ASSERT_TRUE(p->ok);
  EXPECT_EQ(*p->block.line_number, 10.5);
  EXPECT_TRUE(p->block.words.empty());
}

TEST(Parser, LineNumberNotFirstIsAnError) {
  EXPECT_SYNTAX_ERROR("G1 N10 X1", Code::UnknownWord, 4);
}

TEST(Parser, LineNumberWithoutDigitsIsABadNumber) {
  EXPECT_SYNTAX_ERROR("NX1", Code::BadNumber, 1);
}

// --- O-words ----------------------------------------------------------------

struct OCase {
  const char* text;
  OKind kind;
  const char* label;
};

TEST(Parser, EveryOWordKeyword) {
  const OCase cases[] = {
      {"o100 sub", OKind::Sub, "100"},
      {"O100 ENDSUB", OKind::EndSub, "100"},
      {"o<p> call", OKind::Call, "p"},
      {"o100 return", OKind::Return, "100"},
      {"o1 if [1]", OKind::If, "1"},
      {"o1 elseif [1]", OKind::ElseIf, "1"},
      {"o1 else", OKind::Else, "1"},
      {"o1 endif", OKind::EndIf, "1"},
      {"o2 while [1]", OKind::While, "2"},
      {"o2 endwhile", OKind::EndWhile, "2"},
      {"o3 do", OKind::Do, "3"},
      {"o4 repeat [3]", OKind::Repeat, "4"},
      {"o4 endrepeat", OKind::EndRepeat, "4"},
      {"o2 break", OKind::Break, "2"},
      {"o2 continue", OKind::Continue, "2"},
  };
  for (const OCase& c : cases) {
    auto p = parse(c.text);
    ASSERT_TRUE(p->ok) << c.text;
    ASSERT_TRUE(p->block.o.has_value()) << c.text;
    EXPECT_EQ(p->block.o->kind, c.kind) << c.text;
    EXPECT_EQ(p->block.o->label, c.label) << c.text;
    EXPECT_EQ(p->block.o->col, 1u) << c.text;
  }
}

TEST(Parser, OWordKeywordsAreCaseInsensitiveWithBlanks) {
  auto p = parse("O 1 0 0 E N D W H I L E");
  ASSERT_TRUE(p->ok);
  EXPECT_EQ(p->block.o->kind, OKind::EndWhile);
  EXPECT_EQ(p->block.o->label, "100");
}

TEST(Parser, NamedOWordLabelIsLowerCaseWithoutBlanks) {
  auto p = parse("O< Face Mill > SUB");
  ASSERT_TRUE(p->ok);
  EXPECT_EQ(p->block.o->kind, OKind::Sub);
  EXPECT_EQ(p->block.o->label, "facemill");
}

TEST(Parser, OWordAfterLineNumber) {
  auto p = parse("N5 o7 do");
  ASSERT_TRUE(p->ok);
  EXPECT_EQ(p->block.o->kind, OKind::Do);
  EXPECT_EQ(p->block.o->col, 4u);
}

TEST(Parser, ConditionIsABracketedExpression) {
  auto p = parse("o1 if [#7 GT 50]");
  ASSERT_TRUE(p->ok);
  EXPECT_EQ(value(p->block, p->block.o->expr), 1.0);
}

TEST(Parser, RepeatCountIsAnExpression) {
  auto p = parse("o4 repeat [2*3]");
  ASSERT_TRUE(p->ok);
  EXPECT_EQ(value(p->block, p->block.o->expr), 6.0);
}

TEST(Parser, ReturnAndEndsubMayCarryAValue) {
  auto r = parse("o<f> return [2+2]");
  ASSERT_TRUE(r->ok);
  EXPECT_EQ(value(r->block, r->block.o->expr), 4.0);
  auto e = parse("o<f> endsub [7]");
  ASSERT_TRUE(e->ok);
  EXPECT_EQ(value(e->block, e->block.o->expr), 7.0);
  auto bare = parse("o<f> return");
  ASSERT_TRUE(bare->ok);
  EXPECT_EQ(bare->block.o->expr, kNoExpr);
}

TEST(Parser, CallArgumentsInOrder) {
  auto p = parse("o<pocket> call [1] [2+3] [#7]");
  ASSERT_TRUE(p->ok);
  ASSERT_EQ(p->block.o->args.size(), 3u);
  EXPECT_EQ(value(p->block, p->block.o->args[0]), 1.0);
  EXPECT_EQ(value(p->block, p->block.o->args[1]), 5.0);
  EXPECT_EQ(value(p->block, p->block.o->args[2]), 70.0);
}

TEST(Parser, CallByNumberedParameterOrExpression) {
  auto p = parse("o#7 call");
  ASSERT_TRUE(p->ok);
  EXPECT_EQ(p->block.o->kind, OKind::Call);
  ASSERT_NE(p->block.o->label_expr, kNoExpr);
  EXPECT_EQ(value(p->block, p->block.o->label_expr), 70.0);
  auto q = parse("o[100+1] call");
  ASSERT_TRUE(q->ok);
  EXPECT_EQ(value(q->block, q->block.o->label_expr), 101.0);
}

TEST(Parser, BareONumberIsAFanucSubprogram) {
  for (const char* text : {"O1000", "o1000 (drill pattern)", "O1000 ; note"}) {
    auto p = parse(text);
    ASSERT_TRUE(p->ok) << text;
    ASSERT_TRUE(p->block.o.has_value()) << text;
    EXPECT_EQ(p->block.o->kind, OKind::Program) << text;
    EXPECT_EQ(p->block.o->label, "1000") << text;
  }
}

TEST(Parser, CommentAfterAnOWordIsKept) {
  auto p = parse("o100 sub (face the stock)");
  ASSERT_TRUE(p->ok);
  ASSERT_EQ(p->block.comments.size(), 1u);
  EXPECT_EQ(p->block.comments[0].text, "face the stock");
}

TEST(Parser, OWordWithoutNumberOrName) {
  EXPECT_SYNTAX_ERROR("o sub", Code::BadOWord, 1);
}

TEST(Parser, OWordWithEmptyName) {
  EXPECT_SYNTAX_ERROR("o<> sub", Code::BadOWord, 1);
}

TEST(Parser, OWordWithUnclosedName) {
  EXPECT_SYNTAX_ERROR("o<abc sub", Code::BadOWord, 1);
}

TEST(Parser, NamedOWordWithoutKeyword) {
  EXPECT_SYNTAX_ERROR("o<abc>", Code::BadOWord, 7);
}

TEST(Parser, OWordWithUnknownKeyword) {
  EXPECT_SYNTAX_ERROR("o100 loop", Code::BadOWord, 6);
}

TEST(Parser, OWordInTheMiddleOfALine) {
  EXPECT_SYNTAX_ERROR("G0 o100 call", Code::MisplacedOWord, 4);
}

TEST(Parser, OWordStatementWithOtherWords) {
  EXPECT_SYNTAX_ERROR("o100 sub G0 X1", Code::MisplacedOWord, 10);
}

TEST(Parser, IfWithoutCondition) {
  EXPECT_SYNTAX_ERROR("o1 if", Code::ExpectedExpression, 6);
}

TEST(Parser, WhileConditionMustBeBracketed) {
  EXPECT_SYNTAX_ERROR("o1 while 1", Code::ExpectedExpression, 10);
}

// --- parameters -------------------------------------------------------------

TEST(Parser, NumberedAssignment) {
  auto p = parse("#12 = 3.5");
  ASSERT_TRUE(p->ok);
  ASSERT_EQ(p->block.assigns.size(), 1u);
  const ParamAssign& a = p->block.assigns[0];
  EXPECT_EQ(value(p->block, a.index), 12.0);
  EXPECT_EQ(value(p->block, a.value), 3.5);
  EXPECT_TRUE(a.name.empty());
  EXPECT_EQ(a.col, 1u);
}

TEST(Parser, IndexMayBeAnExpression) {
  auto p = parse("#[10+2]=1");
  ASSERT_TRUE(p->ok);
  EXPECT_EQ(value(p->block, p->block.assigns[0].index), 12.0);
}

TEST(Parser, NamedAssignmentKeepsTheNameAsWritten) {
  auto p = parse("#< Depth Of Cut > = 0.5");
  ASSERT_TRUE(p->ok);
  ASSERT_EQ(p->block.assigns.size(), 1u);
  EXPECT_EQ(p->block.assigns[0].name, " Depth Of Cut ");
  EXPECT_EQ(p->block.assigns[0].index, kNoExpr);
}

TEST(Parser, SeveralAssignmentsAndWordsInOneBlock) {
  auto p = parse("#1=2 #2=#1 G0 X#2");
  ASSERT_TRUE(p->ok);
  EXPECT_EQ(p->block.assigns.size(), 2u);
  EXPECT_EQ(p->block.words.size(), 2u);
  EXPECT_EQ(p->block.assigns[1].col, 6u);
}

TEST(Parser, ParameterReadInAWord) {
  EXPECT_EQ(word_value("X#7"), 70.0);
}

TEST(Parser, NamedParameterReadInAWord) {
  EXPECT_EQ(word_value("X#<X>"), 5.0);
}

TEST(Parser, APlainNumberIsKeptInItsWordAndAnExpressionInTheArena) {
  auto p = parse("G1 X-1.5 Y+.25 Z-[2] F#1");
  ASSERT_TRUE(p->ok);
  const auto& w = p->block.words;
  ASSERT_EQ(w.size(), 5u);
  EXPECT_EQ(w[0].value, kPlainNumber);
  EXPECT_EQ(w[0].number, 1.0);
  EXPECT_EQ(w[1].value, kPlainNumber);
  EXPECT_EQ(w[1].number, -1.5);
  EXPECT_EQ(w[2].value, kPlainNumber);
  EXPECT_EQ(w[2].number, 0.25);
  EXPECT_EQ(p->block.expr(w[3].value).kind, ExprKind::Negate);  // "-[2]": the sign read again
  EXPECT_EQ(value(p->block, w[3]), -2.0);
  EXPECT_EQ(p->block.expr(w[4].value).kind, ExprKind::Param);
  EXPECT_EQ(w[4].col, 22u);
}

TEST(Parser, IndirectParameter) {
  // ##7: the parameter whose number is in #7 (here 70 → 0).
  auto p = parse("X##7");
  ASSERT_TRUE(p->ok);
  const ExprNode& outer = p->block.expr(p->block.words[0].value);
  EXPECT_EQ(outer.kind, ExprKind::Param);
  EXPECT_EQ(p->block.expr(outer.a).kind, ExprKind::Param);
}

TEST(Parser, AssignmentWithoutEquals) {
  EXPECT_SYNTAX_ERROR("#1 X5", Code::ExpectedExpression, 4);
}

TEST(Parser, AssignmentWithoutValue) {
  EXPECT_SYNTAX_ERROR("#1=", Code::ExpectedExpression, 4);
}

TEST(Parser, NameWithoutClosingAngle) {
  EXPECT_SYNTAX_ERROR("#<depth=1", Code::BadParameterName, 2);
}

TEST(Parser, EmptyName) {
  EXPECT_SYNTAX_ERROR("#< >=1", Code::BadParameterName, 2);
}

TEST(Parser, NameWithForbiddenCharacter) {
  EXPECT_SYNTAX_ERROR("#<a#b>=1", Code::BadParameterName, 2);
  EXPECT_SYNTAX_ERROR("G0 X#<a(b>", Code::BadParameterName, 6);
}

// --- expressions ------------------------------------------------------------

TEST(Parser, MultiplicationBindsTighterThanAddition) {
  EXPECT_EQ(word_value("X[1+2*3]"), 7.0);
}

TEST(Parser, PowerIsLeftAssociativeAsLinuxCnc) {
  // LinuxCNC interp_read.cc: operators of equal precedence group left to right.
  EXPECT_EQ(word_value("X[2**3**2]"), 64.0);
}

TEST(Parser, PowerBindsTighterThanMultiplication) {
  EXPECT_EQ(word_value("X[2*3**2]"), 18.0);
}

TEST(Parser, SubtractionAndDivisionAreLeftAssociative) {
  EXPECT_EQ(word_value("X[10-4-3]"), 3.0);
  EXPECT_EQ(word_value("X[12/3/2]"), 2.0);
}

TEST(Parser, ModHasMultiplicationPrecedence) {
  EXPECT_EQ(word_value("X[1+7 MOD 3]"), 2.0);
}

TEST(Parser, ComparisonBindsLooserThanArithmetic) {
  EXPECT_EQ(word_value("X[1+2 EQ 3]"), 1.0);
  EXPECT_EQ(word_value("X[2*2 GT 3]"), 1.0);
}

TEST(Parser, LogicalOperatorsShareOnePrecedenceLeftToRight) {
  // (1 OR 0) AND 0 = 0; were AND tighter it would be 1.
  EXPECT_EQ(word_value("X[1 OR 0 AND 0]"), 0.0);
}

TEST(Parser, LogicalBindsLooserThanComparison) {
  EXPECT_EQ(word_value("X[1 LT 2 AND 3 GT 2]"), 1.0);
}

TEST(Parser, OperatorsAreCaseInsensitive) {
  EXPECT_EQ(word_value("x[7 mod 4 + 1 eq 4]"), 1.0);
}

TEST(Parser, NestedBrackets) {
  EXPECT_EQ(word_value("X[[1+2]*[3+4]]"), 21.0);
}

TEST(Parser, NegativeLiteralInsideAPower) {
  // A leading minus with digits is part of the number: (-2)**2.
  EXPECT_EQ(word_value("X[-2**2]"), 4.0);
}

TEST(Parser, NegatedBracketAndParameter) {
  EXPECT_EQ(word_value("X-[1+2]"), -3.0);
  EXPECT_EQ(word_value("X-#7"), -70.0);
}

TEST(Parser, FunctionsAreCaseInsensitive) {
  EXPECT_NEAR(word_value("X sin[30]"), 0.5, 1e-12);
  EXPECT_EQ(word_value("X Sqrt[16]"), 4.0);
  EXPECT_EQ(word_value("X ABS[-2]"), 2.0);
}

TEST(Parser, EveryFunctionName) {
  for (const char* f :
       {"ABS", "ACOS", "ASIN", "COS", "EXP", "FIX", "FUP", "LN", "ROUND", "SIN", "SQRT", "TAN"}) {
    auto p = parse(std::string("X") + f + "[0.5]");
    ASSERT_TRUE(p->ok) << f;
    EXPECT_EQ(p->block.expr(p->block.words[0].value).kind, ExprKind::Func) << f;
  }
}

TEST(Parser, AtanTakesTwoBracketedArguments) {
  auto p = parse("X ATAN[1]/[-1]");
  ASSERT_TRUE(p->ok);
  EXPECT_EQ(p->block.expr(p->block.words[0].value).kind, ExprKind::Atan2);
  EXPECT_NEAR(value(p->block, p->block.words[0]), 135.0, 1e-12);
}

TEST(Parser, AtanWithOneArgumentIsAnError) {
  EXPECT_SYNTAX_ERROR("X ATAN[1]", Code::ExpectedExpression, 10);
}

TEST(Parser, ExistsOfANamedParameter) {
  auto p = parse("X EXISTS[#<x>]");
  ASSERT_TRUE(p->ok);
  const ExprNode& n = p->block.expr(p->block.words[0].value);
  EXPECT_EQ(n.kind, ExprKind::Exists);
  EXPECT_EQ(n.name, "x");
  EXPECT_EQ(value(p->block, p->block.words[0]), 1.0);
  EXPECT_EQ(word_value("X exists[#<nothing>]"), 0.0);
}

TEST(Parser, ExistsOfANumberedParameter) {
  auto p = parse("X EXISTS[#5]");
  ASSERT_TRUE(p->ok);
  EXPECT_EQ(p->block.expr(p->block.words[0].value).kind, ExprKind::Exists);
}

TEST(Parser, ExistsWithoutParameter) {
  EXPECT_SYNTAX_ERROR("X EXISTS[5]", Code::ExpectedExpression, 9);
}

TEST(Parser, ExistsWithoutClosingBracket) {
  EXPECT_SYNTAX_ERROR("X EXISTS[#<a>", Code::UnclosedBracket, 14);
}

TEST(Parser, NodeColumnsPointIntoTheLine) {
  auto p = parse("G0 X[1+SIN[#7]]");
  ASSERT_TRUE(p->ok);
  // The word's own column is the letter; the function's is its name.
  EXPECT_EQ(p->block.words[1].col, 4u);
  const ExprNode& sum = p->block.expr(p->block.words[1].value);
  ASSERT_EQ(sum.kind, ExprKind::Binary);
  const ExprNode& sin = p->block.expr(sum.b);
  EXPECT_EQ(sin.kind, ExprKind::Func);
  EXPECT_EQ(sin.col, 8u);
  EXPECT_EQ(p->block.expr(sin.a).col, 12u);
}

// --- syntax errors: code and column ----------------------------------------

TEST(Parser, UnclosedComment) {
  EXPECT_SYNTAX_ERROR("G1 (no end", Code::UnclosedComment, 4);
}

TEST(Parser, MissingCloseBracketAtEndOfBlock) {
  EXPECT_SYNTAX_ERROR("G1 X[1+2", Code::UnclosedBracket, 9);
}

TEST(Parser, SomethingElseWhereCloseBracketBelongs) {
  EXPECT_SYNTAX_ERROR("G1 X[1 #2]", Code::UnclosedBracket, 8);
}

TEST(Parser, PointWithoutDigitsIsABadNumber) {
  EXPECT_SYNTAX_ERROR("G1 X.", Code::BadNumber, 5);
}

TEST(Parser, UnknownFunction) {
  EXPECT_SYNTAX_ERROR("G1 X[FOO[1]]", Code::UnknownFunction, 6);
}

// Regression (a bug the tests found, fixed): a number longer than the lexer's 64-character buffer
// is refused by Lexer::number(), and the parser then reports "expected a value, found '0'"
// (E_EXPECTED_EXPRESSION), which points at a digit and says no value is
// there. Expected: E_BAD_NUMBER (or E_NUMBER_OUT_OF_RANGE) at the number's
// first column, saying the number is too long.
TEST(Parser, NumberTooLongIsABadNumber) {
  EXPECT_SYNTAX_ERROR("G0 X" + std::string(70, '0') + "1", Code::BadNumber, 5);
}

TEST(Parser, NumberTooLongIsASyntaxErrorAtItsColumn) {
  const SyntaxErr e = syntax_error("G0 X" + std::string(70, '0') + "1");
  EXPECT_EQ(e.col, 5u);
}

TEST(Parser, LetterWithoutValue) {
  EXPECT_SYNTAX_ERROR("G1 X", Code::ExpectedExpression, 5);
}

TEST(Parser, LetterFollowedByAnotherLetterIsAnUnknownFunction) {
  // "XY1": X's value would have to be a function named Y...
  EXPECT_SYNTAX_ERROR("G0 XY1", Code::UnknownFunction, 5);
}

TEST(Parser, OperatorWithoutRightOperand) {
  EXPECT_SYNTAX_ERROR("X[1+]", Code::ExpectedExpression, 5);
}

TEST(Parser, UnexpectedPunctuation) {
  EXPECT_SYNTAX_ERROR("G1 X1 !", Code::UnexpectedCharacter, 7);
}

TEST(Parser, NonAsciiByteIsNamedInHex) {
  auto p = parse("G1 \xC3\xA9");
  ASSERT_FALSE(p->ok);
  ASSERT_EQ(p->diags.all().size(), 1u);
  EXPECT_EQ(p->diags.all()[0].code, Code::UnexpectedCharacter);
  EXPECT_EQ(p->diags.all()[0].loc.col, 4u);
  EXPECT_NE(p->diags.all()[0].message.find("0xc3"), std::string::npos) << p->diags.all()[0].message;
}

TEST(Parser, ValueExpectedButPunctuationFound) {
  EXPECT_SYNTAX_ERROR("G1 X$", Code::ExpectedExpression, 5);
}

TEST(Parser, DeepNestingIsAnErrorNotAStackOverflow) {
  const std::string deep = "X" + std::string(200, '[') + "1" + std::string(200, ']');
  auto p = parse(deep);
  EXPECT_FALSE(p->ok);
  ASSERT_EQ(p->diags.all().size(), 1u);
  EXPECT_EQ(p->diags.all()[0].code, Code::ExpectedExpression);
}

TEST(Parser, DeepNegationIsAnErrorNotAStackOverflow) {
  const std::string deep = "X" + std::string(5000, '-') + "#1";
  auto p = parse(deep);
  EXPECT_FALSE(p->ok);
  EXPECT_EQ(p->diags.all().size(), 1u);
}

TEST(Parser, SixtyBracketsAreFine) {
  const std::string deep = "X" + std::string(60, '[') + "1" + std::string(60, ']');
  EXPECT_EQ(word_value(deep), 1.0);
}

TEST(Parser, OnlyTheFirstErrorOfALineIsReported) {
  auto p = parse("G1 X[ (open");
  EXPECT_FALSE(p->ok);
  EXPECT_EQ(p->diags.all().size(), 1u);
}

TEST(Parser, DiagnosticCarriesFileLineAndLineOffset) {
  auto p = parse("G1 (x", {3, 42, 1000});
  ASSERT_FALSE(p->ok);
  const core::Diagnostic& d = p->diags.all()[0];
  EXPECT_EQ(d.loc.file, 3u);
  EXPECT_EQ(d.loc.line, 42u);
  EXPECT_EQ(d.loc.col, 4u);
  EXPECT_EQ(d.loc.line_offset, 1000u);
}

// --- program index ----------------------------------------------------------

TEST(ProgramIndex, RecordsOWordLinesAndLinksEqualLabels) {
  auto f = core::SourceFile::from_string(
      "p", "G0 X1\no100 sub\n(body)\no100 endsub\nN10 o<x> if [1]\no<x> endif\nM2\n");
  const ProgramIndex idx = ProgramIndex::build(*f, 0);
  ASSERT_EQ(idx.entries().size(), 4u);
  EXPECT_EQ(idx.at(0).kind, OKind::Sub);
  EXPECT_EQ(idx.at(0).line, 2u);
  EXPECT_EQ(idx.at(0).offset, 6u);
  EXPECT_EQ(idx.at(0).next_same, 1u);
  EXPECT_EQ(idx.at(1).prev_same, 0u);
  EXPECT_EQ(idx.at(2).label, "x");
  EXPECT_EQ(idx.at(2).line, 5u);
  EXPECT_EQ(idx.sub("100"), 0u);
  EXPECT_EQ(idx.sub("x"), kNoEntry);
  EXPECT_EQ(idx.find(6), 0u);
  EXPECT_EQ(idx.find(7), kNoEntry);
  EXPECT_EQ(idx.next_of(0, {OKind::EndSub}), 1u);
  EXPECT_EQ(idx.prev_of(3, {OKind::If}), 2u);
}

TEST(ProgramIndex, WhileAfterDoClosesIt) {
  auto f = core::SourceFile::from_string("p", "o1 do\no1 while [0]\no2 while [1]\no2 endwhile\n");
  const ProgramIndex idx = ProgramIndex::build(*f, 0);
  ASSERT_EQ(idx.entries().size(), 4u);
  EXPECT_TRUE(idx.at(1).ends_do);
  EXPECT_FALSE(idx.at(2).ends_do);
}

TEST(ProgramIndex, LineAtHandlesCrLfAndTheLastLine) {
  const std::string_view text = "G0\r\nG1\nM2";
  const LineView a = line_at(text, 0);
  EXPECT_EQ(a.text, "G0");
  EXPECT_EQ(a.next, 4u);
  const LineView b = line_at(text, 4);
  EXPECT_EQ(b.text, "G1");
  const LineView c = line_at(text, b.next);
  EXPECT_EQ(c.text, "M2");
  EXPECT_EQ(c.next, text.size());
  EXPECT_EQ(line_at(text, 100).text, "");
}

// The shortcut for plain blocks must give the words and line number the
// whole parser gives, at the same columns, and leave every other line to
// it. The whole parser's reading is the same line with a ';' comment after
// it, which the shortcut never takes.
TEST(ParserPlainBlocks, TheShortcutReadsAsTheWholeParser) {
  std::mt19937 rng(3);
  int shortcut = 0;
  for (int n = 0; n < 20000; ++n) {
    const std::string line = test::random_block(rng, "GXYZFNOEe0123456789.-+ \t#[]()x", "NGXYZFEA");
    std::size_t first = 0;
    while (first < line.size() && (line[first] == ' ' || line[first] == '\t'))
      ++first;
    Block plain;
    if (!parse_plain_block(line, first, plain)) continue;
    ++shortcut;
    const auto whole = parse(line + ";");
    ASSERT_TRUE(whole->ok) << line;
    EXPECT_EQ(plain.line_number, whole->block.line_number) << line;
    ASSERT_EQ(plain.words.size(), whole->block.words.size()) << line;
    for (std::size_t i = 0; i < plain.words.size(); ++i) {
      const Word& a = plain.words[i];
      const Word& b = whole->block.words[i];
      EXPECT_EQ(a.letter, b.letter) << line;
      EXPECT_EQ(a.col, b.col) << line;
      ASSERT_EQ(b.value, kPlainNumber) << line;
      EXPECT_EQ(a.value, kPlainNumber) << line;
      EXPECT_EQ(std::signbit(a.number), std::signbit(b.number)) << line;
      EXPECT_EQ(a.number, b.number) << line;
    }
  }
  EXPECT_GT(shortcut, 3000);
}

TEST(ParserPlainBlocks, WhatTheShortcutLeavesToTheWholeParser) {
  for (const std::string line : {"",
                                 "   ",
                                 "N10",
                                 "G1 X1 5",
                                 "G1 X 1",
                                 "G1 X- 1",
                                 "G1 X1E3",
                                 "g1 x1",
                                 "G1 X#1",
                                 "G1 X[1]",
                                 "G1 X1 (c)",
                                 "G1 X1 ;c",
                                 "/G1 X1",
                                 "N10 O100 sub",
                                 "G1 N10",
                                 "%",
                                 "G1 X.",
                                 "G1 X1.2.3",
                                 "G1 X1234567890.1234567",
                                 "G1 @5",
                                 "N-1 G1",
                                 "N 10 G1",
                                 "G1\tX1\r"}) {
    Block b;
    std::size_t first = 0;
    while (first < line.size() && line[first] == ' ')
      ++first;
    if (line == "G1\tX1\r") {
      EXPECT_TRUE(parse_plain_block(line, first, b)) << line;  // tab and CR are blanks
      continue;
    }
    EXPECT_FALSE(parse_plain_block(line, first, b)) << line;
  }
  Block b;
  ASSERT_TRUE(parse_plain_block("N20 G1X45.75  Y4 Z-1.4104", 0, b));
  EXPECT_EQ(b.line_number, 20.0);
  ASSERT_EQ(b.words.size(), 4u);
  EXPECT_EQ(b.words[1].letter, 'X');
  EXPECT_EQ(b.words[1].col, 7u);
  EXPECT_EQ(b.words[3].number, -1.4104);
}

}  // namespace
}  // namespace usina::gcode
