// The romi dialect's Fagor-style parametric statements (spec/romi.md,
// "Parametric programming").
#include <string>

#include "romi_test_support.hpp"
#include "support/files.hpp"

namespace usina::gcode::romi_test {
namespace {

using core::Code;

// A romi program run from a file (mapped, its pages released behind the
// reader), not from a string.
std::unique_ptr<Run> run_romi_file(const std::string& path) {
  auto r = std::make_unique<Run>();
  std::string error;
  auto file = core::SourceFile::open(path, error);
  EXPECT_NE(file, nullptr) << error;
  if (file == nullptr) return r;
  const std::uint32_t id = r->sources.add(std::move(file));
  const Dialect* d = find_dialect("romi");
  auto runner = d->make_runner(
      RunContext{r->sources, {}, resolve_options(*d, {}).value(), r->path, r->diags});
  r->ok = runner->run(id);
  return r;
}

TEST(RomiParam, AssignAndUseAsAWordValue) {
  auto r = run_romi("(P1 = 2 * 5)#(P3=-4)#G00 X P1 Y-P3#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_near(r->ends().back(), {10, 4, 0});
}

TEST(RomiParam, AnyWordTakesAParameter) {
  auto r = run_romi("(P3 = 250)#(P4 = 1)#G P4 X10 F P3#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto f = r->all<canon::Feed>();
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].f, 250.0);
}

TEST(RomiParam, OperatorsAndFunctions) {
  auto r = run_romi(
      "(P2 = SIN(30) + SQRT(16) + 2^3 + 7 MOD 4 + INT(-2.5) + LOG(100) + ABS(-1) + ROUND(1.6))#"
      "G00 X P2#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_near(r->ends().back(), {0.5 + 4 + 8 + 3 - 2 + 2 + 1 + 2, 0, 0});
}

TEST(RomiParam, ComparisonsAndLogic) {
  auto r = run_romi(
      "(P1 = (2 GT 1) AND (3 LE 3) + 0)#(P2 = NOT (1 EQ 1) OR (2 NE 2))#G00 X P1 Y P2#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_near(r->ends().back(), {1, 0, 0});
}

TEST(RomiParam, PrecedenceAsInArithmetic) {
  auto r = run_romi("(P100 = 1 + 2 * 3 ^ 2 - (4 - 1))#G00 X P100#M02#");
  expect_near(r->ends().back(), {16, 0, 0});
}

TEST(RomiParam, IfGotoLoops) {
  auto r = run_romi("(P1 = 0)#N10 (P1 = P1 + 1)#G00 X P1#(IF P1 LT 3 GOTO N10)#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  EXPECT_EQ(r->ends().size(), 3u);
  expect_near(r->ends().back(), {3, 0, 0});
}

TEST(RomiParam, GotoSkipsForward) {
  auto r = run_romi("(GOTO N30)#G00 X5#N30 G00 Y5#M02#");
  ASSERT_EQ(r->ends().size(), 1u);
  expect_near(r->ends().back(), {0, 5, 0});
}

TEST(RomiParam, RepeatRunsASectionNTimes) {
  auto r = run_romi("G91#N10 G00 X1#N20 Y1#(RPT N10, N20, 2)#G90#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  EXPECT_EQ(r->ends().size(), 6u);  // once in the flow, twice repeated
  expect_near(r->ends().back(), {3, 3, 0});
}

TEST(RomiParam, CallSubRet) {
  auto r = run_romi("(SUB 5)#G91 G00 X1#(RET)#(CALL 5)#(CALL 5)#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  EXPECT_EQ(r->ends().size(), 2u);
  expect_near(r->ends().back(), {2, 0, 0});
}

TEST(RomiParam, UnknownBlockNumberIsAnError) {
  EXPECT_EQ(run_romi("(GOTO N99)#M02#")->first_error(), Code::UnknownBlockNumber);
  EXPECT_EQ(run_romi("(CALL 7)#M02#")->first_error(), Code::UnknownBlockNumber);
}

TEST(RomiParam, RetWithoutCallIsAnError) {
  EXPECT_EQ(run_romi("(RET)#M02#")->first_error(), Code::UnmatchedControl);
}

TEST(RomiParam, RunawayLoopEnds) {
  InterpOptions o;
  o.max_total_iterations = 100;
  auto r = run_romi("N10 (GOTO N10)#M02#", o);
  EXPECT_EQ(r->first_error(), Code::TooManyIterations);
}

TEST(RomiParam, RecursionEnds) {
  InterpOptions o;
  o.max_call_depth = 10;
  auto r = run_romi("(SUB 1)#(CALL 1)#(RET)#(CALL 1)#M02#", o);
  EXPECT_EQ(r->first_error(), Code::RecursionTooDeep);
}

TEST(RomiParam, ParameterOutOfRangeIsAnError) {
  EXPECT_EQ(run_romi("(P1000 = 1)#M02#")->first_error(), Code::ParameterOutOfRange);
}

TEST(RomiParam, DivisionByZeroIsAnError) {
  EXPECT_EQ(run_romi("(P1 = 1 / 0)#M02#")->first_error(), Code::DivisionByZero);
}

// Every operation's value finite where it is made: a division or a
// comparison after an overflow does not hide it.
TEST(RomiParam, AnOverflowIsAnErrorWhereItIsMade) {
  for (const char* text : {"(P1 = 1 / EXP(720))#M02#", "(P1 = (10 ^ 400) / 10 ^ 400)#M02#",
                           "(P1 = 1 / (10 ^ 400))#M02#"}) {
    EXPECT_EQ(run_romi(text)->first_error(), Code::NumberOutOfRange) << text;
  }
  auto fine = run_romi("(P1 = 1 / EXP(700))#M02#");
  EXPECT_TRUE(fine->ok) << fine->first_error_text();
}

TEST(RomiParam, ACommentIsNotAStatement) {
  auto r = run_romi("(roughing pass)#(P1 is the radius)#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  EXPECT_EQ(r->all<canon::Comment>().size(), 2u);
}

TEST(RomiParam, AJumpBackToTextReleasedFromMemoryReadsItAgain) {
  // Over 8 MiB between N10 and the jump: the text behind the reader has
  // left memory (issue 19) when the jump goes back to it.
  std::string text = "(P1 = 0)#N10 (P1 = P1 + 1)#\n";
  constexpr int kLines = 120000;
  for (int i = 0; i < kLines; ++i)
    text += "G00 X1.25 Y2.5 ;a comment that makes the line longer, as a real program has\n";
  text += "(IF P1 LT 2 GOTO N10)#M02#\n";
  ASSERT_GT(text.size(), 8u << 20);
  test::TempDir dir;
  auto r = run_romi_file(dir.write("long.nc", text));
  ASSERT_TRUE(r->ok) << r->first_error_text();
  EXPECT_EQ(r->all<canon::Traverse>().size(), 2u * kLines);
}

}  // namespace
}  // namespace usina::gcode::romi_test
