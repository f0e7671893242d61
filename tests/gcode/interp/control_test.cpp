// The RS274NGC interpreter, program text in, canon ops out. Control flow: O-word subroutines,
// loops, branches, M98 subprograms: each test runs a small program and checks the ops, the
// parameters or the one diagnostic (helpers: support/interp_run.hpp).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/interp_run.hpp"

namespace usina::gcode::interp_test {
namespace {

// ============================================================================
// Control flow
// ============================================================================

std::string branch_program(int n) {
  return fmt::format(
      "#1={}\n"
      "o1 if [#1 EQ 1]\n  G0 X1\n"
      "o1 elseif [#1 EQ 2]\n  G0 X2\n"
      "o1 elseif [#1 EQ 3]\n  G0 X3\n"
      "o1 else\n  G0 X4\n"
      "o1 endif\n"
      "M2\n",
      n);
}

TEST(InterpControl, IfElseifElseRunsExactlyOneBranch) {
  for (int n = 1; n <= 5; ++n) {
    auto r = run(branch_program(n));
    ASSERT_TRUE(r->ok) << n;
    const auto e = r->ends();
    ASSERT_EQ(e.size(), 1u) << n;
    EXPECT_VEC(e[0], static_cast<double>(std::min(n, 4)), 0, 0);
  }
}

TEST(InterpControl, IfWithoutElseSkipsToEndif) {
  RUN_OK(r, "o1 if [0]\nG0 X1\no1 endif\nG0 X2\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 1u);
  EXPECT_VEC(e[0], 2, 0, 0);
}

TEST(InterpControl, WhileRunsWhileTheConditionHolds) {
  RUN_OK(r, "#1=0\no1 while [#1 LT 3]\nG0 X#1\n#1=[#1+1]\no1 endwhile\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[2], 2, 0, 0);
}

TEST(InterpControl, WhileFalseAtFirstRunsNothing) {
  RUN_OK(r, "o1 while [0]\nG0 X1\no1 endwhile\nM2\n");
  EXPECT_TRUE(r->ends().empty());
}

TEST(InterpControl, DoWhileRunsTheBodyAtLeastOnce) {
  RUN_OK(r, "#1=5\no1 do\nG0 X#1\n#1=[#1+1]\no1 while [#1 LT 3]\nM2\n");
  EXPECT_EQ(r->ends().size(), 1u);
  RUN_OK(three, "#1=0\no1 do\nG0 X#1\n#1=[#1+1]\no1 while [#1 LT 3]\nM2\n");
  EXPECT_EQ(three->ends().size(), 3u);
}

TEST(InterpControl, RepeatRunsTheBodyNTimes) {
  RUN_OK(r, "o1 repeat [3]\nG91 G0 X1\no1 endrepeat\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[2], 3, 0, 0);
}

TEST(InterpControl, RepeatZeroTimesRunsNothing) {
  RUN_OK(r, "o1 repeat [0]\nG0 X1\no1 endrepeat\nG0 X2\nM2\n");
  EXPECT_EQ(r->ends().size(), 1u);
}

TEST(InterpControl, BreakLeavesTheLoop) {
  RUN_OK(r,
         "#1=0\n"
         "o1 while [1]\n"
         "  #1=[#1+1]\n"
         "  o2 if [#1 GT 2]\n"
         "    o1 break\n"
         "  o2 endif\n"
         "  G0 X#1\n"
         "o1 endwhile\n"
         "G0 Y9\n"
         "M2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[1], 2, 0, 0);
  EXPECT_VEC(e[2], 2, 9, 0);
}

TEST(InterpControl, BreakLeavesARepeat) {
  RUN_OK(r,
         "o1 repeat [10]\nG91 G0 X1\no2 if [#<_x> GE 2]\no1 break\no2 endif\no1 endrepeat\nM2\n");
  EXPECT_EQ(r->ends().size(), 2u);
}

TEST(InterpControl, ContinueSkipsTheRestOfTheBody) {
  RUN_OK(r,
         "#1=0\n"
         "o1 while [#1 LT 4]\n"
         "  #1=[#1+1]\n"
         "  o2 if [#1 EQ 2]\n"
         "    o1 continue\n"
         "  o2 endif\n"
         "  G0 X#1\n"
         "o1 endwhile\n"
         "M2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[0], 1, 0, 0);
  EXPECT_VEC(e[1], 3, 0, 0);
  EXPECT_VEC(e[2], 4, 0, 0);
}

TEST(InterpControl, ContinueInADoWhileTestsTheCondition) {
  RUN_OK(r,
         "#1=0\n"
         "o1 do\n"
         "  #1=[#1+1]\n"
         "  o2 if [#1 EQ 1]\n"
         "    o1 continue\n"
         "  o2 endif\n"
         "  G0 X#1\n"
         "o1 while [#1 LT 3]\n"
         "M2\n");
  EXPECT_EQ(r->ends().size(), 2u);
}

TEST(InterpControl, NestedLoopsEachRunFully) {
  RUN_OK(r,
         "#1=0\n"
         "o1 while [#1 LT 3]\n"
         "  #2=0\n"
         "  o2 while [#2 LT 4]\n"
         "    G0 X#1 Y#2\n"
         "    #2=[#2+1]\n"
         "  o2 endwhile\n"
         "  #1=[#1+1]\n"
         "o1 endwhile\n"
         "M2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 12u);
  EXPECT_VEC(e[11], 2, 3, 0);
}

TEST(InterpControl, LoopLimitCountsOneRunOfAWhileLoop) {
  // 3 x 4 inner iterations in all, but no single run of a loop exceeds 5.
  InterpOptions o;
  o.max_loop_iterations = 5;
  RUN_OK(r,
         "#1=0\n"
         "o1 while [#1 LT 3]\n"
         "  #2=0\n"
         "  o2 while [#2 LT 4]\n"
         "    #2=[#2+1]\n"
         "  o2 endwhile\n"
         "  #1=[#1+1]\n"
         "o1 endwhile\n"
         "M2\n",
         std::move(o));
}

// Regression (a bug the tests found, fixed): the loop counter of `repeat` is never reset when the
// loop finishes normally (EndRepeat pops loops_ but does not erase iterations_), so an inner repeat
// counts its iterations over every run of the outer loop. Expected: 10 x 10 nested repeats with
// max_loop_iterations = 50 run (no single run exceeds 10). Actual: E_TOO_MANY_ITERATIONS on the
// inner endrepeat once the total passes 50. `while` loops reset correctly.
TEST(InterpControl, LoopLimitCountsOneRunOfARepeat) {
  InterpOptions o;
  o.max_loop_iterations = 50;
  RUN_OK(r, "o1 repeat [10]\no2 repeat [10]\nG0 X1\no2 endrepeat\no1 endrepeat\nM2\n",
         std::move(o));
  EXPECT_EQ(r->ends().size(), 100u);
}

// Regression (a bug the tests found, fixed): as for repeat: a do-while's counter (keyed by its
// `do`) is not reset when its closing `while` is false. Expected: an inner do-while of 10 runs
// inside an outer loop of 10 with max_loop_iterations = 50 runs. Actual:
// E_TOO_MANY_ITERATIONS.
TEST(InterpControl, LoopLimitCountsOneRunOfADoWhile) {
  InterpOptions o;
  o.max_loop_iterations = 50;
  RUN_OK(r,
         "#1=0\n"
         "o1 while [#1 LT 10]\n"
         "  #2=0\n"
         "  o2 do\n"
         "    #2=[#2+1]\n"
         "  o2 while [#2 LT 10]\n"
         "  #1=[#1+1]\n"
         "o1 endwhile\n"
         "M2\n",
         std::move(o));
}

// Regression (a bug the tests found, fixed): `break` erases the counter of the break statement's
// own index entry, not the loop's, so a while loop left by break keeps its count for its next run.
// Expected: an inner while left by break after 9 runs, inside an outer loop of 10, with
// max_loop_iterations = 50, runs. Actual: E_TOO_MANY_ITERATIONS.
TEST(InterpControl, LoopLimitCountsOneRunOfAWhileLeftByBreak) {
  InterpOptions o;
  o.max_loop_iterations = 50;
  RUN_OK(r,
         "#1=0\n"
         "o1 while [#1 LT 10]\n"
         "  #2=0\n"
         "  o2 while [1]\n"
         "    #2=[#2+1]\n"
         "    o3 if [#2 GE 9]\n"
         "      o2 break\n"
         "    o3 endif\n"
         "  o2 endwhile\n"
         "  #1=[#1+1]\n"
         "o1 endwhile\n"
         "M2\n",
         std::move(o));
}

TEST(InterpControl, TooManyIterationsStopsARunawayLoop) {
  InterpOptions o;
  o.max_loop_iterations = 5;
  auto r = run("o1 while [1]\n  G91 G0 X1\no1 endwhile\nM2\n", std::move(o));
  expect_error(*r, Code::TooManyIterations, 3, 1);
  EXPECT_EQ(r->ends().size(), 6u);
}

TEST(InterpControl, TooManyIterationsOfARepeat) {
  InterpOptions o;
  o.max_loop_iterations = 3;
  auto r = run("o1 repeat [100]\no1 endrepeat\nM2\n", std::move(o));
  expect_error(*r, Code::TooManyIterations, 2, 1);
}

TEST(InterpControl, TooManyIterationsOfADoWhile) {
  InterpOptions o;
  o.max_loop_iterations = 3;
  auto r = run("o1 do\no1 while [1]\nM2\n", std::move(o));
  expect_error(*r, Code::TooManyIterations, 2, 1);
}

// --- subroutines ------------------------------------------------------------

TEST(InterpSub, CallWithArgumentsAndReturnValue) {
  RUN_OK(r,
         "o<double> sub\n"
         "  o<double> return [#1*2]\n"
         "o<double> endsub\n"
         "o<double> call [21]\n"
         "G0 X#<_value>\n"
         "#1=#<_value_returned>\n"
         "M2\n");
  EXPECT_VEC(r->ends()[0], 42, 0, 0);
  EXPECT_DOUBLE_EQ(r->param(1), 1.0);
}

TEST(InterpSub, EndsubWithValueReturnsIt) {
  RUN_OK(r, "o100 sub\no100 endsub [7]\no100 call\nG0 X#<_value>\nM2\n");
  EXPECT_VEC(r->ends()[0], 7, 0, 0);
}

TEST(InterpSub, ArgumentsAreHash1ToHash30AndRestoredAfter) {
  RUN_OK(r,
         "#1=100 #2=200 #3=300\n"
         "o1 sub\n  G0 X#1 Y#2 Z#3\no1 endsub\n"
         "o1 call [1] [2]\n"
         "G0 X#1 Y#2 Z#3\n"
         "M2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 2u);
  EXPECT_VEC(e[0], 1, 2, 0);
  EXPECT_VEC(e[1], 100, 200, 300);
}

TEST(InterpSub, SubroutineDefinedAfterItsCall) {
  RUN_OK(r, "o<later> call [4]\nM2\no<later> sub\nG0 X#1\no<later> endsub\n");
  EXPECT_VEC(r->ends()[0], 4, 0, 0);
}

TEST(InterpSub, DefinitionIsSkippedWhenReached) {
  RUN_OK(r, "o1 sub\nG0 X9\no1 endsub\nG0 X1\nM2\n");
  EXPECT_EQ(r->ends().size(), 1u);
  EXPECT_VEC(r->ends()[0], 1, 0, 0);
}

TEST(InterpSub, OpsOfASubroutinePointIntoIt) {
  RUN_OK(r, "o1 sub\n  G0 X9\no1 endsub\no1 call\nM2\n");
  const auto t = r->ops_of<Traverse>();
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0]->src.line, 2u);
  EXPECT_EQ(t[0]->src.col, 3u);
}

TEST(InterpSub, RecursiveFactorial) {
  RUN_OK(r,
         "o<fact> sub\n"
         "  o<base> if [#1 LE 1]\n"
         "    o<fact> return [1]\n"
         "  o<base> endif\n"
         "  o<fact> call [#1-1]\n"
         "  o<fact> return [#1*#<_value>]\n"
         "o<fact> endsub\n"
         "o<fact> call [5]\n"
         "#1=#<_value>\n"
         "M2\n");
  EXPECT_DOUBLE_EQ(r->param(1), 120.0);
}

TEST(InterpSub, CallByNumberFromAParameter) {
  RUN_OK(r, "#5=200\no200 sub\nG0 X2\no200 endsub\no#5 call\nM2\n");
  EXPECT_VEC(r->ends()[0], 2, 0, 0);
}

TEST(InterpSub, CallLevelInsideASubroutine) {
  RUN_OK(r, "o1 sub\n#<_lvl>=#<_call_level>\no1 endsub\no1 call\n#1=#<_lvl>\nM2\n");
  EXPECT_DOUBLE_EQ(r->param(1), 1.0);
}

TEST(InterpSub, SubroutineInItsOwnFileOnTheSearchPath) {
  TempDir dir;
  const std::string file = dir.write("peck.ngc", "o<peck> sub\n  G0 X#1\no<peck> endsub\n");
  InterpOptions o;
  o.subroutine_path = {"/nonexistent/usina", dir.path()};
  RUN_OK(r, "o<peck> call [4]\no<peck> call [5]\nM2\n", std::move(o));
  const auto t = r->ops_of<Traverse>();
  ASSERT_EQ(t.size(), 2u);
  EXPECT_VEC(std::get<Traverse>(t[1]->kind).to, 5, 0, 0);
  // The op points into the subroutine's file, line 2.
  const core::SourceFile* f = r->sources.get(t[0]->src.file);
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->name(), file);
  EXPECT_EQ(t[0]->src.line, 2u);
  EXPECT_EQ(r->sources.size(), 2u) << "the file is loaded once";
}

TEST(InterpSub, FileWithoutSubLinesIsTheSubroutineBody) {
  TempDir dir;
  dir.write("corner.ngc", "G0 X#1 Y#2\n");
  InterpOptions o;
  o.subroutine_path = {dir.path()};
  RUN_OK(r, "o<corner> call [1] [2]\nG0 Z3\nM2\n", std::move(o));
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 2u);
  EXPECT_VEC(e[0], 1, 2, 0);
  EXPECT_VEC(e[1], 1, 2, 3);
}

TEST(InterpSub, SubroutineFileMayCallSubroutinesOfTheMainProgram) {
  TempDir dir;
  dir.write("outer.ngc", "o<outer> sub\n  o<inner> call\no<outer> endsub\n");
  InterpOptions o;
  o.subroutine_path = {dir.path()};
  RUN_OK(r, "o<inner> sub\nG0 X8\no<inner> endsub\no<outer> call\nM2\n", std::move(o));
  EXPECT_VEC(r->ends()[0], 8, 0, 0);
}

TEST(InterpSub, SubroutineFileWithoutEndsubIsAnError) {
  TempDir dir;
  const std::string file = dir.write("open.ngc", "o<open> sub\nG0 X1\n");
  InterpOptions o;
  o.subroutine_path = {dir.path()};
  auto r = run("o<open> call\nM2\n", std::move(o));
  EXPECT_FALSE(r->ok);
  const auto errors = r->of_severity(core::Severity::Error);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(core::code_name(errors[0].code), core::code_name(Code::UnclosedBlock));
  EXPECT_EQ(r->sources.get(errors[0].loc.file)->name(), file);
}

TEST(InterpSub, UnknownSubroutine) {
  auto r = run("G0 X1\n  o<nothere> call\nM2\n");
  expect_error(*r, Code::UnknownSubroutine, 2, 3);
}

TEST(InterpSub, ShellSyntaxInANameIsNeverRun) {
  // LinuxCNC expands o<name> file names with wordexp(), which runs $(...).
  // usina never may: the name is only a file name.
  const char* marker = "/tmp/usina_pwned";
  ::unlink(marker);
  TempDir dir;
  InterpOptions o;
  o.subroutine_path = {dir.path(), "."};
  auto r = run("o<$(touch /tmp/usina_pwned)> call\nM2\n", std::move(o));
  expect_error(*r, Code::BadSubroutineName, 1, 1);  // the '/' of the path

  struct stat st {};

  EXPECT_NE(::stat(marker, &st), 0) << marker << " was created";
  auto backticks = run("o<`touch /tmp/usina_pwned`> call\nM2\n");
  expect_error(*backticks, Code::BadSubroutineName, 1, 1);
  EXPECT_NE(::stat(marker, &st), 0) << marker << " was created";
}

TEST(InterpSub, NameWithoutSlashButWithShellSyntaxIsOnlyAFileName) {
  TempDir dir;
  // A file literally named so is found; nothing is expanded.
  dir.write("$(id).ngc", "G0 X3\n");
  InterpOptions o;
  o.subroutine_path = {dir.path()};
  RUN_OK(r, "o<$(id)> call\nM2\n", std::move(o));
  EXPECT_VEC(r->ends()[0], 3, 0, 0);
}

TEST(InterpSub, NamesCannotLeaveTheSearchPath) {
  TempDir dir;
  dir.write(".hidden.ngc", "G0 X1\n");
  InterpOptions o;
  o.subroutine_path = {dir.path()};
  auto r = run("o<.hidden> call\nM2\n", o);
  expect_error(*r, Code::BadSubroutineName, 1, 1);
  auto up = run("o<../etc/passwd> call\nM2\n", o);
  expect_error(*up, Code::BadSubroutineName, 1, 1);
}

TEST(InterpSub, RecursionTooDeep) {
  InterpOptions o;
  o.max_call_depth = 10;
  auto r = run("o<r> sub\n  o<r> call\no<r> endsub\no<r> call\nM2\n", std::move(o));
  expect_error(*r, Code::RecursionTooDeep, 2, 3);
}

TEST(InterpSub, AtMostThirtyArguments) {
  std::string call = "o1 call";
  for (int i = 0; i < 31; ++i)
    call += " [1]";
  auto r = run("o1 sub\no1 endsub\n" + call + "\nM2\n");
  expect_error(*r, Code::BadOWord, 3, 1);
}

TEST(InterpSub, SubWithoutEndsub) {
  auto r = run("G0 X1\no<s> sub\nG0 X2\nM2\n");
  expect_error(*r, Code::UnclosedBlock, 2, 1);
}

TEST(InterpSub, EndsubOutsideACall) {
  auto r = run("G0 X1\no<s> endsub\nM2\n");
  expect_error(*r, Code::UnmatchedControl, 2, 1);
  auto ret = run("o<s> return\nM2\n");
  expect_error(*ret, Code::UnmatchedControl, 1, 1);
}

// --- Fanuc-style subprograms ------------------------------------------------

TEST(InterpFanuc, M98RunsTheSubprogramLTimes) {
  RUN_OK(r, "M98 P100 L2\nG90 G0 Y5\nM30\nO100\nG91 G0 X1\nM99\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[0], 1, 0, 0);
  EXPECT_VEC(e[1], 2, 0, 0);
  EXPECT_VEC(e[2], 2, 5, 0);
}

TEST(InterpFanuc, M98WithoutLRunsOnce) {
  RUN_OK(r, "M98 P7\nM30\nO7 (subprogram)\nG0 X1\nM99\n");
  EXPECT_EQ(r->ends().size(), 1u);
}

TEST(InterpFanuc, M98ParametersAreNotScoped) {
  RUN_OK(r, "#1=1\nM98 P7\nG0 X#1\nM30\nO7\n#1=6\nM99\n");
  EXPECT_VEC(r->ends()[0], 6, 0, 0);
}

TEST(InterpFanuc, M98WithoutP) {
  auto r = run("G0 X1\nG0 X2 M98\nM30\n");
  expect_error(*r, Code::MissingWord, 2, 7);
}

TEST(InterpFanuc, M98OfAMissingProgram) {
  auto r = run("M98 P200\nM30\n");
  expect_error(*r, Code::UnknownSubroutine, 1, 5);
}

// --- unclosed and unmatched control statements -----------------------------

// Control statements left open, closed without an opening, or failing:
// each program stops at its one error.
constexpr ErrorCase kControlErrors[] = {
    {"if without endif", "G0 X1\no1 if [0]\nG0 X2\nM2\n", Code::UnclosedBlock, 2, 1},
    {"else of a taken branch without endif", "o1 if [1]\nG0 X1\no1 else\nG0 X2\nM2\n",
     Code::UnclosedBlock, 3, 1},
    {"while without endwhile", "o1 while [0]\nG0 X1\nM2\n", Code::UnclosedBlock, 1, 1},
    {"repeat without endrepeat", "o1 repeat [2]\nG0 X1\nM2\n", Code::UnclosedBlock, 1, 1},
    {"break outside a loop", "G0 X1\no1 break\nM2\n", Code::UnclosedBlock, 2, 1},
    // Regression (a bug the tests found, fixed): a closing statement with no opening one is not
    // E_UNMATCHED_CONTROL: `o1 endwhile` alone is reported as E_UNCLOSED_CONTROL_BLOCK ("o1
    // endwhile has no while"), and `o1 else` / `o1 endif` without an `o1 if` are accepted
    // silently (else jumps to the endif; endif does nothing). Expected:
    // E_UNMATCHED_CONTROL at the stray statement in each case.
    {"a stray closing statement is unmatched", "G0 X1\no1 endwhile\nM2\n", Code::UnmatchedControl,
     2, 1},
    {"a stray closing statement is unmatched", "o1 endrepeat\nM2\n", Code::UnmatchedControl, 1, 1},
    {"a stray closing statement is unmatched", "o1 else\nG0 X1\no1 endif\nM2\n",
     Code::UnmatchedControl, 1, 1},
    {"a stray closing statement is unmatched", "o1 endif\nM2\n", Code::UnmatchedControl, 1, 1},
    {"an error in a condition is reported", "o1 if [#<undefined> GT 1]\no1 endif\nM2\n",
     Code::UndefinedParameter, 1, 8},
    {"an O-word after other text is a syntax error", "G0 X1 o1 if [1]\nM2\n", Code::MisplacedOWord,
     1, 7},
};

TEST(InterpControl, UnclosedUnmatchedAndFailedControlStatementsAreErrors) {
  expect_errors(kControlErrors);
}

}  // namespace
}  // namespace usina::gcode::interp_test
