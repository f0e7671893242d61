// The fanuc dialect's runner: lexical rules, the decimal-point option,
// control flow, subprograms and macros, system variables, the
// transformations, each rule and each error path (docs/fanuc.md).
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "fanuc_test_support.hpp"

namespace usina::gcode::fanuc_test {
namespace {

using core::Code;
using core::Vec3;

TEST(FanucEngine, SemicolonEndsABlockAndPercentDelimitsTheTape) {
  auto r = run_fanuc("leader text\n%\nO0001 (MAIN)\nG0 X1. ; G0 Y2.\nM30\n%\ntrailing junk\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  ASSERT_EQ(r->ends().size(), 2u);
  expect_end(*r, {1, 2, 0});
}

TEST(FanucEngine, EmptyProgramsWarn) {
  for (const char* text : {"", "%\n%\n", "(ONLY A COMMENT)\n", ";;;\n"}) {
    auto r = run_fanuc(text);
    EXPECT_TRUE(r->ok) << text;
    EXPECT_TRUE(r->has(Code::NoProgramEnd)) << text;
  }
}

TEST(FanucEngine, TextAfterSemicolonIsAnotherBlock) {
  auto r = run_fanuc("G0 X1. ; note\nM30\n");
  EXPECT_FALSE(r->ok);
}

TEST(FanucEngine, CommentsMayHoldSemicolonsAndNestedParentheses) {
  auto r = run_fanuc("G0 X1. (A; B (C) D)\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {1, 0, 0});
}

TEST(FanucEngine, DecimalPointCalculatorWarnsOnce) {
  auto r = run_fanuc("G0 X1000\nY2000\nM30\n");
  EXPECT_TRUE(r->ok);
  expect_end(*r, {1000, 2000, 0});
  int warnings = 0;
  for (const core::Diagnostic& d : r->diags.all())
    warnings += d.code == Code::IntegerCoordinate ? 1 : 0;
  EXPECT_EQ(warnings, 1);
}

TEST(FanucEngine, DecimalPointFanucReadsLeastIncrements) {
  auto r = run_fanuc("#1 = 50\nG0 X1000 Y2.\nX#1 Z[5 * 2]\nF100 G1 X1.5\nM30\n", {},
                     {"decimal_point=fanuc"});
  EXPECT_TRUE(r->ok) << r->first_error_text();
  ASSERT_EQ(r->ends().size(), 3u);
  EXPECT_NEAR(r->ends()[0].x, 1.0, 1e-9);
  EXPECT_NEAR(r->ends()[1].x, 50.0, 1e-9);  // variables carry real values
  EXPECT_NEAR(r->ends()[1].z, 10.0, 1e-9);
  EXPECT_NEAR(r->ends()[2].x, 1.5, 1e-9);
  EXPECT_FALSE(r->has(Code::IntegerCoordinate));
}

// The rule holds in a plain move after others (a shortcut for plain moves
// must not let an integer past it).
TEST(FanucEngine, DecimalPointRuleAfterPlainMoves) {
  auto fanuc = run_fanuc("G0 X1. Y1.\nG1 X1000 Y2. F100.\nM30\n", {}, {"decimal_point=fanuc"});
  EXPECT_TRUE(fanuc->ok) << fanuc->first_error_text();
  ASSERT_EQ(fanuc->ends().size(), 2u);
  EXPECT_NEAR(fanuc->ends()[1].x, 1.0, 1e-9);
  auto calculator = run_fanuc("G0 X1. Y1.\nG1 X1000 Y2. F100.\nM30\n");
  ASSERT_EQ(calculator->ends().size(), 2u);
  EXPECT_NEAR(calculator->ends()[1].x, 1000.0, 1e-9);
  EXPECT_TRUE(calculator->has(Code::IntegerCoordinate));
}

TEST(FanucEngine, VacantVariableLeavesItsWordOut) {
  auto r = run_fanuc("G0 X5. Y5.\nG0 X#1 Y7.\nM30\n");
  EXPECT_TRUE(r->ok);
  expect_end(*r, {5, 7, 0});
}

TEST(FanucEngine, IfThenAndIfGoto) {
  auto r = run_fanuc(
      "IF [#1 EQ #0] THEN #1 = 3.\n#2 = 0\nN10 #2 = #2 + 1\nIF [#2 LT #1] GOTO 10\nG0 X#2\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {3, 0, 0});
}

TEST(FanucEngine, NestedWhileThreeDeep) {
  auto r = run_fanuc(
      "#1 = 0\n#10 = 0\nWHILE [#1 LT 2] DO1\n#2 = 0\nWHILE [#2 LT 2] DO2\n#3 = 0\n"
      "WHILE [#3 LT 2] DO3\n#10 = #10 + 1\n#3 = #3 + 1\nEND3\n#2 = #2 + 1\nEND2\n"
      "#1 = #1 + 1\nEND1\nG0 X#10\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {8, 0, 0});
}

TEST(FanucEngine, SequentialLoopsMayReuseTheirNumber) {
  auto r = run_fanuc(
      "#1 = 0\nWHILE [#1 LT 2] DO1\n#1 = #1 + 1\nEND1\n"
      "WHILE [#1 LT 5] DO1\n#1 = #1 + 1\nEND1\nG0 X#1\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {5, 0, 0});
}

TEST(FanucEngine, LoopErrors) {
  EXPECT_EQ(run_fanuc("WHILE [1 EQ 1] DO4\nEND4\nM30\n")->first_error(), Code::BadLoop);
  EXPECT_EQ(run_fanuc("WHILE [1 EQ 1] DO1\nM30\n")->first_error(), Code::BadLoop);
  EXPECT_EQ(run_fanuc("END1\nM30\n")->first_error(), Code::BadLoop);
  // Overlapping ranges.
  EXPECT_EQ(run_fanuc("WHILE [1 EQ 1] DO1\nWHILE [1 EQ 1] DO2\nEND1\nEND2\nM30\n")->first_error(),
            Code::BadLoop);
  // Four deep (DO1 DO2 DO3 DO1 nested).
  EXPECT_EQ(
      run_fanuc("DO1\nDO2\nDO3\nWHILE [1 EQ 1] DO1\nEND1\nEND3\nEND2\nEND1\nM30\n")->first_error(),
      Code::BadLoop);
}

TEST(FanucEngine, GotoOutOfALoopIsAllowedIntoALoopIsNot) {
  auto out = run_fanuc(
      "#1 = 0\nWHILE [#1 LT 9] DO1\n#1 = #1 + 1\nIF [#1 EQ 3] GOTO 50\nEND1\n"
      "N50 G0 X#1\nM30\n");
  EXPECT_TRUE(out->ok) << out->first_error_text();
  expect_end(*out, {3, 0, 0});
  auto into = run_fanuc("GOTO 20\nWHILE [1 EQ 1] DO1\nN20 #1 = 1\nEND1\nM30\n");
  EXPECT_EQ(into->first_error(), Code::BadLoop);
  EXPECT_EQ(run_fanuc("GOTO 99\nM30\n")->first_error(), Code::UnknownBlockNumber);
}

TEST(FanucEngine, EndlessLoopStopsAtTheLimit) {
  InterpOptions o;
  o.max_loop_iterations = 100;
  auto r = run_fanuc("DO1\nEND1\nM30\n", o);
  EXPECT_EQ(r->first_error(), Code::TooManyIterations);
}

TEST(FanucEngine, MacroStatementMixedWithNcWordsIsAnError) {
  EXPECT_EQ(run_fanuc("G1 X1. #2 = 5\nM30\n")->first_error(), Code::MacroFormat);
  EXPECT_EQ(run_fanuc("#2 = [1 LT 2]\nM30\n")->first_error(), Code::MacroFormat);
  EXPECT_EQ(run_fanuc("IF [1 EQ 1] X1.\nM30\n")->first_error(), Code::MacroFormat);
}

TEST(FanucEngine, VariableWritesAndErrors) {
  EXPECT_EQ(run_fanuc("#0 = 1\nM30\n")->first_error(), Code::ReadOnlyParameter);
  EXPECT_EQ(run_fanuc("#50 = 1\nM30\n")->first_error(), Code::ReadOnlyParameter);
  EXPECT_EQ(run_fanuc("#1 = #50\nM30\n")->first_error(), Code::ParameterOutOfRange);
  auto alarm = run_fanuc("#3000 = 1 (ARGUMENT A MISSING)\nM30\n");
  EXPECT_EQ(alarm->first_error(), Code::MacroAlarm);
  EXPECT_EQ(alarm->first_error_text(), "alarm 3001: ARGUMENT A MISSING");
  auto stop = run_fanuc("#3006 = 1 (CHECK)\nM30\n");
  EXPECT_TRUE(stop->ok);
  EXPECT_TRUE(stop->has(Code::Message));
}

TEST(FanucEngine, G65ArgumentSpecificationI) {
  // Each letter to its variable; the macro moves to their sum weighted so
  // every one is seen: X = #1 + #2 + #3 + #7 + #4 + #5 + #6, Y = #24 #25 #26.
  auto r = run_fanuc(
      "G65 P9000 A1. B2. C3. D4. I5. J6. K7. X8. Y9. Z10.\nM30\n"
      "O9000\nG0 X[#1 + #2 + #3 + #7 + #4 + #5 + #6] Y[#24 * 100 + #25 * 10 + #26]\n"
      "IF [#8 NE #0] THEN #3000 = 1 (E PASSED)\nM99\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {28, 900, 0});
}

TEST(FanucEngine, G65SpecificationIIRepeatsIJK) {
  auto r = run_fanuc("G65 P9000 A1. I3. I4. D5.\nM30\nO9000\nG0 X#4 Y#7\nM99\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {3, 5, 0});  // D after the second I: the later word wins
}

TEST(FanucEngine, G65GetsNewLocalsM98SharesThem) {
  auto r = run_fanuc(
      "#1 = 7.\nG65 P9000\nG0 X#1\nM98 P9001\nG0 Y#1\nM30\n"
      "O9000\n#1 = 100.\nM99\nO9001\n#1 = 9.\nM99\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  ASSERT_EQ(r->ends().size(), 2u);
  EXPECT_NEAR(r->ends()[0].x, 7.0, 1e-9);
  EXPECT_NEAR(r->ends()[1].y, 9.0, 1e-9);
}

TEST(FanucEngine, G65WithAGCodeArgumentIsAnError) {
  EXPECT_EQ(run_fanuc("G65 P9000 G1\nM30\nO9000\nM99\n")->first_error(), Code::MacroFormat);
  EXPECT_EQ(run_fanuc("G65 A1.\nM30\n")->first_error(), Code::MissingWord);
}

TEST(FanucEngine, RecursionLimit) {
  auto r = run_fanuc("G65 P9000\nM30\nO9000\nG65 P9000\nM99\n");
  EXPECT_EQ(r->first_error(), Code::RecursionTooDeep);
}

TEST(FanucEngine, M98RepeatCountInTheHighDigits) {
  auto r = run_fanuc("#100 = 0\nM98 P30010\nG0 X#100\nM30\nO0010\n#100 = #100 + 1\nM99\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {3, 0, 0});
  auto eight = run_fanuc("M98 P30010\nM30\nO0010\nM99\n", {}, {"program_digits=8"});
  EXPECT_EQ(eight->first_error(), Code::UnknownSubroutine);
}

TEST(FanucEngine, M99PReturnsToABlockOfTheCaller) {
  auto r = run_fanuc("M98 P20\nG0 X1.\nN30 G0 Y1.\nM30\nO20\nM99 P30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  ASSERT_EQ(r->ends().size(), 1u);
  expect_end(*r, {0, 1, 0});
}

TEST(FanucEngine, M99InTheMainProgramEndsTheTraceWithAWarning) {
  auto r = run_fanuc("G0 X1.\nM99\nG0 X2.\n");
  EXPECT_TRUE(r->ok);
  expect_end(*r, {1, 0, 0});
  EXPECT_TRUE(r->has(Code::NoProgramEnd));
}

TEST(FanucEngine, SubprogramWithoutM99IsAnError) {
  EXPECT_EQ(run_fanuc("M98 P20\nM30\nO20\nG0 X1.\n")->first_error(), Code::UnclosedBlock);
}

// The messages at the end of the tape point at the last block read, its line
// and column (the engine keeps where it starts and cuts it again).
TEST(FanucEngine, TheEndOfTapeMessagesPointAtTheLastBlockRead) {
  const auto where = [](const dialect_test::Run& r, Code code) {
    for (const core::Diagnostic& d : r.diags.all()) {
      if (d.code == code) return std::pair{d.loc.line, d.loc.col};
    }
    return std::pair<std::uint32_t, std::uint32_t>{0, 0};
  };
  EXPECT_EQ(where(*run_fanuc("G0 X1.\n  N20 G1 X2. F100\n\n"), Code::NoProgramEnd),
            (std::pair<std::uint32_t, std::uint32_t>{2, 7}));  // at G1, after N20
  EXPECT_EQ(where(*run_fanuc("M98 P20\nM30\nO20\nG0 X1.\n G0 Y1.\n"), Code::UnclosedBlock),
            (std::pair<std::uint32_t, std::uint32_t>{5, 2}));
}

TEST(FanucEngine, G66CallsTheMacroAfterEachMove) {
  auto r = run_fanuc(
      "#100 = 0\nG66 P9000 Z-1.\nG0 X1.\nX2.\nG67\nX3.\nG0 Y#100\nM30\n"
      "O9000\n#100 = #100 + 1\nM99\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {3, 2, 0});
}

TEST(FanucEngine, SystemVariables) {
  auto r = run_fanuc(
      "G91 G1 X5. F250.\n#1 = #4003\n#2 = #4109\n#3 = #5001\n#4 = #4001\n"
      "G90 G0 X#1 Y#2 Z[#3 + #4]\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {91, 250, 6});
}

TEST(FanucEngine, WorkOffsetVariablesGoThroughG10) {
  auto r = run_fanuc("#5221 = 10.\nG54 G0 X0\n#1 = #5221\nG0 Y#1\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  ASSERT_EQ(r->ends().size(), 2u);
  EXPECT_NEAR(r->ends()[0].x, 10.0, 1e-9);  // machine = work 0 + offset 10
}

TEST(FanucEngine, AfterG80AxisWordsMoveInTheGroupOneMode) {
  auto r = run_fanuc("X5.\nG1 X6. F100.\nG81 X7. Z-1. R1.\nG80\nX8.\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  ASSERT_FALSE(r->all<canon::Feed>().empty());
  expect_end(*r, {8, 0, 1});
  EXPECT_NEAR(r->all<canon::Feed>().back().to.x, 8.0, 1e-9);  // G01 again after G80
}

TEST(FanucEngine, G04PIsMilliseconds) {
  auto r = run_fanuc("G04 P1500\nG04 X2.\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  const auto dwells = r->all<canon::Dwell>();
  ASSERT_EQ(dwells.size(), 2u);
  EXPECT_NEAR(dwells[0].s, 1.5, 1e-9);
  EXPECT_NEAR(dwells[1].s, 2.0, 1e-9);
}

TEST(FanucEngine, G10L2InG91Adds) {
  auto r = run_fanuc("G10 L2 P1 X10.\nG91 G10 L2 P1 X5.\nG90 G54 G0 X0\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {15, 0, 0});
}

TEST(FanucEngine, PolarAngleOnlyInG91KeepsTheRadius) {
  auto r = run_fanuc("G16\nG0 X10. Y0\nG91 Y90.\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {0, 10, 0});
}

TEST(FanucEngine, RotationTurnsPositions) {
  auto r = run_fanuc("G68 X0 Y0 R90.\nG0 X10. Y0\nG69\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {0, 10, 0});
}

TEST(FanucEngine, ScalingWithPAndPerAxisFactors) {
  auto p = run_fanuc("G51 X0 Y0 P2000\nG0 X3. Y4.\nG50\nM30\n");
  EXPECT_TRUE(p->ok) << p->first_error_text();
  expect_end(*p, {6, 8, 0});
  auto ij = run_fanuc("G51 X0 Y0 I2. J-1.\nG0 X3. Y4.\nM30\n");
  EXPECT_TRUE(ij->ok) << ij->first_error_text();
  expect_end(*ij, {6, -4, 0});
  EXPECT_EQ(run_fanuc("G51 X0 Y0 I2. J1.\nG0 X1. Y0\nG2 X-1. R1. F100.\nM30\n")->first_error(),
            Code::UnequalScaleArc);
}

TEST(FanucEngine, MirrorReversesArcs) {
  auto r = run_fanuc("G0 X0 Y0\nG51.1 X0\nG0 X1. Y0\nG3 X0 Y1. R1. F100.\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  const auto arcs = r->all<canon::Arc>();
  ASSERT_EQ(arcs.size(), 1u);
  EXPECT_NEAR(arcs[0].to.x, 0.0, 1e-9);
  EXPECT_LT(arcs[0].turn, 0);  // G03 mirrored in X is clockwise
}

TEST(FanucEngine, CodesNotImplementedSaySo) {
  // Cutter compensation in G12.1 mode (fanuc_polar_interp_test.cpp).
  EXPECT_EQ(run_fanuc("G0 X20. C0\nG12.1\nG1 G41 X10. F100.\nM30\n")->first_error(),
            Code::Unsupported);
}

TEST(FanucEngine, CycleRAndZAreKeptAsPositions) {
  // G85 without R takes the R of the running cycle; G91 K3 keeps R and Z.
  auto r = run_fanuc("G0 Z10.\nG99 G81 X0 Y0 Z-5. R2. F100.\nG85 X10.\nG91 X10. K2\nG80\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {30, 0, 2});
}

TEST(FanucEngine, ABlockWithoutPositionsInACycleDrillsNothing) {
  // M05 and G04 between the holes of a G81 (a posted job ends its holes
  // so): no hole at them, and G04's P is no dwell of the cycle's.
  auto r = run_fanuc(
      "G0 X0 Y0 Z10.\nS500 M3\nG98 G82 X5. Y5. Z-8. R2. P500 F60.\nG04 P2000\nX10.\nM05\n"
      "G80\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  EXPECT_EQ(r->all<canon::Hole>().size(), 2u);
  const auto dwells = r->all<canon::Dwell>();
  ASSERT_EQ(dwells.size(), 3u);  // the two holes' 0.5 s, the G04's 2 s between them
  EXPECT_NEAR(dwells[0].s, 0.5, 1e-9);
  EXPECT_NEAR(dwells[1].s, 2.0, 1e-9);
  EXPECT_NEAR(dwells[2].s, 0.5, 1e-9);
}

TEST(FanucEngine, G76FineBoringShiftsAwayFromTheWall) {
  auto r = run_fanuc("G0 X0 Y0 Z10.\nS500 M3\nG98 G76 X5. Y5. Z-8. R2. Q0.5 P200 F60.\nG80\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  const auto ends = r->ends();
  ASSERT_GE(ends.size(), 6u);
  EXPECT_NEAR(ends[3].z, -8.0, 1e-9);  // fed to the bottom
  EXPECT_NEAR(ends[4].x, 5.5, 1e-9);   // shifted Q in +X
  EXPECT_NEAR(ends[5].z, 10.0, 1e-9);  // G98: back to the initial level
  ASSERT_EQ(r->all<canon::Dwell>().size(), 1u);
  EXPECT_NEAR(r->all<canon::Dwell>()[0].s, 0.2, 1e-9);
}

TEST(FanucEngine, G87BackBoringFeedsUpFromTheBottom) {
  auto r = run_fanuc("G0 X0 Y0 Z10.\nS500 M3\nG98 G87 X5. Y5. Z-2. R-20. Q0.5 P0 F60.\nG80\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  const auto ends = r->ends();
  ASSERT_GE(ends.size(), 9u);
  EXPECT_NEAR(ends[2].x, 5.5, 1e-9);    // shifted in
  EXPECT_NEAR(ends[3].z, -20.0, 1e-9);  // rapid down to R, the bottom
  EXPECT_NEAR(ends[5].z, -2.0, 1e-9);   // fed up to Z
  EXPECT_NEAR(ends[7].z, 10.0, 1e-9);   // out at the initial level
  EXPECT_EQ(run_fanuc("G99 G87 X5. Y5. Z-2. R-20. Q0.5 F60.\nM30\n")->first_error(),
            Code::NotAllowedInMode);
}

// A file name of this test process: ctest runs the tests in parallel, and
// one test must not truncate the file another is reading.
std::string scratch(const std::string& name) {
  return ::testing::TempDir() + "usina_fanuc_" + std::to_string(::getpid()) + "_" + name;
}

// A file the test writes and removes when it ends (1,282 were left in /tmp).
class ScratchFile {
 public:
  explicit ScratchFile(std::string path) : path_(std::move(path)) {}

  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;

  ~ScratchFile() { std::remove(path_.c_str()); }

  operator const std::string&() const { return path_; }  // NOLINT: read as its path

  const char* c_str() const { return path_.c_str(); }

 private:
  std::string path_;
};

std::unique_ptr<ScratchFile> offsets_file() {
  auto path = std::make_unique<ScratchFile>(scratch("offsets.toml"));
  std::FILE* f = std::fopen(path->c_str(), "w");
  std::fputs(
      "# offset page\n[H]\n1 = [10.5, -0.5]\n2 = 3.0\n[D]\n11 = [5.0, -0.01]\n"
      "12 = [-2.0, 0]\n",
      f);
  std::fclose(f);
  return path;
}

TEST(FanucEngine, G43AndG44TakeHRegistersFromTheOffsetFile) {
  const auto offsets = offsets_file();
  const std::string& o = *offsets;
  // #5083: the tool length offset now applied on Z (the trace shows the tip).
  auto r = run_fanuc_offsets("G43 H1\nG0 X#5083\nG44 H2\nG0 X#5083\nG49\nG0 X#5083\nM30\n", o);
  EXPECT_TRUE(r->ok) << r->first_error_text();
  ASSERT_EQ(r->ends().size(), 3u);
  EXPECT_NEAR(r->ends()[0].x, 10.0, 1e-9);  // geometry + wear
  EXPECT_NEAR(r->ends()[1].x, -3.0, 1e-9);  // G44 subtracts
  EXPECT_NEAR(r->ends()[2].x, 0.0, 1e-9);
}

TEST(FanucEngine, G43WithAMoveAndHSelectedBefore) {
  const auto offsets = offsets_file();
  const std::string& o = *offsets;
  auto r = run_fanuc_offsets("H1\nG43 Z50.\nG0 X#5083\nG43 H2 Z20.\nM30\n", o);
  EXPECT_TRUE(r->ok) << r->first_error_text();
  ASSERT_EQ(r->ends().size(), 3u);
  EXPECT_NEAR(r->ends()[0].z, 50.0, 1e-9);
  EXPECT_NEAR(r->ends()[1].x, 10.0, 1e-9);
  EXPECT_NEAR(r->ends()[2].z, 20.0, 1e-9);
}

TEST(FanucEngine, OffsetRegistersAsVariablesAndG10L10ToL13) {
  const auto offsets = offsets_file();
  const std::string& o = *offsets;
  auto r = run_fanuc_offsets(
      "G0 X#2201 Y#2001 Z#2611\nG10 L10 P3 R7.\nG91 G10 L11 P3 R1.\nG90\n"
      "G0 X[#2203 + #2003]\nM30\n",
      o);
  EXPECT_TRUE(r->ok) << r->first_error_text();
  ASSERT_EQ(r->ends().size(), 2u);
  EXPECT_NEAR(r->ends()[0].x, 10.5, 1e-9);
  EXPECT_NEAR(r->ends()[0].y, -0.5, 1e-9);
  EXPECT_NEAR(r->ends()[0].z, 5.0, 1e-9);
  EXPECT_NEAR(r->ends()[1].x, 8.0, 1e-9);
}

TEST(FanucEngine, CutterCompTakesTheRadiusOfRegisterD) {
  const auto offsets = offsets_file();
  const std::string& o = *offsets;
  auto r =
      run_fanuc_offsets("G0 X0 Y-20.\nG41 D11 G1 X0 Y-10. F100.\nY10.\nG40 G0 X-20.\nM30\n", o);
  EXPECT_TRUE(r->ok) << r->first_error_text();
  ASSERT_GE(r->ends().size(), 3u);
  EXPECT_NEAR(r->ends()[2].x, -4.99, 1e-6);  // G41 on +Y travel: tool to the left (-X)
}

TEST(FanucEngine, OffsetFileErrors) {
  EXPECT_EQ(
      run_fanuc_offsets("M30\n", ::testing::TempDir() + "no_such_offsets.toml")->first_error(),
      Code::FileNotFound);
  const ScratchFile bad(scratch("bad_offsets.toml"));
  std::FILE* f = std::fopen(bad.c_str(), "w");
  std::fputs("[H]\n1 = [x, 2]\n", f);
  std::fclose(f);
  EXPECT_EQ(run_fanuc_offsets("M30\n", bad)->first_error(), Code::BadToolTable);
  auto missing = run_fanuc("G43 H5\nM30\n");
  EXPECT_TRUE(missing->ok);
  EXPECT_TRUE(missing->has(Code::UnknownRegister));  // warned: taken as 0
}

TEST(FanucEngine, MirrorSwapsTheCompensationSide) {
  const auto offsets = offsets_file();
  const std::string& o = *offsets;
  auto r = run_fanuc_offsets(
      "G51.1 X0\nG0 X0 Y-20.\nG41 D11 G1 X0 Y-10. F100.\nY10.\nG40 G0 X20.\nM30\n", o);
  EXPECT_TRUE(r->ok) << r->first_error_text();
  ASSERT_GE(r->ends().size(), 3u);
  EXPECT_NEAR(r->ends()[2].x, 4.99, 1e-6);  // G41 mirrored is G42: the tool on +X
}

std::string program_text(const std::string& name) {
  std::ifstream in(std::string(USINA_TEST_DIR) + "/programs/fanuc/" + name);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(FanucEngine, TheG65PocketRunsAndAlarmsWithoutItsDiameter) {
  const std::string text = program_text("o1002_g65_circular_pocket.nc");
  ASSERT_FALSE(text.empty());
  EXPECT_TRUE(run_fanuc(text)->ok);
  // Without D the macro's guard raises alarm 3001 (docs/fanuc.md §11).
  auto r = run_fanuc(std::regex_replace(text, std::regex(" D1[06]\\."), ""));
  EXPECT_EQ(r->first_error(), Code::MacroAlarm);
  EXPECT_EQ(r->first_error_text(), "alarm 3001: DIAMETER D MISSING");
}

TEST(FanucEngine, ACharacterThatIsNoWordIsAnErrorAtItsColumn) {
  auto r = run_fanuc("G0 X1. $\nM30\n");
  EXPECT_EQ(r->first_error(), Code::UnexpectedCharacter);
  for (const core::Diagnostic& d : r->diags.all()) {
    if (d.code == Code::UnexpectedCharacter) {
      EXPECT_EQ(d.loc.col, 8u);  // at the '$'
    }
  }
}

}  // namespace
}  // namespace usina::gcode::fanuc_test
