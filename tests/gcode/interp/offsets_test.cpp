// The RS274NGC interpreter, program text in, canon ops out. Offsets: G92, G52, work offsets, G53,
// G28/G30: each test runs a small program and checks the ops, the parameters or the one diagnostic
// (helpers: support/interp_run.hpp).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/interp_run.hpp"

namespace usina::gcode::interp_test {
namespace {

// ============================================================================
// G92, G52, work offsets, G53, G28/G30
// ============================================================================

TEST(InterpOffsets, G92MakesTheCurrentPointReadTheGivenValue) {
  RUN_OK(r, "G0 X10\nG92 X0\nG0 X5\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 2u) << "G92 itself does not move";
  EXPECT_VEC(e[1], 15, 0, 0);
  EXPECT_DOUBLE_EQ(r->param(5211), 10.0);
  EXPECT_DOUBLE_EQ(r->param(5210), 1.0);
}

TEST(InterpOffsets, G92InInchStoresMachineUnits) {
  RUN_OK(r, "G20\nG0 X1\nG92 X0\nG0 X1\nM2\n");
  EXPECT_VEC(r->ends()[1], 2 * kInch, 0, 0);
  EXPECT_NEAR(r->param(5211), kInch, kTol);
}

TEST(InterpOffsets, G921ClearsTheOffsetAndItsParameters) {
  RUN_OK(r, "G0 X10\nG92 X0\nG92.1\nG0 X5\nM2\n");
  EXPECT_VEC(r->ends().back(), 5, 0, 0);
  EXPECT_DOUBLE_EQ(r->param(5211), 0.0);
  EXPECT_DOUBLE_EQ(r->param(5210), 0.0);
}

TEST(InterpOffsets, G922ClearsTheOffsetButKeepsItsParametersForG923) {
  RUN_OK(r, "G0 X10\nG92 X0\nG92.2\nG0 X5\nG92.3\nG0 X5\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[1], 5, 0, 0);
  EXPECT_VEC(e[2], 15, 0, 0);
  EXPECT_DOUBLE_EQ(r->param(5211), 10.0);
}

TEST(InterpOffsets, G52ShiftsTheOriginByTheGivenValue) {
  RUN_OK(r, "G0 X1\nG52 X5 Y-1\nG0 X0 Y0\nG52 X0 Y0\nG0 X0 Y0\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[1], 5, -1, 0);
  EXPECT_VEC(e[2], 0, 0, 0);
}

TEST(InterpOffsets, G10L2SetsTheActiveWorkOffset) {
  RUN_OK(r, "G10 L2 P1 X10 Y5\nG0 X0 Y0\nM2\n");
  EXPECT_VEC(r->ends()[0], 10, 5, 0);
  EXPECT_DOUBLE_EQ(r->param(5221), 10.0);
  EXPECT_DOUBLE_EQ(r->param(5222), 5.0);
}

TEST(InterpOffsets, G10L2OnAnotherSystemTakesEffectWhenSelected) {
  RUN_OK(r, "G10 L2 P2 X20\nG0 X0\nG55\nG0 X0\n#1=#<_coord_system>\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 2u);
  EXPECT_VEC(e[0], 0, 0, 0);
  EXPECT_VEC(e[1], 20, 0, 0);
  EXPECT_DOUBLE_EQ(r->param(5241), 20.0);
  EXPECT_DOUBLE_EQ(r->param(5220), 2.0);
  EXPECT_DOUBLE_EQ(r->param(1), 550.0);
}

TEST(InterpOffsets, G10L2P0MeansTheActiveSystem) {
  RUN_OK(r, "G56\nG10 L2 P0 X3\nG0 X0\nM2\n");
  EXPECT_VEC(r->ends()[0], 3, 0, 0);
  EXPECT_DOUBLE_EQ(r->param(5261), 3.0);
}

TEST(InterpOffsets, G593IsTheNinthSystem) {
  RUN_OK(r, "G10 L2 P9 X7\nG59.3\nG0 X0\n#1=#<_coord_system>\nM2\n");
  EXPECT_VEC(r->ends()[0], 7, 0, 0);
  EXPECT_DOUBLE_EQ(r->param(5381), 7.0);
  EXPECT_DOUBLE_EQ(r->param(1), 593.0);
}

TEST(InterpOffsets, G10L2InInchStoresMachineUnits) {
  RUN_OK(r, "G20\nG10 L2 P1 X1\nG0 X0\nM2\n");
  EXPECT_VEC(r->ends()[0], kInch, 0, 0);
  EXPECT_NEAR(r->param(5221), kInch, kTol);
}

TEST(InterpOffsets, G10L2RRotatesTheSystemAboutItsOrigin) {
  RUN_OK(r, "G10 L2 P1 X100 R90\nG0 X10 Y0\nM2\n");
  EXPECT_VEC(r->ends()[0], 100, 10, 0);
  EXPECT_DOUBLE_EQ(r->param(5230), 90.0);
}

TEST(InterpOffsets, RotatedArcHasARotatedCentre) {
  RUN_OK(r, "G10 L2 P1 R90\nG1 F100\nG2 X10 I5\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 1u);
  EXPECT_VEC(a[0].to, 0, 10, 0);
  EXPECT_VEC(a[0].center, 0, 5, 0);
  EXPECT_VEC(a[0].normal, 0, 0, 1);
  EXPECT_EQ(a[0].turn, -1);
}

TEST(InterpOffsets, G10L20MakesTheCurrentPointReadTheGivenValue) {
  RUN_OK(r, "G0 X3\nG10 L20 P1 X5\nG0 X5\nG0 X10\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[1], 3, 0, 0);
  EXPECT_VEC(e[2], 8, 0, 0);
  EXPECT_DOUBLE_EQ(r->param(5221), -2.0);
}

TEST(InterpOffsets, G53MovesInMachineCoordinatesForOneBlock) {
  RUN_OK(r, "G10 L2 P1 X10\nG0 X0\nG53 G0 X0\nG0 X1\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[0], 10, 0, 0);
  EXPECT_VEC(e[1], 0, 0, 0);
  EXPECT_VEC(e[2], 11, 0, 0);
}

TEST(InterpOffsets, G53IsAbsoluteEvenUnderG91) {
  RUN_OK(r, "G91\nG0 X5\nG53 G0 X1\nM2\n");
  EXPECT_VEC(r->ends()[1], 1, 0, 0);
}

TEST(InterpOffsets, G53WithG1Feeds) {
  RUN_OK(r, "G10 L2 P1 X10\nG53 G1 X2 F100\nM2\n");
  EXPECT_EQ(r->kinds(), "feed end");
  EXPECT_VEC(r->ends()[0], 2, 0, 0);
}

TEST(InterpOffsets, G53WithAnArcIsAnError) {
  auto r = run("G1 F100\nG53 G2 X1 I1\nM2\n");
  expect_error(*r, Code::NotAllowedInMode, 2, 1);
}

TEST(InterpOffsets, G28GoesToThePositionStoredByG281) {
  // LinuxCNC moves to the intermediate point even without axis words (a
  // move to where the tool is), then home.
  RUN_OK(r, "G0 X3 Y4 Z5\nG28.1\nG0 X0 Y0 Z0\nG28\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 4u);
  EXPECT_VEC(e[2], 0, 0, 0);
  EXPECT_VEC(e[3], 3, 4, 5);
  EXPECT_DOUBLE_EQ(r->param(5161), 3.0);
  EXPECT_DOUBLE_EQ(r->param(5162), 4.0);
  EXPECT_DOUBLE_EQ(r->param(5163), 5.0);
}

TEST(InterpOffsets, G28WithAnAxisWordGoesThroughItAndHomesOnlyThatAxis) {
  RUN_OK(r, "G0 X3 Y4 Z5\nG28.1\nG0 X1 Y1 Z0\nG28 Z2\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 4u);
  EXPECT_VEC(e[2], 1, 1, 2);
  EXPECT_VEC(e[3], 1, 1, 5);
}

TEST(InterpOffsets, G28HomeIsInMachineCoordinates) {
  RUN_OK(r, "G10 L2 P1 X10\nG0 X3\nG28.1\nG0 X0\nG28\nM2\n");
  EXPECT_DOUBLE_EQ(r->param(5161), 13.0);
  EXPECT_VEC(r->ends().back(), 13, 0, 0);
}

TEST(InterpOffsets, G28UsesAPresetParameter) {
  RUN_OK(r, "G28\nM2\n", {}, {{5161, 50}, {5163, 20}});
  EXPECT_VEC(r->ends().back(), 50, 0, 20);
}

TEST(InterpOffsets, G30GoesToThePositionStoredByG301) {
  RUN_OK(r, "G0 X1 Y2 Z3\nG30.1\nG0 X0 Y0 Z0\nG30\nM2\n");
  EXPECT_VEC(r->ends().back(), 1, 2, 3);
  EXPECT_DOUBLE_EQ(r->param(5181), 1.0);
  EXPECT_DOUBLE_EQ(r->param(5183), 3.0);
}

// Regression (a bug the tests found, fixed): the work offset and G92 offset held by the parameters
// at the start
// (#5220 and #5221.., #5210 and #5211.., as a var file gives them) are not
// applied until the program selects a system or runs G92.3. LinuxCNC restores
// both when the interpreter starts (rs274ngc_pre.cc, Interp::init: origin
// offsets from pars[5220]'s system, axis offsets when pars[5210] is set).
// Expected: with #5221 = 10, `G0 X0` goes to absolute X10; with #5210 = 1 and
// #5211 = 3 to X3. Actual: X0 both times (g5x and g92 start at zero).
TEST(InterpOffsets, OffsetsFromParametersApplyAtStart) {
  RUN_OK(r, "G0 X0\nM2\n", {}, {{5220, 1}, {5221, 10}});
  EXPECT_VEC(r->ends()[0], 10, 0, 0);
  RUN_OK(g92, "G0 X0\nM2\n", {}, {{5210, 1}, {5211, 3}});
  EXPECT_VEC(g92->ends()[0], 3, 0, 0);
}

TEST(InterpOffsets, WorkOffsetFromParametersAppliesWhenSelected) {
  RUN_OK(r, "G54\nG0 X0\nM2\n", {}, {{5221, 10}});
  EXPECT_VEC(r->ends()[0], 10, 0, 0);
}

}  // namespace
}  // namespace usina::gcode::interp_test
