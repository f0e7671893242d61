// The fanuc dialect's geometry: G76/G87 under G91 and K repeats, G16
// polar coordinates (G91 radius, arcs, the G18/G19 planes), G51/G51.1/G68
// in every plane, G68's incremental angle (parameter 5400 RIN), mirror
// reversing G68, the warning after G69, and ROUND at an address (docs/fanuc.md §4, §7). Each
// expected point is worked out by hand in the comment beside it.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "fanuc_test_support.hpp"

namespace usina::gcode::fanuc_test {
namespace {

using core::Code;
using core::Vec3;

// The points the tool fed to (the bottoms of bored holes, G1 ends).
std::vector<Vec3> feeds(const Run& r) {
  std::vector<Vec3> out;
  for (const canon::Feed& f : r.all<canon::Feed>())
    out.push_back(f.to);
  return out;
}

// --- 1. G76 / G87 under G91 ---------------------------------------------

TEST(FanucFineBoring, G91RIsFromTheInitialLevelAndZFromR) {
  // Initial level 10; R-8. -> R point 2; Z-10. from R -> bottom -8; hole at
  // the current point + (5, 5). After the cycle the program is still in G91.
  auto r = run_fanuc(
      "G0 X1. Y1. Z10.\nS500 M3\nG91 G98 G76 X5. Y5. Z-10. R-8. Q0.5 P200 F60.\nG80\n"
      "G1 X1. F100.\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto ends = r->ends();
  ASSERT_EQ(ends.size(), 8u);
  expect_near(ends[1], {6, 6, 10});    // rapid over the hole
  expect_near(ends[2], {6, 6, 2});     // R point
  expect_near(ends[3], {6, 6, -8});    // bottom
  expect_near(ends[4], {6.5, 6, -8});  // shifted Q in +X
  expect_near(ends[5], {6.5, 6, 10});  // G98: initial level
  expect_near(ends[6], {6, 6, 10});    // shifted back
  expect_near(ends[7], {7, 6, 10});    // G91 again: X1. moves by 1
}

TEST(FanucFineBoring, G91KRepeatsStepTheHole) {
  // K3 with X5.: holes at 5, 10, 15; G99 returns to the R point 2.
  auto r = run_fanuc("G0 X0 Y0 Z10.\nG91 G99 G76 X5. Z-10. R-8. Q0.5 K3 F60.\nG80\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto bottoms = feeds(*r);
  ASSERT_EQ(bottoms.size(), 3u);
  expect_near(bottoms[0], {5, 0, -8});
  expect_near(bottoms[1], {10, 0, -8});
  expect_near(bottoms[2], {15, 0, -8});
  expect_end(*r, {15, 0, 2});
}

TEST(FanucFineBoring, G90KBoresTheSameHoleAndK0BoresNothing) {
  auto twice = run_fanuc("G0 X0 Y0 Z10.\nG98 G76 X5. Y5. Z-8. R2. Q0.5 K2 F60.\nG80\nM30\n");
  ASSERT_TRUE(twice->ok) << twice->first_error_text();
  const auto bottoms = feeds(*twice);
  ASSERT_EQ(bottoms.size(), 2u);
  expect_near(bottoms[0], {5, 5, -8});
  expect_near(bottoms[1], {5, 5, -8});
  auto none = run_fanuc("G0 X0 Y0 Z10.\nG98 G76 X5. Y5. Z-8. R2. Q0.5 K0 F60.\nG80\nM30\n");
  ASSERT_TRUE(none->ok) << none->first_error_text();
  EXPECT_TRUE(feeds(*none).empty());
}

TEST(FanucFineBoring, G87UnderG91) {
  // Initial 10; R-30. -> bottom (R point) -20; Z18. from R -> -2.
  auto r =
      run_fanuc("G0 X0 Y0 Z10.\nS500 M3\nG91 G98 G87 X5. Y5. Z18. R-30. Q0.5 F60.\nG80\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto ends = r->ends();
  ASSERT_EQ(ends.size(), 9u);
  expect_near(ends[2], {5.5, 5, 10});   // shifted in
  expect_near(ends[3], {5.5, 5, -20});  // rapid down to R, the bottom
  expect_near(ends[5], {5, 5, -2});     // fed up to Z
  expect_near(ends[7], {5.5, 5, 10});   // out at the initial level
}

TEST(FanucFineBoring, G91ZWithoutRIsAnError) {
  auto r = run_fanuc("G0 Z10.\nG91 G76 X1. Z-1. Q0.1 F10.\nM30\n");
  EXPECT_EQ(r->first_error(), Code::MissingWord);
}

TEST(FanucFineBoring, LaterBlocksKeepTheLevelsAsPositions) {
  // The second hole (G91 X10.) bores to the same R 2 and bottom -8.
  auto r = run_fanuc("G0 X0 Y0 Z10.\nG98 G76 X5. Z-8. R2. Q0.5 F60.\nG91 X10.\nG80\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto bottoms = feeds(*r);
  ASSERT_EQ(bottoms.size(), 2u);
  expect_near(bottoms[1], {15, 0, -8});
  expect_end(*r, {15, 0, 10});
}

// --- 2. G16 polar coordinates -------------------------------------------

TEST(FanucPolar, G91RadiusMeasuresFromTheCurrentPoint) {
  // From (10, 0): G91 X5. Y90. -> 5 at 0 + 90 degrees from (10, 0) = (10, 5).
  auto r = run_fanuc("G16\nG0 X10. Y0\nG91 X5. Y90.\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {10, 5, 0});
  // The angle left out is the current point's: 5 further along 0 degrees.
  auto along = run_fanuc("G16\nG0 X10. Y0\nG91 X5.\nM30\n");
  ASSERT_TRUE(along->ok) << along->first_error_text();
  expect_end(*along, {15, 0, 0});
}

TEST(FanucPolar, AnglesAfterAG91RadiusAreThePointsAngle) {
  // (10, 0) then G91 X10. Y90. -> (10, 10), at 45 degrees on radius 14.142;
  // G91 Y45. turns it to 90 degrees on the same radius: (0, 14.142).
  auto r = run_fanuc("G16\nG0 X10. Y0\nG91 X10. Y90.\nY45.\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {0, std::sqrt(200.0), 0});
}

TEST(FanucPolar, ArcsTakeAPolarEndPointAndR) {
  // From (10, 0) a G03 to radius 10 at 90 degrees, R10.: the quarter circle
  // about the work zero, counter-clockwise.
  auto r = run_fanuc("G16\nG0 X10. Y0\nG3 X10. Y90. R10. F100.\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto arcs = r->all<canon::Arc>();
  ASSERT_EQ(arcs.size(), 1u);
  expect_near(arcs[0].to, {0, 10, 0});
  expect_near(arcs[0].center, {0, 0, 0});
  EXPECT_GT(arcs[0].turn, 0);
}

TEST(FanucPolar, ArcsWithIJKAreAnError) {
  auto r = run_fanuc("G16\nG0 X10. Y0\nG3 X10. Y90. I-10. F100.\nM30\n");
  EXPECT_EQ(r->first_error(), Code::NotAllowedInMode);
}

TEST(FanucPolar, TheFirstAndSecondAxisOfG18AndG19) {
  // G18: Z is the radius, X the angle from +Z: Z10. X30. -> Z 8.660, X 5.
  auto zx = run_fanuc("G18 G16\nG0 Z10. X30.\nM30\n");
  ASSERT_TRUE(zx->ok) << zx->first_error_text();
  expect_end(*zx, {5, 0, 10 * std::cos(std::numbers::pi / 6)});
  // G19: Y is the radius, Z the angle from +Y: Y10. Z90. -> Y 0, Z 10.
  auto yz = run_fanuc("G19 G16\nG0 Y10. Z90.\nM30\n");
  ASSERT_TRUE(yz->ok) << yz->first_error_text();
  expect_end(*yz, {0, 0, 10});
}

// --- 3. G51 / G51.1 / G68 outside G17 -----------------------------------

TEST(FanucPlanes, G68InG18AndG19TakesThePlanesAxesAsCentre) {
  // G18 turns from +Z towards +X: (Z10, X5) about (Z0, X5) by 90 -> X 15, Z 0.
  auto zx = run_fanuc("G18 G68 X5. Z0 R90.\nG0 X5. Z10.\nG69\nM30\n");
  ASSERT_TRUE(zx->ok) << zx->first_error_text();
  expect_end(*zx, {15, 0, 0});
  // G19 turns from +Y towards +Z: (Y10, Z0) by 90 -> Y 0, Z 10.
  auto yz = run_fanuc("G19 G68 Y0 Z0 R90.\nG0 Y10. Z0\nM30\n");
  ASSERT_TRUE(yz->ok) << yz->first_error_text();
  expect_end(*yz, {0, 0, 10});
}

TEST(FanucPlanes, ArcsUnderG68InG18) {
  // The G18 quarter (Z10, X0) -> (Z0, X10) about the origin, turned 90:
  // (Z0, X10) -> (Z-10, X0), still counter-clockwise, centre unmoved.
  auto r = run_fanuc("G18 G0 X0 Z0\nG68 X0 Z0 R90.\nG0 X0 Z10.\nG3 X10. Z0 K-10. F100.\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto arcs = r->all<canon::Arc>();
  ASSERT_EQ(arcs.size(), 1u);
  expect_near(arcs[0].to, {0, 0, -10});
  expect_near(arcs[0].center, {0, 0, 0});
  EXPECT_GT(arcs[0].turn, 0);
}

TEST(FanucPlanes, MirrorInG18ReversesArcs) {
  // X mirrored about 0: the G03 from (Z10, X0) to (Z0, X10) becomes a
  // clockwise arc to (Z0, X-10).
  auto r = run_fanuc("G18 G0 X0 Z10.\nG51.1 X0\nG3 X10. Z0 K-10. F100.\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto arcs = r->all<canon::Arc>();
  ASSERT_EQ(arcs.size(), 1u);
  expect_near(arcs[0].to, {-10, 0, 0});
  EXPECT_LT(arcs[0].turn, 0);
}

TEST(FanucPlanes, G51IJKScalePerAxis) {
  // I2. K3. about the origin: X4. Z5. -> X8 Z15; Y (J left out, P absent) 1.
  auto r = run_fanuc("G51 X0 Y0 Z0 I2. K3.\nG0 X4. Y1. Z5.\nG50\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {8, 1, 15});
  // An arc in G18 scaled by 2 in X and Z: the radius doubles.
  auto arc = run_fanuc("G18 G0 X0 Z10.\nG51 X0 Y0 Z0 I2. K2.\nG3 X10. Z0 R10. F100.\nM30\n");
  ASSERT_TRUE(arc->ok) << arc->first_error_text();
  ASSERT_EQ(arc->all<canon::Arc>().size(), 1u);
  expect_near(arc->all<canon::Arc>()[0].to, {20, 0, 0});
  EXPECT_EQ(run_fanuc("G18 G51 X0 Y0 Z0 I2.\nG3 X10. Z0 R10. F100.\nM30\n")->first_error(),
            Code::UnequalScaleArc);
  EXPECT_EQ(run_fanuc("G51 X0 Y0 Z0 K0\nM30\n")->first_error(), Code::ScaleOutOfRange);
}

TEST(FanucPlanes, PScalesXAndYUnlessScalingAxesSaysXyz) {
  auto xy = run_fanuc("G51 X0 Y0 Z0 P2.\nG0 X1. Y1. Z1.\nM30\n");
  ASSERT_TRUE(xy->ok) << xy->first_error_text();
  expect_end(*xy, {2, 2, 1});
  auto xyz = run_fanuc("G51 X0 Y0 Z0 P2.\nG0 X1. Y1. Z1.\nM30\n", {}, {"scaling_axes=xyz"});
  ASSERT_TRUE(xyz->ok) << xyz->first_error_text();
  expect_end(*xyz, {2, 2, 2});
}

TEST(FanucPlanes, ArcOutsideTheRotationPlaneIsAnError) {
  auto r = run_fanuc("G68 X0 Y0 R10.\nG18\nG2 X1. Z1. R1. F100.\nM30\n");
  EXPECT_EQ(r->first_error(), Code::NotAllowedInMode);
}

TEST(FanucPlanes, CycleWithTheDrillingAxisScaledIsNotImplemented) {
  auto r = run_fanuc("G51 X0 Y0 Z0 K2.\nG81 X1. Y1. Z-1. R1. F100.\nM30\n");
  EXPECT_EQ(r->first_error(), Code::Unsupported);
}

// --- 4. G68 incremental angle (parameter 5400 RIN) ----------------------

TEST(FanucRotation, G91RIsAbsoluteByDefault) {
  // RIN = 0: the second G68 R45. in G91 sets 45 degrees: (10, 0) -> (7.071, 7.071).
  auto r = run_fanuc("G68 X0 Y0 R45.\nG91 G68 R45.\nG90 G0 X10. Y0\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const double h = 10 / std::sqrt(2.0);
  expect_end(*r, {h, h, 0});
}

TEST(FanucRotation, G91RAddsWithRotationIncremental) {
  const std::vector<std::string> rin{"rotation_incremental=1"};
  // RIN = 1: 45 + 45 = 90 degrees: (10, 0) -> (0, 10).
  auto r = run_fanuc("G68 X0 Y0 R45.\nG91 G68 R45.\nG90 G0 X10. Y0\nM30\n", {}, rin);
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {0, 10, 0});
  // In G90 R stays absolute; after G69 the angle starts from 0 again.
  auto g90 = run_fanuc("G68 X0 Y0 R45.\nG68 R90.\nG0 X10. Y0\nM30\n", {}, rin);
  ASSERT_TRUE(g90->ok) << g90->first_error_text();
  expect_end(*g90, {0, 10, 0});
  auto after = run_fanuc("G68 X0 Y0 R45.\nG69\nG91 G68 X0 Y0 R90.\nG90 G0 X10. Y0\nM30\n", {}, rin);
  ASSERT_TRUE(after->ok) << after->first_error_text();
  expect_end(*after, {0, 10, 0});
}

// --- 5. Mirror reverses G68; the order mirror, scaling, rotation --------

TEST(FanucRotation, MirrorTurnsTheRotationTheOtherWay) {
  // Unmirrored, (10, 0) about (5, 0) by 90 is (5, 5); mirrored in X about 0
  // the part is the mirror image: (-5, 5).
  auto r = run_fanuc("G51.1 X0\nG68 X5. Y0 R90.\nG0 X10. Y0\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {-5, 5, 0});
  // Both axes mirrored: a point reflection, the rotation keeps its sense:
  // (5, 5) -> (-5, -5).
  auto both = run_fanuc("G51.1 X0 Y0\nG68 X5. Y0 R90.\nG0 X10. Y0\nM30\n");
  ASSERT_TRUE(both->ok) << both->first_error_text();
  expect_end(*both, {-5, -5, 0});
}

TEST(FanucRotation, ScalingComesFirstAndScalesTheCentre) {
  // Scale 2 about 0, then turn 90 about (5, 0) scaled to (10, 0):
  // (10, 0) -> (20, 0) -> (10, 10), i.e. the turned part (5, 5) scaled.
  auto r = run_fanuc("G51 X0 Y0 P2.\nG68 X5. Y0 R90.\nG0 X10. Y0\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {10, 10, 0});
}

// --- 5b. The first move after G69 ([16MC] p. 354) -----------------------

int after_g69_warnings(const Run& r) {
  int n = 0;
  for (const core::Diagnostic& d : r.diags.all())
    n += d.code == Code::IncrementalAfterG69 ? 1 : 0;
  return n;
}

TEST(FanucAfterG69, AnIncrementalFirstMoveIsWarnedAtItsWord) {
  // Under R90 X10. ends at (0, 10); after G69 usina moves by the increment
  // from there: (5, 10).
  auto r = run_fanuc("G68 X0 Y0 R90.\nG0 X10.\nG69\nG91 G0 X5.\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  ASSERT_EQ(after_g69_warnings(*r), 1);
  for (const core::Diagnostic& d : r->diags.all()) {
    if (d.code != Code::IncrementalAfterG69) continue;
    EXPECT_EQ(d.severity, core::Severity::Warning);
    EXPECT_EQ(d.loc.line, 4u);
    EXPECT_EQ(d.loc.col, 8u);  // at X5.
  }
  expect_end(*r, {5, 10, 0});
}

TEST(FanucAfterG69, AMoveInTheG69BlockIsTheFirstMove) {
  auto r = run_fanuc("G68 X0 Y0 R90.\nG91 G69 G0 X5.\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  EXPECT_EQ(after_g69_warnings(*r), 1);
}

TEST(FanucAfterG69, AnAbsoluteFirstMoveEndsTheCheck) {
  auto r = run_fanuc("G68 X0 Y0 R90.\nG0 X10.\nG69\nG90 G0 X1. Y1.\nG91 X5.\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  EXPECT_EQ(after_g69_warnings(*r), 0);
  expect_end(*r, {6, 1, 0});
}

TEST(FanucAfterG69, G69WithoutARotationIsNotWatched) {
  auto r = run_fanuc("G90 G17 G69\nG91 G0 X5.\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  EXPECT_EQ(after_g69_warnings(*r), 0);
}

TEST(FanucAfterG69, MovesOutsideThePlaneDoNotDecide) {
  // G91 Z5. does not name X or Y; the X5. after it is the first move.
  auto r = run_fanuc("G68 X0 Y0 R90.\nG69\nG91 G0 Z5.\nX5.\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  ASSERT_EQ(after_g69_warnings(*r), 1);
  // G04 X is a dwell, not a move.
  auto dwell = run_fanuc("G68 X0 Y0 R90.\nG69\nG91 G04 X1.\nG90 G0 X1.\nM30\n");
  ASSERT_TRUE(dwell->ok) << dwell->first_error_text();
  EXPECT_EQ(after_g69_warnings(*dwell), 0);
}

TEST(FanucAfterG69, G28EndsTheCheck) {
  // G91 G28 X0 Y0 goes to the reference position: the point is known again.
  auto r = run_fanuc("G68 X0 Y0 R90.\nG69\nG91 G28 X0 Y0\nG0 X5.\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  EXPECT_EQ(after_g69_warnings(*r), 0);
}

// --- 6. ROUND at an address ---------------------------------------------

TEST(FanucRound, AtAnAddressToTheLeastIncrement) {
  // X[ROUND[1.2345]] is X1.235 (0.001 mm); #2 = ROUND[1.2345] is 1.
  auto r = run_fanuc("#1 = 1.2345\nG0 X[ROUND[#1]]\n#2 = ROUND[#1]\nG0 Y#2\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {1.235, 1, 0});
  // In G20 the increment is 0.0001 in: 1.23456 -> 1.2346 in.
  auto inch = run_fanuc("G20\n#1 = 1.23456\nG0 X[ROUND[#1]]\nM30\n");
  ASSERT_TRUE(inch->ok) << inch->first_error_text();
  expect_end(*inch, {1.2346 * 25.4, 0, 0});
  // Negative values round half away from zero: -1.2345 -> -1.235.
  auto neg = run_fanuc("#1 = -1.2345\nG0 Z[ROUND[#1]]\nM30\n");
  ASSERT_TRUE(neg->ok) << neg->first_error_text();
  expect_end(*neg, {0, 0, -1.235});
}

TEST(FanucRound, InAMacroStatementToAnInteger) {
  // ROUND[2.5] = 3 in a statement; in an IF condition too.
  auto r = run_fanuc("#1 = ROUND[2.5]\nIF [ROUND[0.5] EQ 1] THEN #2 = 7.\nG0 X#1 Y#2\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_end(*r, {3, 7, 0});
}

}  // namespace
}  // namespace usina::gcode::fanuc_test
