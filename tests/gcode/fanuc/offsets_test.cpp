// The fanuc dialect's offsets and settings (docs/fanuc.md §7): G54.1
// additional work systems, the external work offset, G10 L50 parameter
// input, G22 stored stroke check 2, the persistent variables and the
// columns of errors in rewritten blocks; each rule and each error path.
#include <string>

#include <gtest/gtest.h>

#include "fanuc_test_support.hpp"

namespace usina::gcode::fanuc_test {
namespace {

using core::Code;
using core::Vec3;

const core::Diagnostic* first_error(const Run& r) {
  for (const core::Diagnostic& d : r.diags.all())
    if (d.severity == core::Severity::Error) return &d;
  return nullptr;
}

// A run that keeps its runner: parameters before, persistent variables after.
struct Kept {
  std::unique_ptr<Run> run = std::make_unique<Run>();
  std::unique_ptr<ProgramRunner> runner;
};

Kept run_kept(const std::string& dialect, const std::string& text,
              const std::vector<std::pair<int, double>>& parameters = {}) {
  Kept k;
  const std::uint32_t id = k.run->sources.add(core::SourceFile::from_string("test.nc", text));
  const Dialect* d = find_dialect(dialect);
  OptionValues values = default_options(*d);
  k.runner =
      d->make_runner(RunContext{k.run->sources, {}, std::move(values), k.run->path, k.run->diags});
  for (const auto& [n, v] : parameters)
    k.runner->set_parameter(n, v);
  k.run->ok = k.runner->run(id);
  return k;
}

// --- G54.1 P1..P48 --------------------------------------------------------

// Programs that must end at a point: each row names the rule it checks.
struct EndCase {
  const char* rule;
  const char* program;
  core::Vec3 end;
};

const EndCase kEndCases[] = {
    {"G10L20SetsAnAdditionalSystemAndG541SelectsIt",
     "G10 L20 P1 X10. Y20.\nG90 G54.1 P1 G0 X0 Y0\nM30\n",
     {10, 20, 0}},
    {"G54PIsTheSameAsG541P", "G10 L20 P48 X-3.\nG54 P48 G0 X1.\nM30\n", {-2, 0, 0}},
    {"G541WithoutPIsP1", "G10 L20 P1 Z-5.\nG54.1 G0 Z0\nM30\n", {0, 0, -5}},
    {"G10L20InG91Adds",
     "G10 L20 P2 X10.\nG91 G10 L20 P2 X5.\nG90 G54.1 P2 G0 X0\nM30\n",
     {15, 0, 0}},
    {"ChangingTheActiveSystemTakesEffect",
     "G54.1 P3 G0 X0\nG10 L20 P3 X7.\nG0 X0\nM30\n",
     {7, 0, 0}},
    {"WritingTheActiveSystemsVariableTakesEffect",
     "G54.1 P5 G0 X0\n#7081 = 3.\nG0 X0\nM30\n",
     {3, 0, 0}},
    {"ExternalOffsetShiftsTheAdditionalSystems",
     "G10 L20 P1 X1.\nG54.1 P1\nG10 L2 P0 X5.\nG0 X0\nM30\n",
     {6, 0, 0}},
    {"WorkOffsetVariableKeepsTheExternalOffset",
     "#5201 = 2.\n#5221 = 10.\nG54 G0 X0\n#1 = #5221\nG0 Y#1\nM30\n",
     {12, 10, 0}},
};

TEST(FanucOffsets, EachProgramEndsWhereItsRuleSays) {
  for (const EndCase& c : kEndCases) {
    SCOPED_TRACE(c.rule);
    auto r = run_fanuc(c.program);
    EXPECT_TRUE(r->ok) << r->first_error_text();
    expect_end(*r, c.end);
  }
}

TEST(FanucOffsets, PInAG54BlockWithM98IsTheProgram) {
  auto r = run_fanuc("%\nO0001\nG10 L20 P1 X9.\nG54 M98 P2\nG0 X0\nM30\nO0002\nG0 Y1.\nM99\n%\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {0, 1, 0});  // G54, not G54.1 P2 (nor P1)
}

TEST(FanucOffsets, VariablesReadAndWriteTheAdditionalSystems) {
  // #7021 is P2's X, #7003 P1's Z; #4130 the active P; #4014 group 14.
  auto r = run_fanuc(
      "#7021 = 4.\nG10 L20 P1 Z2.\nG54.1 P2 G0 X0\n#1 = #4130\n#2 = #7003\n#3 = #4014\n"
      "G54 G0 X#1 Y#2 Z#3\n#4 = #4130\nG0 X#4\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  ASSERT_EQ(r->ends().size(), 3u);
  EXPECT_NEAR(r->ends()[0].x, 4.0, 1e-9);
  EXPECT_NEAR(r->ends()[1].x, 2.0, 1e-9);   // #4130 = 2
  EXPECT_NEAR(r->ends()[1].y, 2.0, 1e-9);   // #7003 = 2
  EXPECT_NEAR(r->ends()[1].z, 54.1, 1e-9);  // G54.1 was active
  EXPECT_NEAR(r->ends()[2].x, 0.0, 1e-9);   // back in G54: #4130 = 0
}

TEST(FanucOffsets, AdditionalSystemErrors) {
  EXPECT_EQ(run_fanuc("G54.1 P49\nM30\n")->first_error(), Code::BadWordValue);
  EXPECT_EQ(run_fanuc("G54.1 P0\nM30\n")->first_error(), Code::BadWordValue);
  EXPECT_EQ(run_fanuc("G10 L20 P0 X1.\nM30\n")->first_error(), Code::BadWordValue);
  EXPECT_EQ(run_fanuc("G10 L20 P49 X1.\nM30\n")->first_error(), Code::BadWordValue);
  EXPECT_EQ(run_fanuc("G10 L20 X1.\nM30\n")->first_error(), Code::BadWordValue);
  // #7961 is past P48; #7010 is an axis usina does not have.
  EXPECT_EQ(run_fanuc("#1 = #7961\nM30\n")->first_error(), Code::ParameterOutOfRange);
  EXPECT_EQ(run_fanuc("#1 = #7010\nM30\n")->first_error(), Code::ParameterOutOfRange);
}

// --- EXT: G10 L2 P0, #5201- -------------------------------------------------

TEST(FanucOffsets, ExternalOffsetShiftsEveryWorkSystem) {
  auto r = run_fanuc(
      "G10 L2 P0 X5.\nG10 L2 P1 X10.\nG10 L2 P2 Y1.\nG54 G0 X0\n#1 = #5221\n#2 = #5201\n"
      "G55 G0 X0 Y0\nG54 G0 X#1 Y#2\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  ASSERT_EQ(r->ends().size(), 3u);
  EXPECT_NEAR(r->ends()[0].x, 15.0, 1e-9);  // EXT 5 + G54 10
  EXPECT_NEAR(r->ends()[1].x, 5.0, 1e-9);   // EXT + G55 (0, 1)
  EXPECT_NEAR(r->ends()[1].y, 1.0, 1e-9);
  expect_end(*r, {25, 5, 0});  // #5221 reads 10 (without EXT), #5201 reads 5
}

TEST(FanucOffsets, ExternalOffsetInG91AddsAndMovesTheActiveSystem) {
  auto r = run_fanuc("G10 L2 P0 X5.\nG91 G10 L2 P0 X2.\nG90 G0 X0\n#5202 = 3.\nG0 X0 Y0\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  ASSERT_EQ(r->ends().size(), 2u);
  EXPECT_NEAR(r->ends()[0].x, 7.0, 1e-9);
  expect_end(*r, {7, 3, 0});
}

TEST(FanucOffsets, ExternalOffsetFromTheParameterFile) {
  auto k = run_kept("fanuc", "G0 X0\nM30\n", {{5201, 4.0}, {5221, 1.0}});
  EXPECT_TRUE(k.run->ok) << k.run->first_error_text();
  expect_end(*k.run, {5, 0, 0});
}

TEST(FanucOffsets, G10L2AndOtherLErrors) {
  EXPECT_EQ(run_fanuc("G10 L2 P7 X1.\nM30\n")->first_error(), Code::BadWordValue);
  EXPECT_EQ(run_fanuc("G10 L3 P1 X1.\nM30\n")->first_error(), Code::BadWordValue);
}

// --- G10 L50 ... G11 ---------------------------------------------------------

std::vector<double> traverse_z(const Run& r) {
  std::vector<double> z;
  for (const auto& t : r.all<canon::Traverse>())
    z.push_back(t.to.z);
  return z;
}

TEST(FanucOffsets, Parameter5115IsTheG83Clearance) {
  auto r = run_fanuc("G10 L50\nN5115 R500\nG11\nG0 Z10.\nG83 X0 Y0 Z-3. R0 Q1. F100.\nG80\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  // After the first peck to -1: out to R (0), back down to -1 + 0.5.
  // Traverses: to Z10, over the hole, down to R, then the pecks.
  const auto z = traverse_z(*r);
  ASSERT_GE(z.size(), 5u);
  EXPECT_NEAR(z[3], 0.0, 1e-9);
  EXPECT_NEAR(z[4], -0.5, 1e-9);
}

TEST(FanucOffsets, Parameter5114IsTheG73BackOff) {
  auto r = run_fanuc("G10 L50\nN5114 R2.\nG11\nG0 Z10.\nG73 X0 Y0 Z-6. R0 Q3. F100.\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  const auto z = traverse_z(*r);
  ASSERT_GE(z.size(), 4u);
  EXPECT_NEAR(z[3], -1.0, 1e-9);  // peck to -3, back off 2 mm
}

TEST(FanucOffsets, Parameter3401Bit0IsTheDecimalPointRule) {
  auto standard = run_fanuc("G10 L50\nN3401 R0\nG11\nG0 X1000\nM30\n");
  EXPECT_TRUE(standard->ok) << standard->first_error_text();
  expect_end(*standard, {1, 0, 0});
  auto calculator =
      run_fanuc("G10 L50\nN3401 R1\nG11\nG0 X1000\nM30\n", {}, {"decimal_point=fanuc"});
  EXPECT_TRUE(calculator->ok) << calculator->first_error_text();
  expect_end(*calculator, {1000, 0, 0});
}

TEST(FanucOffsets, ParametersUsinaDoesNotModelAreWarned) {
  auto r = run_fanuc("G10 L50\nN1234 P1 R5\nN3401 R3\nG11\nG0 X1.\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  int warnings = 0;
  for (const core::Diagnostic& d : r->diags.all())
    warnings += d.code == Code::ParameterNotModeled ? 1 : 0;
  EXPECT_EQ(warnings, 2);
  EXPECT_EQ(r->diags.all()[0].loc.line, 2u);
  EXPECT_EQ(r->diags.all()[0].loc.col, 1u);  // at N1234
  expect_end(*r, {1, 0, 0});
}

TEST(FanucOffsets, BadParameterBlocks) {
  const char* cases[][2] = {
      {"G10 L50\nN5115\nG11\nM30\n", "MissingWord"},
      {"G10 L50\nR5\nG11\nM30\n", "MissingWord"},
      {"G10 L50\nN5115 X1 R5\nG11\nM30\n", "NotAllowedInMode"},
      {"G10 L50\n#1 = 5\nG11\nM30\n", "NotAllowedInMode"},
      {"G10 L50\nN5114 R-1\nG11\nM30\n", "BadWordValue"},
      {"G10 L50\nN5114 P1 R5\nG11\nM30\n", "BadWordValue"},
      {"G10 L50\nN3401 R1.5\nG11\nM30\n", "BadWordValue"},
      {"G10 L50\nN1300 R256\nG11\nM30\n", "BadWordValue"},
      {"G10 L50 X1.\nG11\nM30\n", "NotAllowedInMode"},
      {"G10 L50\nN5115 R5\nG11 X1.\nM30\n", "NotAllowedInMode"},
      {"G10 L50\nN5115 R5\nM30\n", "NotAllowedInMode"},
      {"G10 L50\nN5115 R5\n", "UnclosedBlock"},
  };
  const std::pair<const char*, Code> codes[] = {{"MissingWord", Code::MissingWord},
                                                {"NotAllowedInMode", Code::NotAllowedInMode},
                                                {"BadWordValue", Code::BadWordValue},
                                                {"UnclosedBlock", Code::UnclosedBlock}};
  for (const auto& c : cases) {
    Code want = Code::Message;
    for (const auto& [name, code] : codes)
      if (std::string(name) == c[1]) want = code;
    EXPECT_EQ(run_fanuc(c[0])->first_error(), want) << c[0];
  }
}

// --- G22 / G23 ------------------------------------------------------------------

constexpr const char* kBox = "G22 X10. Y10. Z10. I-10. J-10. K-10.\n";

TEST(FanucOffsets, G22StopsAtTheBlockThatEntersTheArea) {
  auto r = run_fanuc(std::string("G0 Z50.\n") + kBox + "G0 X0 Y0\nG1 Z0 F100.\nG0 X50.\nM30\n");
  EXPECT_FALSE(r->ok);
  const core::Diagnostic* e = first_error(*r);
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->code, Code::ForbiddenArea);
  EXPECT_EQ(e->loc.line, 4u);
  EXPECT_NE(e->message.find("OT0503 -Z"), std::string::npos) << e->message;
  EXPECT_TRUE(r->all<canon::Feed>().empty());  // the move into the area is not made
  expect_end(*r, {0, 0, 50});
}

TEST(FanucOffsets, G22ChecksTheWholeSegmentNotOnlyItsEnd) {
  auto through = run_fanuc(std::string("G0 X-20. Y0 Z0\n") + kBox + "G0 X20.\nM30\n");
  EXPECT_EQ(through->first_error(), Code::ForbiddenArea);
  EXPECT_NE(through->first_error_text().find("OT0502 +X"), std::string::npos);
  auto beside = run_fanuc(std::string("G0 X-20. Y10. Z0\n") + kBox + "G0 X20.\nM30\n");
  EXPECT_TRUE(beside->ok) << beside->first_error_text();  // along the boundary
}

TEST(FanucOffsets, G22ChecksArcsAlongTheirWay) {
  // A half circle of radius 15 about the origin from (15, 0) to (-15, 0)
  // misses the box [-10, 10]; its chord would cross it.
  auto around = run_fanuc(std::string("G0 X15. Y0 Z0\n") + kBox + "G3 X-15. Y0 R15. F100.\nM30\n");
  EXPECT_TRUE(around->ok) << around->first_error_text();
  // About (16, 0) from (12, -5) to (12, 5): the chord stays at X12, the
  // clockwise arc reaches X9.6, inside the box; counter-clockwise it
  // goes round the far side.
  auto bulge =
      run_fanuc(std::string("G0 X12. Y-5. Z0\n") + kBox + "G2 X12. Y5. I4. J5. F100.\nM30\n");
  EXPECT_EQ(bulge->first_error(), Code::ForbiddenArea);
  EXPECT_NE(bulge->first_error_text().find("OT0503 -X"), std::string::npos);
  auto far =
      run_fanuc(std::string("G0 X12. Y-5. Z0\n") + kBox + "G3 X12. Y5. I4. J5. F100.\nM30\n");
  EXPECT_TRUE(far->ok) << far->first_error_text();
}

TEST(FanucOffsets, G23DisarmsTheArea) {
  auto r = run_fanuc(std::string("G0 Z50.\n") + kBox + "G23\nG1 Z0 F100.\n#1 = #4004\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {0, 0, 0});
  auto on = run_fanuc(std::string("G0 Z50.\n") + kBox + "#1 = #4004\nG0 X#1\nM30\n");
  EXPECT_TRUE(on->ok) << on->first_error_text();
  expect_end(*on, {22, 0, 50});
}

TEST(FanucOffsets, OutsideForbiddenByOptionOrParameter1300) {
  const std::string box = "G22 X100. Y100. Z100. I-100. J-100. K-100.\n";
  auto option = run_fanuc(box + "G0 X50.\nG0 X150.\nM30\n", {}, {"stroke_area=outside"});
  EXPECT_EQ(option->first_error(), Code::ForbiddenArea);
  EXPECT_NE(option->first_error_text().find("OT0502 +X"), std::string::npos);
  expect_end(*option, {50, 0, 0});
  auto parameter = run_fanuc("G10 L50\nN1300 R1\nG11\n" + box + "G0 Y-150.\nM30\n");
  EXPECT_EQ(parameter->first_error(), Code::ForbiddenArea);
  EXPECT_NE(parameter->first_error_text().find("OT0503 -Y"), std::string::npos);
}

TEST(FanucOffsets, G22Errors) {
  // Armed around the tool; a corner missing; G22 with G23.
  EXPECT_EQ(run_fanuc(std::string(kBox) + "M30\n")->first_error(), Code::ForbiddenArea);
  EXPECT_EQ(run_fanuc("G22 X1. Y1. Z1. I0 J0\nM30\n")->first_error(), Code::MissingWord);
  EXPECT_EQ(run_fanuc("G22 G23 X1. Y1. Z1. I0 J0 K0\nM30\n")->first_error(),
            Code::ModalGroupConflict);
}

// --- persistent variables ---------------------------------------------------------

TEST(FanucOffsets, PersistentVariablesAreTheSetOnesOf500To999) {
  auto k = run_kept("fanuc", "#500 = 1.5\n#999 = -2\n#100 = 7\n#501 = #0\n#3000 = 1 (STOP)\n",
                    {{502, 3.0}});
  EXPECT_FALSE(k.run->ok);  // the alarm: the variables set before it are kept
  const auto vars = k.runner->persistent_variables();
  ASSERT_TRUE(vars.has_value());
  const std::vector<VarFileEntry> want = {{500, 1.5}, {502, 3.0}, {999, -2.0}};
  EXPECT_EQ(*vars, want);
}

TEST(FanucOffsets, Rs274ngcKeepsLinuxCncsRequiredParameters) {
  auto k = run_kept("rs274ngc", "G10 L2 P1 X7\nM2\n", {{31, 2.0}});
  EXPECT_TRUE(k.run->ok) << k.run->first_error_text();
  const auto vars = k.runner->persistent_variables();
  ASSERT_TRUE(vars.has_value());
  auto find = [&](int n) -> const VarFileEntry* {
    for (const VarFileEntry& e : *vars)
      if (e.number == n) return &e;
    return nullptr;
  };
  ASSERT_NE(find(5221), nullptr);
  EXPECT_DOUBLE_EQ(find(5221)->value, 7.0);
  ASSERT_NE(find(31), nullptr);  // a number the parameter file had
  for (int n : {5161, 5169, 5189, 5210, 5220, 5230, 5381, 5390})
    EXPECT_NE(find(n), nullptr) << n;
  EXPECT_EQ(find(5391), nullptr);
  EXPECT_EQ(vars->size(), 1u + 9 + 9 + 11 + 9 * 10);
}

TEST(FanucOffsets, DialectsWithoutPersistentVariablesSaySo) {
  auto k = run_kept("grbl", "G0 X1\n");
  EXPECT_FALSE(k.runner->persistent_variables().has_value());
}

// --- columns of errors in rewritten blocks ------------------------------------------

TEST(FanucOffsets, InterpreterErrorsPointAtTheFanucWord) {
  // G7.5 is no code: the interpreter finds it in the block the front end
  // wrote; the error points at its column in the program (after a comment).
  auto r = run_fanuc("G0 (A (B)) X1. G7.5\nM30\n");
  const core::Diagnostic* e = first_error(*r);
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->loc.line, 1u);
  EXPECT_EQ(e->loc.col, 16u);
  auto plain = run_fanuc("N10 G0 X1. G7.5\nM30\n");
  ASSERT_NE(first_error(*plain), nullptr);
  EXPECT_EQ(first_error(*plain)->loc.col, 12u);
}

}  // namespace
}  // namespace usina::gcode::fanuc_test
