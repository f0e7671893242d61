// The RS274NGC interpreter, program text in, canon ops out. Parameters:
// each test runs a small program and checks the ops, the parameters or the
// one diagnostic (helpers: support/interp_run.hpp).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/interp_run.hpp"

namespace usina::gcode::interp_test {
namespace {

// ============================================================================
// Parameters
// ============================================================================

TEST(InterpParams, EveryValueOfABlockIsReadBeforeAnyIsWritten) {
  // RS274NGC 3.2.1: #2 takes the value #1 had before the block.
  RUN_OK(r, "#1=1\n#1=2 #2=#1\nG0 X#2\nM2\n");
  EXPECT_VEC(r->ends()[0], 1, 0, 0);
  EXPECT_DOUBLE_EQ(r->param(1), 2.0);
  EXPECT_DOUBLE_EQ(r->param(2), 1.0);
}

TEST(InterpParams, WordsReadTheValueBeforeTheBlocksAssignment) {
  RUN_OK(r, "#1=5 G0 X#1\nG0 Y#1\nM2\n");
  EXPECT_VEC(r->ends()[0], 0, 0, 0);
  EXPECT_VEC(r->ends()[1], 0, 5, 0);
}

TEST(InterpParams, NamedParameterNamesIgnoreCaseAndBlanks) {
  RUN_OK(r, "#<Depth Of Cut>=2\nG0 Z-#<depthofcut>\nM2\n");
  EXPECT_VEC(r->ends()[0], 0, 0, -2);
}

TEST(InterpParams, LocalsBelongToTheirCallGlobalsAreShared) {
  RUN_OK(r,
         "#<a>=1\n"
         "#<_g>=2\n"
         "#1=9\n"
         "o<s> sub\n"
         "  G0 X[EXISTS[#<a>]] Y#<_g> Z#1\n"
         "  #<a>=5\n"
         "  #<_g>=7\n"
         "o<s> endsub\n"
         "o<s> call [3]\n"
         "G0 X#<a> Y#<_g> Z#1\n"
         "M2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 2u);
  EXPECT_VEC(e[0], 0, 2, 3);
  EXPECT_VEC(e[1], 1, 7, 9);
}

TEST(InterpParams, CurrentPositionInProgramUnits) {
  RUN_OK(r,
         "G20\nG0 X1 Y2\n#1=#<_x>\n#2=#5421\n#3=#<_metric>\n#4=#<_imperial>\n"
         "G21\n#5=#<_metric>\n#6=#<_x>\nM2\n");
  EXPECT_DOUBLE_EQ(r->param(1), 1.0);
  EXPECT_DOUBLE_EQ(r->param(2), 2.0);
  EXPECT_DOUBLE_EQ(r->param(3), 0.0);
  EXPECT_DOUBLE_EQ(r->param(4), 1.0);
  EXPECT_DOUBLE_EQ(r->param(5), 1.0);
  EXPECT_NEAR(r->param(6), kInch, kTol);
}

TEST(InterpParams, PositionParametersAreInTheWorkSystem) {
  RUN_OK(r, "G10 L2 P1 X10\nG0 X2\n#1=#5420\n#2=#<_abs_x>\nM2\n");
  EXPECT_DOUBLE_EQ(r->param(1), 2.0);
  EXPECT_DOUBLE_EQ(r->param(2), 12.0);
}

TEST(InterpParams, ModalStateParameters) {
  RUN_OK(r,
         "G18 G91 G1 F10\n#1=#<_plane>\n#2=#<_incremental>\n#3=#<_absolute>\n"
         "#4=#<_motion_mode>\n#5=#<_feed>\nG20\nF4\n#6=#<_feed>\nM2\n");
  EXPECT_DOUBLE_EQ(r->param(1), 180.0);
  EXPECT_DOUBLE_EQ(r->param(2), 1.0);
  EXPECT_DOUBLE_EQ(r->param(3), 0.0);
  EXPECT_DOUBLE_EQ(r->param(4), 10.0);
  EXPECT_DOUBLE_EQ(r->param(5), 10.0);
  EXPECT_NEAR(r->param(6), 4.0, kTol);
}

TEST(InterpParams, ReadOnlyPredefinedParameterCannotBeAssigned) {
  auto r = run("G0 X1\n#<_x>=1\nM2\n");
  expect_error(*r, Code::ReadOnlyParameter, 2, 1);
}

TEST(InterpParams, UndefinedNamedParameterInAWord) {
  auto r = run("G0 X1\nG0 X#<nope>\nM2\n");
  expect_error(*r, Code::UndefinedParameter, 2, 5);
}

TEST(InterpParams, ParameterNumberOutOfRangeInAnAssignment) {
  auto r = run("#0=1\nM2\n");
  expect_error(*r, Code::ParameterOutOfRange, 1, 1);
  auto high = run("G0 X1\n  #5603=1\nM2\n");
  expect_error(*high, Code::ParameterOutOfRange, 2, 3);
}

TEST(InterpParams, DivisionByZeroInAWord) {
  auto r = run("G0 X1\nG0 X[1/0]\nM2\n");
  EXPECT_FALSE(r->ok);
  const auto errors = r->of_severity(core::Severity::Error);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(core::code_name(errors[0].code), core::code_name(Code::DivisionByZero));
  EXPECT_EQ(errors[0].loc.line, 2u);
}

// Regression (a bug the tests found, fixed): a parameter index that evaluates to NaN (inf - inf)
// passes parameter_index() and is read out of bounds. Expected: an error (E_PARAMETER_OUT_OF_RANGE)
// on line 1. Actual: undefined behaviour; the `usina trace` binary dies with SIGSEGV on this
// program.
TEST(InterpParams, NotANumberParameterIndexIsAnError) {
  auto r = run("#1=#[[10**400]-[10**400]]\nM2\n");
  EXPECT_FALSE(r->ok);
  EXPECT_EQ(r->of_severity(core::Severity::Error).size(), 1u);
}

}  // namespace
}  // namespace usina::gcode::interp_test
