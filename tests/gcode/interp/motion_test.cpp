// The RS274NGC interpreter, program text in, canon ops out. Straight moves, arcs and polar
// coordinates: each test runs a small program and checks the ops, the parameters or the one
// diagnostic (helpers: support/interp_run.hpp).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/interp_run.hpp"

namespace usina::gcode::interp_test {
namespace {

// ============================================================================
// Straight moves, units, distance modes
// ============================================================================

TEST(InterpMotion, RapidMoveIsATraverseInAbsoluteMm) {
  RUN_OK(r, "G21 G90\nG0 X1 Y2 Z3\nM2\n");
  EXPECT_EQ(r->kinds(), "traverse end");
  const auto t = r->all<Traverse>();
  ASSERT_EQ(t.size(), 1u);
  EXPECT_VEC(t[0].to, 1, 2, 3);
}

TEST(InterpMotion, OpsCarryTheLineAndColumnOfTheirBlock) {
  RUN_OK(r, "G0 X1\n\n   G0 X2\nM2\n");
  const auto t = r->ops_of<Traverse>();
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0]->src.line, 1u);
  EXPECT_EQ(t[0]->src.col, 1u);
  EXPECT_EQ(t[1]->src.line, 3u);
  EXPECT_EQ(t[1]->src.col, 4u);
  EXPECT_EQ(r->ops().back().src.line, 4u);
}

TEST(InterpMotion, FeedMoveCarriesTheFeedRate) {
  RUN_OK(r, "G1 X5 F120\nM2\n");
  const auto f = r->all<Feed>();
  ASSERT_EQ(f.size(), 1u);
  EXPECT_VEC(f[0].to, 5, 0, 0);
  ASSERT_TRUE(f[0].f.has_value());
  EXPECT_DOUBLE_EQ(*f[0].f, 120.0);
}

TEST(InterpMotion, InchWordsAndFeedBecomeMm) {
  RUN_OK(r, "G20\nG0 X1 Y-2\nG1 Z0.5 F10\nM2\n");
  const auto t = r->all<Traverse>();
  const auto f = r->all<Feed>();
  ASSERT_EQ(t.size(), 1u);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_VEC(t[0].to, kInch, -2 * kInch, 0);
  EXPECT_VEC(f[0].to, kInch, -2 * kInch, 0.5 * kInch);
  EXPECT_NEAR(*f[0].f, 10 * kInch, kTol);
}

TEST(InterpMotion, G21AfterG20MakesWordsMmAgain) {
  RUN_OK(r, "G20\nG0 X1\nG21\nG0 X1\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 2u);
  EXPECT_VEC(e[0], kInch, 0, 0);
  EXPECT_VEC(e[1], 1, 0, 0);
}

TEST(InterpMotion, FeedSetInInchKeepsItsSpeedAfterG21) {
  RUN_OK(r, "G20\nF10\nG21\nG1 X1\nM2\n");
  const auto f = r->all<Feed>();
  ASSERT_EQ(f.size(), 1u);
  EXPECT_NEAR(*f[0].f, 254.0, kTol);
}

TEST(InterpMotion, IncrementalG91AddsToTheCurrentPoint) {
  RUN_OK(r, "G91\nG0 X1\nG0 X1 Y2\nG90\nG0 X0\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[0], 1, 0, 0);
  EXPECT_VEC(e[1], 2, 2, 0);
  EXPECT_VEC(e[2], 0, 2, 0);
}

TEST(InterpMotion, IncrementalInchSteps) {
  RUN_OK(r, "G20 G91\nG0 X1\nG0 X1\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 2u);
  EXPECT_VEC(e[1], 2 * kInch, 0, 0);
}

TEST(InterpMotion, MotionModeStaysForLaterBlocks) {
  RUN_OK(r, "G1 X2 F100\nX1\nY1\nM2\n");
  EXPECT_EQ(r->kinds(), "feed feed feed end");
}

TEST(InterpMotion, FeedInTheBlockOfG20IsReadBeforeTheUnitsChange) {
  // RS274NGC order of execution: F (step 3) before units (step 12), so F10
  // here is 10 mm/min, and stays that speed in inch.
  RUN_OK(r, "G20 F10\nG1 X1\n#1=#<_feed>\nM2\n");
  EXPECT_NEAR(*r->all<Feed>()[0].f, 10.0, kTol);
  EXPECT_NEAR(r->param(1), 10.0 / kInch, kTol);
}

TEST(InterpMotion, G80BesideAMotionCodeIsAccepted) {
  RUN_OK(r, "G0 G80 X1\nG80 G1 X2 F10\nM2\n");
  EXPECT_EQ(r->kinds(), "traverse feed end");
}

TEST(InterpMotion, UnchangedAxesKeepTheirValue) {
  RUN_OK(r, "G0 X1 Y2 Z3\nG0 Y5\nM2\n");
  EXPECT_VEC(r->ends()[1], 1, 5, 3);
}

TEST(InterpMotion, RotaryAxesGoToAbcInDegreesNotScaledByInch) {
  RUN_OK(r, "G20\nG0 X1 A90\nM2\n");
  const auto t = r->all<Traverse>();
  ASSERT_EQ(t.size(), 1u);
  EXPECT_VEC(t[0].to, kInch, 0, 0);
  EXPECT_DOUBLE_EQ(t[0].abc[0], 90.0);
}

TEST(InterpMotion, CrLfProgramRunsLikeLf) {
  RUN_OK(r, "G0 X1\r\nG0 X2\r\nM2\r\n");
  EXPECT_EQ(r->kinds(), "traverse traverse end");
}

// ============================================================================
// Arcs
// ============================================================================

TEST(InterpArc, G2WithIjIsClockwiseAboutTheOffsetCentre) {
  RUN_OK(r, "G1 F100\nG2 X10 Y0 I5 J0\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 1u);
  EXPECT_VEC(a[0].to, 10, 0, 0);
  EXPECT_VEC(a[0].center, 5, 0, 0);
  EXPECT_VEC(a[0].normal, 0, 0, 1);
  EXPECT_EQ(a[0].turn, -1);
  EXPECT_DOUBLE_EQ(*a[0].f, 100.0);
}

TEST(InterpArc, G3IsCounterClockwiseAndAMissingJIsZero) {
  RUN_OK(r, "G1 F100\nG3 X10 Y0 I5\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 1u);
  EXPECT_VEC(a[0].center, 5, 0, 0);
  EXPECT_EQ(a[0].turn, 1);
}

TEST(InterpArc, CentreOffsetIsFromTheStartPoint) {
  RUN_OK(r, "G0 X10 Y10\nG1 F100\nG3 X0 Y10 I-5 J0\nM2\n");
  EXPECT_VEC(r->all<Arc>()[0].center, 5, 10, 0);
}

TEST(InterpArc, RFormatPositiveRadiusTakesTheShortArc) {
  // Chord (0,0)-(10,10), R10: the centres are (0,10) and (10,0); G3 short
  // is the one left of the chord.
  RUN_OK(r, "G1 F100\nG3 X10 Y10 R10\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 1u);
  EXPECT_VEC(a[0].center, 0, 10, 0);
  EXPECT_EQ(a[0].turn, 1);
}

TEST(InterpArc, RFormatNegativeRadiusTakesTheLongArc) {
  RUN_OK(r, "G1 F100\nG3 X10 Y10 R-10\nM2\n");
  EXPECT_VEC(r->all<Arc>()[0].center, 10, 0, 0);
}

TEST(InterpArc, RFormatClockwiseShortArc) {
  RUN_OK(r, "G1 F100\nG2 X10 Y10 R10\nM2\n");
  const auto a = r->all<Arc>();
  EXPECT_VEC(a[0].center, 10, 0, 0);
  EXPECT_EQ(a[0].turn, -1);
}

TEST(InterpArc, RFormatInInchIsScaled) {
  RUN_OK(r, "G20 G1 F10\nG3 X1 Y1 R1\nM2\n");
  EXPECT_VEC(r->all<Arc>()[0].center, 0, kInch, 0);
}

TEST(InterpArc, RFormatHalfCircleWithinToleranceUsesTheMidpoint) {
  // Half the chord is 5; R 4.9995 is within the 0.001 mm a program may be off.
  RUN_OK(r, "G1 F100\nG2 X10 R4.9995\nM2\n");
  EXPECT_VEC(r->all<Arc>()[0].center, 5, 0, 0);
}

TEST(InterpArc, FullCircleWhenTheEndIsTheStart) {
  RUN_OK(r, "G1 F100\nG2 X0 Y0 I5\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 1u);
  EXPECT_VEC(a[0].to, 0, 0, 0);
  EXPECT_VEC(a[0].center, 5, 0, 0);
  EXPECT_EQ(a[0].turn, -1);
}

TEST(InterpArc, PCountsTurns) {
  RUN_OK(r, "G1 F100\nG3 X0 Y0 I5 P3\nG2 X0 Y0 I5 P2\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0].turn, 3);
  EXPECT_EQ(a[1].turn, -2);
}

TEST(InterpArc, HelixEndsAtTheAxialWordAndCentreHasTheStartsAxialCoordinate) {
  RUN_OK(r, "G1 Z2 F100\nG3 X0 Y0 Z-5 I5 P2\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 1u);
  EXPECT_VEC(a[0].to, 0, 0, -5);
  EXPECT_VEC(a[0].center, 5, 0, 2);
  EXPECT_EQ(a[0].turn, 2);
}

TEST(InterpArc, G18UsesZAndXWithNormalY) {
  RUN_OK(r, "G1 F100\nG18 G2 X10 Z0 I5 K0\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 1u);
  EXPECT_VEC(a[0].to, 10, 0, 0);
  EXPECT_VEC(a[0].center, 5, 0, 0);
  EXPECT_VEC(a[0].normal, 0, 1, 0);
  EXPECT_EQ(a[0].turn, -1);
}

TEST(InterpArc, G18RFormatShortArcIsCounterClockwiseSeenFromPlusY) {
  // In (Z, X) coordinates the chord runs (0,0)-(10,10); the G3 short-arc
  // centre is (Z0, X10).
  RUN_OK(r, "G1 F100\nG18 G3 X10 Z10 R10\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 1u);
  EXPECT_VEC(a[0].center, 10, 0, 0);
  EXPECT_EQ(a[0].turn, 1);
}

TEST(InterpArc, G18HelixMovesAlongY) {
  RUN_OK(r, "G1 F100\nG18 G3 X10 Z0 Y3 I5\nM2\n");
  const auto a = r->all<Arc>();
  EXPECT_VEC(a[0].to, 10, 3, 0);
  EXPECT_VEC(a[0].center, 5, 0, 0);
}

TEST(InterpArc, G19UsesYAndZWithNormalX) {
  RUN_OK(r, "G1 F100\nG19 G2 Y10 Z0 J5\nG19 G3 Y20 Z10 R10\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 2u);
  EXPECT_VEC(a[0].center, 0, 5, 0);
  EXPECT_VEC(a[0].normal, 1, 0, 0);
  EXPECT_EQ(a[0].turn, -1);
  // From (Y10, Z0) to (Y20, Z10), G3 short: centre (Y10, Z10).
  EXPECT_VEC(a[1].center, 0, 10, 10);
}

TEST(InterpArc, G901MakesIjAbsoluteAndG911Incremental) {
  RUN_OK(r, "G1 F100\nG0 X2\nG90.1\nG3 X8 Y0 I5 J0\nG91.1\nG0 X2\nG3 X8 I3\nM2\n");
  const auto a = r->all<Arc>();
  ASSERT_EQ(a.size(), 2u);
  EXPECT_VEC(a[0].center, 5, 0, 0);
  EXPECT_VEC(a[1].center, 5, 0, 0);
}

TEST(InterpArc, ArcInIncrementalModeEndsRelativeToTheStart) {
  RUN_OK(r, "G0 X10\nG91 G1 F100\nG3 X-10 Y10 I-10\nM2\n");
  const auto a = r->all<Arc>();
  EXPECT_VEC(a[0].to, 0, 10, 0);
  EXPECT_VEC(a[0].center, 0, 0, 0);
}

TEST(InterpArc, InchCentreOffsetsAreScaled) {
  RUN_OK(r, "G20 G1 F10\nG2 X2 I1\nM2\n");
  EXPECT_VEC(r->all<Arc>()[0].center, kInch, 0, 0);
}

// ============================================================================
// Polar coordinates
// ============================================================================

TEST(InterpPolar, RadiusAndAngleAboutTheOrigin) {
  RUN_OK(r, "G0 @10 ^90\nG1 @10 ^0 F100\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 2u);
  EXPECT_VEC(e[0], 0, 10, 0);
  EXPECT_VEC(e[1], 10, 0, 0);
}

TEST(InterpPolar, IncrementalAddsToThePolarCoordinatesOfTheCurrentPoint) {
  RUN_OK(r, "G0 @10 ^0\nG91 G0 ^90\nG0 @5\nM2\n");
  const auto e = r->ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[1], 0, 10, 0);
  EXPECT_VEC(e[2], 0, 15, 0);
}

TEST(InterpPolar, RadiusInInch) {
  RUN_OK(r, "G20 G0 @1 ^180\nM2\n");
  EXPECT_VEC(r->ends()[0], -kInch, 0, 0);
}

TEST(InterpPolar, PolarWithXIsAnError) {
  auto r = run("G0 @10 X5\nM2\n");
  expect_error(*r, Code::AxisWordsConflict, 1, 8);
}

TEST(InterpPolar, PolarOutsideG17IsAnError) {
  auto r = run("G18\nG0 @10 ^0\nM2\n");
  expect_error(*r, Code::NotAllowedInMode, 2, 1);
}

}  // namespace
}  // namespace usina::gcode::interp_test
