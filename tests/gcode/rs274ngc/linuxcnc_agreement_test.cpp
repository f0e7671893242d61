// Differences from LinuxCNC's stand-alone interpreter (Debian's rs274) that
// the differential fuzzer found (tests/differential/fuzz_differential.py),
// each fixed and kept here as the rule it broke.
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "canon/toolpath.hpp"
#include "core/source.hpp"
#include "core/units.hpp"
#include "gcode/interp/interpreter.hpp"
#include "gcode/tool_table.hpp"
#include "support/dialect_run.hpp"
#include "support/interp_run.hpp"

namespace usina::gcode {
namespace {

using core::Vec3;

using namespace interp_test;  // NOLINT(google-build-using-namespace): the shared run

constexpr double kPi = 3.14159265358979323846;

// saicanon.cc STRAIGHT_PROBE backs the probe off 0.01 in under G20 and
// 0.254 mm under G21: the same distance, not 0.01 of the program's unit.
TEST(LinuxcncAgreement, ProbeStopsAQuarterMillimetreShortInEveryUnit) {
  auto r = run("G21 F100\nG38.2 Z-10\nG0 X0\nM2\n");
  ASSERT_TRUE(r->ok) << r->first_error();
  const std::vector<Vec3> ends = r->ends();
  ASSERT_EQ(ends.size(), 2u);
  EXPECT_NEAR(ends[1].z, -10.0 + 0.254, kTol);
  EXPECT_NEAR(r->param(5063), -10.0 + 0.254, kTol);
}

TEST(LinuxcncAgreement, ProbeBackOffUnderG20IsOneHundredthOfAnInch) {
  auto r = run("G20 F10\nG38.2 Z-1\nG0 X0\nM2\n");
  ASSERT_TRUE(r->ok) << r->first_error();
  EXPECT_NEAR(r->ends()[1].z, (-1.0 + 0.01) * core::kMmPerInch, kTol);
  EXPECT_NEAR(r->param(5063), -0.99, kTol);
}

// interp_execute.cc computes sin((x * M_PIl) / 180.0): the angle and the
// sine in long double. Rounded to double, SIN[30] is exactly 0.5 and
// TAN[45] exactly 1, and SIN[180] is -5e-20, where double arithmetic gives
// 0.49999999999999994, 0.9999999999999999 and +1.2e-16. FIX, ROUND,
// comparisons and LN then decide otherwise (rs274 gives these positions).
TEST(LinuxcncAgreement, TrigonometryInLongDoubleAsLinuxcnc) {
  auto r =
      run("G21\n"
          "G0 X[FIX[SIN[30]*10]] Y[FIX[COS[60]*10]] Z[FIX[TAN[45]*10]]\n"
          "G0 X[FIX[ASIN[0.5]]] Y[FIX[ACOS[0.5]]] Z[FIX[ATAN[1]/[1]]]\n"
          "G0 X[[SIN[180] LT 0] + 10*[COS[90] LT 0]] Y[FIX[ATAN[1]/[SQRT[3]]]]\n"
          "M2\n");
  ASSERT_TRUE(r->ok) << r->first_error();
  const std::vector<Vec3> ends = r->ends();
  ASSERT_EQ(ends.size(), 3u);
  EXPECT_EQ(ends[0], (Vec3{5, 5, 10}));
  EXPECT_EQ(ends[1], (Vec3{30, 60, 45}));
  EXPECT_EQ(ends[2], (Vec3{11, 30, 45}));
}

TEST(LinuxcncAgreement, LogarithmOfTheSineOfAHalfTurnIsAnError) {
  auto r = run("G21\n#1 = LN[SIN[180]]\nM2\n");
  EXPECT_FALSE(r->ok);
  EXPECT_EQ(r->diags.error_count(), 1);
}

// interp_convert.cc convert_coordinate_system: selecting the system already
// in use does nothing ("continuing to use same coordinate system"), so a new
// value written to its parameters takes effect only when the system is
// selected again after another one.
TEST(LinuxcncAgreement, SelectingTheActiveSystemAgainKeepsItsOffsets) {
  // The rs274ngc dialect's rule (DialectRules), so run by the dialect.
  auto r = dialect_test::run_in("rs274ngc", "G21\n#5223 = 10\nG54\nG0 Z1\nG55\nG54\nG0 Z2\nM2\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const std::vector<Vec3> ends = r->ends();
  ASSERT_EQ(ends.size(), 2u);
  EXPECT_NEAR(ends[0].z, 1.0, kTol);
  EXPECT_NEAR(ends[1].z, 12.0, kTol);
}

// Issue 12: "a canned cycle started with the tool below the R plane does not
// first traverse Z up to R". The tool was below R after a G99 cycle, a G80
// and a new cycle with a higher R: a G80 alone on its block was dropped, so
// the old cycle went on (its initial level Z10 above the new R5: no rise)
// and the tool went straight to the next hole through the part. LinuxCNC
// (convert_motion) ends the cycle at G80; the next one starts at Z1, below
// R5, and rises straight up first (interp_cycles.cc: "if we're below the R
// plane, rapid straight up to the R plane").
TEST(LinuxcncAgreement, CycleAfterG80RisesStraightToRFromBelowIt) {
  auto r = run("G21 F100\nG0 Z10\nG99 G81 X1 Z-5 R1\nG80\nG81 X2 Z-5 R5\nG80\nM2\n");
  ASSERT_TRUE(r->ok) << r->first_error();
  const std::vector<Vec3> expected{{0, 0, 10}, {1, 0, 10}, {1, 0, 1},  {1, 0, -5}, {1, 0, 1},
                                   {1, 0, 5},  {2, 0, 5},  {2, 0, -5}, {2, 0, 5}};
  EXPECT_EQ(r->ends(), expected);
}

// Once, whatever L is; in every plane.
TEST(LinuxcncAgreement, CycleAfterG80RisesOnceWithRepeatsInEveryPlane) {
  auto r =
      run("G21 F100\nG18 G0 Y10\nG99 G81 X1 Y-5 R1\nG80\nG81 X2 Y-5 R5 L2\nG80\n"
          "G19 G0 X10\nG99 G81 Y1 X-5 R1\nG80\nG81 Y2 X-5 R5 L2\nM2\n");
  ASSERT_TRUE(r->ok) << r->first_error();
  const std::vector<Vec3> ends = r->ends();
  ASSERT_EQ(ends.size(), 24u);  // as rs274 traces it
  // G18: from Y1 over X1 straight up to Y5, then over to X2 and down.
  EXPECT_EQ(ends[5], (Vec3{1, 5, 0}));
  EXPECT_EQ(ends[6], (Vec3{2, 5, 0}));
  EXPECT_EQ(ends[9], (Vec3{2, 5, 0}));  // the repeat: no second rise
  EXPECT_EQ(ends[10], (Vec3{2, -5, 0}));
  // G19: from X1 straight up to X5.
  EXPECT_EQ(ends[17], (Vec3{5, 1, 0}));
  EXPECT_EQ(ends[18], (Vec3{5, 2, 0}));
}

TEST(LinuxcncAgreement, AxisWordsAfterG80AreAnError) {
  auto r = run("G21 F100\nG81 X1 Z-5 R1\nG80\nX5\nM2\n");
  EXPECT_FALSE(r->ok);
  ASSERT_FALSE(r->diags.all().empty());
  EXPECT_EQ(r->diags.all()[0].code, core::Code::AxisWordsConflict);
  EXPECT_EQ(r->diags.all()[0].loc.line, 4u);
}

TEST(LinuxcncAgreement, ACycleAfterG80NeedsItsRAgain) {
  auto r = run("G21 F100\nG81 X1 Z-5 R1\nG80\nG81 X5\nM2\n");
  EXPECT_FALSE(r->ok);
  ASSERT_FALSE(r->diags.all().empty());
  EXPECT_EQ(r->diags.all()[0].code, core::Code::MissingWord);
}

// LinuxCNC computes a cycle in inches under G20; usina in mm. An R the
// program computes, [-7.192 + 7.57577] = 0.38377000000000017, lies a few ulps
// above the initial level Z0.38377, so rs274 rises straight up to it before
// it moves over (its trace); rounded to 15 digits it was the level itself.
TEST(LinuxcncAgreement, AnInchRComputedAnUlpAboveTheInitialLevelIsAbove) {
  auto r =
      run("G20 F10\nG0 X0 Y0 Z0.38377\nG99 G81 X1 Z-0.2 R0.19616\nX2 R[-7.192 + 7.57577]\nM2\n");
  ASSERT_TRUE(r->ok) << r->first_error();
  const std::vector<Vec3> ends = r->ends();
  ASSERT_EQ(ends.size(), 9u);
  EXPECT_NEAR(ends[5].x, 25.4, 1e-9);  // up at the first hole
  EXPECT_NEAR(ends[5].z, 0.38377 * core::kMmPerInch, 1e-6);
  EXPECT_NEAR(ends[6].x, 50.8, 1e-9);  // then over to the second
}

// LinuxCNC reads (and evaluates) every O-word line execution reaches: an
// elseif after the branch that ran is evaluated before the skip to endif,
// so its division by zero is an error there too (rs274: "Attempt to divide
// by zero" at the elseif).
TEST(LinuxcncAgreement, ElseifAfterTheBranchThatRanIsStillEvaluated) {
  auto r =
      run("G21\n#1 = 0\no102 if [0]\nG0 X1\no102 elseif [1]\nG0 X2\no102 elseif [8/#1]\n"
          "G0 X4\no102 endif\nG0 X3\nM2\n");
  EXPECT_FALSE(r->ok);
  ASSERT_FALSE(r->diags.all().empty());
  EXPECT_EQ(r->diags.all()[0].code, core::Code::DivisionByZero);
  EXPECT_EQ(r->diags.all()[0].loc.line, 7u);
  EXPECT_EQ(r->ends().size(), 1u);  // X2, and nothing after the error
}

// Every elseif on the way to the endif, not only the first one.
TEST(LinuxcncAgreement, EveryElseifAfterTheBranchThatRanIsEvaluated) {
  auto r =
      run("G21\n#1 = 0\no102 if [1]\nG0 X1\no102 elseif [1]\nG0 X2\no102 elseif [8/#1]\n"
          "G0 X4\no102 else\nG0 X5\no102 endif\nG0 X3\nM2\n");
  EXPECT_FALSE(r->ok);
  ASSERT_FALSE(r->diags.all().empty());
  EXPECT_EQ(r->diags.all()[0].code, core::Code::DivisionByZero);
  EXPECT_EQ(r->diags.all()[0].loc.line, 7u);
  EXPECT_EQ(r->ends().size(), 1u);
}

// interp_queue.cc move_endpoint_and_flush lets an arc whose end is moved
// sweep more than programmed by 0.0254 (radians) under G21 and by 0.001
// under G20: it compares turns with a length. A concave corner into this
// arc makes it 0.0077 rad longer: refused in inches, accepted in mm (rs274
// ends the arc, then goes straight to the G40 move's point).
TEST(LinuxcncAgreement, ArcLengthenedByAConcaveCornerHasMoreSlackInMm) {
  auto mm =
      run("G21 F746.8\nG41.1 D12.7 G1 X9.4467 Y-44.3195\nX-36.9515 Y-176.4855\n"
          "G91 G3 X75.6928 Y-10.8984 I36.54672 J-14.4789\nG90 G40 G1 X0 Y0\nM2\n");
  ASSERT_TRUE(mm->ok) << mm->first_error();
  EXPECT_EQ(mm->ends().size(), 5u);
  auto inch =
      run("G20 F30\nG41.1 D0.5 G1 X0.371917 Y-1.744862\nX-1.454783 Y-6.948248\n"
          "G91 G3 X2.980031 Y-0.429071 I1.438847 J-0.570035\nG90 G40 G1 X0 Y0\nM2\n");
  EXPECT_FALSE(inch->ok);
  ASSERT_FALSE(inch->diags.all().empty());
  EXPECT_EQ(inch->diags.all()[0].code, core::Code::CutterGouge);
}

// interp_convert.cc convert_home: the stored position is taken into program
// coordinates (find_relative) and the named axes take its program values;
// under an XY rotation that moves more than the named machine axis (rs274's
// trace of this program).
TEST(LinuxcncAgreement, HomeOfNamedAxesIsInProgramCoordinates) {
  InterpOptions mm;
  auto r = run("G21\n#5161 = 5\nG10 L2 P1 R90\nG0 X10 Y0\nG28 X10\nG30 Y2\nM2\n", mm);
  ASSERT_TRUE(r->ok) << r->first_error();
  const std::vector<Vec3> ends = r->ends();
  ASSERT_EQ(ends.size(), 5u);
  const std::vector<Vec3> expected{{0, 10, 0}, {0, 10, 0}, {0, 0, 0}, {-2, 0, 0}, {0, 0, 0}};
  for (std::size_t i = 0; i < ends.size(); ++i) {
    EXPECT_NEAR(ends[i].x, expected[i].x, 1e-9) << i;
    EXPECT_NEAR(ends[i].y, expected[i].y, 1e-9) << i;
    EXPECT_NEAR(ends[i].z, expected[i].z, 1e-9) << i;
  }
}

// interp_convert.cc convert_setup (G10 L20) starts from the current point
// as system P sees it (find_current_in_system): an axis not named keeps its
// offset, whichever system is in use (rs274's trace of this program).
TEST(LinuxcncAgreement, G10L20OnAnotherSystemSetsOnlyTheNamedAxes) {
  auto r =
      run("G21\nG10 L2 P2 Y7 R30\nG55\nG0 X1 Y2 Z3\nG10 L20 P4 X5\nG57\nG0 X0 Y0 Z0\n"
          "G10 L20 P3 Z1\nG56 G0 X1 Y1 Z1\nM2\n");
  ASSERT_TRUE(r->ok) << r->first_error();
  const std::vector<Vec3> ends = r->ends();
  ASSERT_EQ(ends.size(), 3u);
  EXPECT_NEAR(ends[1].x, std::cos(kPi / 6) - 2 * std::sin(kPi / 6) - 5,
              1e-9);  // R30 (1, 2), less 5
  EXPECT_NEAR(ends[1].y, 0.0, 1e-9);
  EXPECT_NEAR(ends[1].z, 0.0, 1e-9);
  EXPECT_NEAR(ends[2].x, 1.0, 1e-9);
  EXPECT_NEAR(ends[2].y, 1.0, 1e-9);
  EXPECT_NEAR(ends[2].z, 0.0, 1e-9);
}

// A table with tool 8: 3 mm long, 4 mm across.
InterpOptions tool_eight() {
  InterpOptions o;
  ToolEntry t;
  t.number = 8;
  t.pocket = 8;
  t.offset = {0, 0, 3};
  t.diameter = 4;
  o.tools.set(t);
  return o;
}

// interp_convert.cc convert_tool_length_offset: H goes through
// find_tool_index, and index 0 is the spindle: G43 H0 applies the length of
// the tool in the spindle (none before the first M6).
TEST(LinuxcncAgreement, G43H0IsTheToolInTheSpindle) {
  auto r = run("G21\nT8 M6\nG0 X0 Y0 Z0\nG43 H0\nG91 G0 X1\nM2\n", tool_eight());
  ASSERT_TRUE(r->ok) << r->first_error();
  EXPECT_EQ(r->ends().back(), (Vec3{1, 0, -3}));
  auto none = run("G21\nG0 X0 Y0 Z0\nG43 H0\nG91 G0 X1\nM2\n", tool_eight());
  ASSERT_TRUE(none->ok) << none->first_error();
  EXPECT_EQ(none->ends().back(), (Vec3{1, 0, 0}));
}

// Likewise convert_cutter_compensation_on: G41 D0 is the spindle's tool.
TEST(LinuxcncAgreement, G41D0IsTheToolInTheSpindle) {
  auto r =
      run("G21 F100\nT8 M6\nG0 X0 Y0 Z0\nG41 D0 G1 X20 Y0\nG1 Y20\nG40 G1 X40\nM2\n", tool_eight());
  ASSERT_TRUE(r->ok) << r->first_error();
  // The entry ends 2 mm (the radius) left of the line to (20, 0), square
  // to the next move: rs274 traces (17.6188, 2.3812) with its 1/8 in tool.
  const Vec3 entry = r->ends().at(1);
  EXPECT_GT(entry.y, 1.0);
  EXPECT_LT(entry.x, 20.0);
}

// saicanon.cc: after a probe the canon's position is the backed-off stop,
// and a tool change makes the interpreter read the position from the canon.
TEST(LinuxcncAgreement, ToolChangeAfterAProbeStartsFromTheProbesStop) {
  auto r = run("G21 F100\nG38.2 Z-10\nT8 M6\nG91 G1 X1\nM2\n", tool_eight());
  ASSERT_TRUE(r->ok) << r->first_error();
  EXPECT_NEAR(r->ends().back().z, -10.0 + 0.254, kTol);
}

// interp_o_word.cc enter_context: a tenth call level (the main program
// counted, INTERP_SUB_ROUTINE_LEVELS) is "Too many subroutine levels": nine
// nested calls run, ten do not (found by the differential fuzzer, seed
// 9209076). M98 enters a level the same way.
TEST(LinuxcncAgreement, CallsNestNineDeep) {
  const auto nested = [](int n) {
    return "o<r> sub\n  o1 if [#1 GT 0]\n    G1 X#1 F100\n    o<r> call [#1 - 1]\n"
           "  o1 endif\no<r> endsub\no<r> call [" +
           std::to_string(n) + "]\nM2\n";
  };
  auto nine = dialect_test::run_in("rs274ngc", nested(8));  // calls with 8, 7, ... 0
  EXPECT_TRUE(nine->ok) << nine->first_error_text();
  auto ten = dialect_test::run_in("rs274ngc", nested(9));
  EXPECT_EQ(ten->first_error(), core::Code::RecursionTooDeep);
  EXPECT_NE(ten->first_error_text().find("deeper than 9 calls"), std::string::npos)
      << ten->first_error_text();
}

// saicanon.cc STRAIGHT_PROBE backs off along the move the canon makes, from
// where its last move ended: after G43 H8 (3 mm) with no move, a probe over
// in Y also goes down 3 mm, and its stop is back along that slant, not
// along Y alone (found by the differential fuzzer, seed 8114888).
TEST(LinuxcncAgreement, AProbeBacksOffAlongTheMoveTheCanonMakes) {
  auto r = run("G21 F100\nG0 X0 Y0 Z0\nG43 H8\nG38.4 Y4\nG1 X0\nM2\n", tool_eight());
  ASSERT_TRUE(r->ok) << r->first_error();
  // The move: (0, 0, 0) to (0, 4, -3), 5 mm long; 0.254 mm back along it.
  const Vec3 stop = r->ends().back();
  EXPECT_NEAR(stop.y, 4.0 - 0.254 * 4.0 / 5.0, kTol);
  EXPECT_NEAR(stop.z, -3.0 + 0.254 * 3.0 / 5.0, kTol);
}

// interp_execute.cc: ROUND is (int)(x +- 0.5), so what rounds to zero is
// +0; the two-argument ATAN tells the sign of a zero apart (atan2). MOD
// keeps fmod's -0 (found by the differential fuzzer, seed 900576).
TEST(LinuxcncAgreement, RoundToZeroIsPositiveZero) {
  auto r = run("G21\nG0 X[ATAN[ROUND[-0.3]]/[-1]] Y0\nG0 X[ATAN[-1 MOD -1]/[-1]] Y1\nM2\n");
  ASSERT_TRUE(r->ok) << r->first_error();
  ASSERT_EQ(r->ends().size(), 2u);
  EXPECT_EQ(r->ends()[0].x, 180.0);
  EXPECT_EQ(r->ends()[1].x, -180.0);
}

// interp_execute.cc execute_unary: ABS negates what is below zero, so
// ABS[-0] is -0, and ATAN[ABS[-0]]/[-1] is -180 (found by the differential
// fuzzer, seed 10432060).
TEST(LinuxcncAgreement, AbsOfNegativeZeroIsNegativeZero) {
  auto r = run("G21\n#1 = [-0 * 1]\nG0 X[ATAN[ABS[#1]]/[-1]] Y[ABS[-2]]\nM2\n");
  ASSERT_TRUE(r->ok) << r->first_error();
  ASSERT_EQ(r->ends().size(), 1u);
  EXPECT_EQ(r->ends()[0].x, -180.0);
  EXPECT_EQ(r->ends()[0].y, 2.0);
}

// interp_read.cc read_real_value refuses a value that is not finite: a
// number, a parameter, a function's result, a bracket read as a value. What
// one operation hands the next inside a bracket is not checked, nor is a
// function's own bracket (differential fuzzer, seed 10427999: EXP[720]
// inside a comparison). Each case checked against rs274.
TEST(LinuxcncAgreement, AFunctionOrABracketThatIsNotFiniteIsAnError) {
  for (const char* value : {"[EXP[720] GT 0]", "[[10 ** 400] GT 0]", "[-[10 ** 400] LT 0]",
                            "[SQRT[10 ** 400] GT 0]", "[1 + ATAN[0]/[0 * [10 ** 400]]]"}) {
    auto r = run(std::string("G21\n#1 = ") + value + "\nG0 X#1\nM2\n");
    EXPECT_FALSE(r->ok) << value;
    EXPECT_TRUE(r->has(core::Code::NumberOutOfRange)) << value << ": " << r->first_error();
  }
  for (const auto& [value, x] : std::vector<std::pair<const char*, double>>{
           {"[10 ** 400 GT 0]", 1.0}, {"[ATAN[10 ** 400]/[1]]", 90.0}, {"[1 / 10 ** 400]", 0.0}}) {
    auto r = run(std::string("G21\n#1 = ") + value + "\nG0 X#1\nM2\n");
    ASSERT_TRUE(r->ok) << value << ": " << r->first_error();
    ASSERT_EQ(r->ends().size(), 1u);
    EXPECT_EQ(r->ends()[0].x, x) << value;
  }
}

// interp_arc.cc arc_data_ijk: a centre nearer than RADIUS_TOLERANCE
// (0.00005 in, 0.00127 mm) to the start or the end is "Zero-radius arc",
// before the radii are compared (found by the differential fuzzer, seed
// 7301243). Grbl has no such rule: a tinier arc runs.
TEST(LinuxcncAgreement, AnArcOfLessThanRadiusToleranceIsZeroRadius) {
  for (const char* arc : {"G21 G2 X0.002 Y0 I0.001 J0", "G20 G2 X0.00008 Y0 I0.00004 J0",
                          "G21 G2 X5 Y0 I0.0001 J0"}) {
    auto r = dialect_test::run_in("rs274ngc", std::string("F100\nG0 X0 Y0\n") + arc + "\nM2\n");
    EXPECT_EQ(r->first_error(), core::Code::ArcZeroLength) << arc;
    EXPECT_NE(r->first_error_text().find("zero radius"), std::string::npos)
        << r->first_error_text();
  }
  auto above = dialect_test::run_in("rs274ngc", "G21 F100\nG0 X0 Y0\nG2 X0.0026 Y0 I0.0013\nM2\n");
  EXPECT_TRUE(above->ok) << above->first_error_text();
  auto grbl = dialect_test::run_in("grbl", "G21 F100\nG0 X0 Y0\nG2 X0.002 Y0 I0.001 J0\nM2\n");
  EXPECT_TRUE(grbl->ok) << grbl->first_error_text();
}

// interp_arc.cc arc_data_r: half the chord may exceed |R| by
// RADIUS_TOLERANCE, 0.00005 in or 0.00127 mm, no more (usina allowed 0.0005
// in and 0.001 mm; found by the differential fuzzer, seed 7331363).
TEST(LinuxcncAgreement, AnRArcMayFallShortOfItsChordByRadiusTolerance) {
  struct Case {
    const char* arc;
    bool ok;
  };

  for (const Case& c :
       {Case{"G20 G2 X1.0002 Y0 R0.5", false}, Case{"G20 G2 X1.00009 Y0 R0.5", true},
        Case{"G21 G2 X10.0024 Y0 R5", true}, Case{"G21 G2 X10.0026 Y0 R5", false}}) {
    auto r = dialect_test::run_in("rs274ngc", std::string("F10\nG0 X0 Y0\n") + c.arc + "\nM2\n");
    EXPECT_EQ(r->ok, c.ok) << c.arc << ": " << r->first_error_text();
    if (!c.ok) {
      EXPECT_EQ(r->first_error(), core::Code::ArcRadiusTooSmall) << c.arc;
    }
  }
}

}  // namespace
}  // namespace usina::gcode
