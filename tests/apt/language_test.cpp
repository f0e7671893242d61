// The language: statements, continuation, comments, labels, scalars and
// expressions, nested and named definitions, SYN, diagnostics.
#include "apt_run.hpp"

namespace usina::apt::test {
namespace {

TEST(AptLanguage, DollarContinuesAndDoubleDollarComments) {
  const AptRun r =
      run("P1 = POINT/ 1, $\n   2, 3   $$ the first point\n$$ a line of comment\nFINI\n");
  EXPECT_FALSE(r.diags.has_errors());
  expect_canon(r.def("P1"), {1, 2, 3});
}

TEST(AptLanguage, CaseIsIgnoredAndLabelsAccepted) {
  const AptRun r = run("p1 = point/1,2\nAGN) GOTO/P1\nfini\n");
  EXPECT_FALSE(r.diags.has_errors());
  expect_canon(r.def("P1"), {1, 2, 0});
}

TEST(AptLanguage, ScalarsAndExpressions) {
  const AptRun r = run("A = 2\nB = A**3 - 4/2 + -1\nC = (A+1)*2\nP = POINT/A, B, C\nFINI\n");
  EXPECT_FALSE(r.diags.has_errors());
  expect_canon(r.def("P"), {2, 5, 6});
}

TEST(AptLanguage, FunctionsInDegrees) {
  const AptRun r =
      run("P = POINT/SINF(30), COSF(60), ATANF(1)\nQ = POINT/SQRTF(16), ABSF(-3), ATAN2F(1,0)\n"
          "R = POINT/EXPF(0), LOGF(1), TANF(45)\nFINI\n");
  EXPECT_FALSE(r.diags.has_errors());
  expect_canon(r.def("P"), {.5, .5, 45});
  expect_canon(r.def("Q"), {4, 3, 90});
  expect_canon(r.def("R"), {1, 0, 1});
}

TEST(AptLanguage, NestedAndNamedNestedDefinitions) {
  const AptRun r =
      run("L = LINE/(P2=POINT/1,3),(POINT/5,3)\nQ = POINT/INTOF,L,(LINE/P2,ATANGL,90)\nFINI\n");
  EXPECT_FALSE(r.diags.has_errors());
  expect_canon(r.def("P2"), {1, 3, 0});
  expect_canon(r.def("Q"), {1, 3, 0});
  EXPECT_EQ(r.result.definitions.size(), 3u);  // L, P2, Q (the anonymous one is not listed)
}

TEST(AptLanguage, SynonymsStandForTheirWords) {
  const AptRun r =
      run("SYN/PT,POINT,TT,TANTO\nC=CIRCLE/0,0,5\nP=PT/10,0\nL=LINE/P,LEFT,TT,C\nFINI\n");
  EXPECT_FALSE(r.diags.has_errors());
  expect_canon(r.def("P"), {10, 0, 0});
}

TEST(AptLanguage, UndefinedSymbolIsIbmError101AtItsColumn) {
  const AptRun r = run("P1=POINT/1,2\nL1=LINE/P1,PX\nFINI\n");
  ASSERT_EQ(r.diags.error_count(), 1);
  const core::Diagnostic& d = r.diags.all()[0];
  EXPECT_EQ(d.code, core::Code::AptUndefinedSymbol);
  EXPECT_EQ(d.loc.line, 2u);
  EXPECT_EQ(d.loc.col, 12u);
}

TEST(AptLanguage, ErrorOnAContinuationLineIsPlacedThere) {
  const AptRun r = run("P1=POINT/1,$\n  2 # 3\nFINI\n");
  ASSERT_TRUE(r.has(core::Code::AptSyntax));
  EXPECT_EQ(r.diags.all()[0].loc.line, 2u);
  EXPECT_EQ(r.diags.all()[0].loc.col, 5u);
}

TEST(AptLanguage, ArithmeticErrors) {
  EXPECT_TRUE(run("A=1/0\nFINI\n").has(core::Code::AptArithmetic));
  EXPECT_TRUE(run("A=SQRTF(-1)\nFINI\n").has(core::Code::AptArithmetic));
  EXPECT_TRUE(run("A=10**400\nFINI\n").has(core::Code::AptArithmetic));
  EXPECT_TRUE(run("A=NOSUCHF(1)\nFINI\n").has(core::Code::AptUndefinedSymbol));
  EXPECT_TRUE(run("A=SINF(1,2)\nFINI\n").has(core::Code::AptBadArgument));
}

TEST(AptLanguage, SyntaxErrors) {
  EXPECT_TRUE(run("P=POINT/1 2\nFINI\n").has(core::Code::AptSyntax));
  EXPECT_TRUE(run("P=POINT/(1,2\nFINI\n").has(core::Code::AptSyntax));
  EXPECT_TRUE(run("3=POINT/1,2\nFINI\n").has(core::Code::AptSyntax));
  EXPECT_TRUE(run("TANTO=POINT/1,2\nFINI\n").has(core::Code::AptSyntax));
  EXPECT_TRUE(run("SYN/GL\nFINI\n").has(core::Code::AptSyntax));
}

TEST(AptLanguage, GeometryInAnExpressionIsAnError) {
  EXPECT_TRUE(run("P=POINT/1,2\nA=P+1\nFINI\n").has(core::Code::AptBadArgument));
}

TEST(AptLanguage, ProcessingGoesOnPastErrors) {
  const AptRun r = run("A=1/0\nB=Q\nP=POINT/1,2,3\nC=SQRTF(-4)\nFINI\n");
  EXPECT_EQ(r.diags.error_count(), 3);
  expect_canon(r.def("P"), {1, 2, 3});
}

TEST(AptLanguage, MissingFiniIsAWarning) {
  const AptRun r = run("P=POINT/1,2\n");
  EXPECT_FALSE(r.diags.has_errors());
  EXPECT_TRUE(r.has(core::Code::AptNoFini));
}

TEST(AptLanguage, NothingAfterFiniIsRead) {
  EXPECT_FALSE(run("FINI\nP=POINT/(\n").diags.has_errors());
}

}  // namespace
}  // namespace usina::apt::test

namespace usina::apt::test {
namespace {

TEST(AptLanguage, DeepNestingIsAnErrorNotACrash) {
  const std::string deep = "A=" + std::string(100000, '(') + "1" + std::string(100000, ')');
  EXPECT_TRUE(run(deep + "\nFINI\n").has(core::Code::AptSyntax));
  std::string power = "A=2";
  for (int i = 0; i < 100000; ++i)
    power += "**1";
  EXPECT_TRUE(run(power + "\nFINI\n").has(core::Code::AptSyntax));
  std::string nest = "P=POINT/INTOF,";
  for (int i = 0; i < 50000; ++i)
    nest += "(LINE/INTOF,";
  EXPECT_TRUE(run(nest + "\nFINI\n").has(core::Code::AptSyntax));
}

}  // namespace
}  // namespace usina::apt::test

namespace usina::apt::test {
namespace {

TEST(AptLanguage, NumberBeyondDoubleIsAnError) {
  const AptRun r = run("CUTTER/1E400\nFINI\n");
  EXPECT_TRUE(r.has(core::Code::AptArithmetic));
  EXPECT_EQ(r.result.records.size(), 2u);  // FINI's records only: no infinite cutter
}

}  // namespace
}  // namespace usina::apt::test
