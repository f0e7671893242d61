// The romi dialect's polar straight moves and arcs (spec/romi.md, "Polar
// linear moves", "Polar arcs").
#include <cmath>

#include "romi_test_support.hpp"

namespace usina::gcode::romi_test {
namespace {

using core::Code;

Vec3 last_end(const std::string& program) {
  auto r = run_romi(program);
  EXPECT_TRUE(r->ok) << r->first_error_text();
  return r->ends().empty() ? Vec3{} : r->ends().back();
}

TEST(RomiPolarLine, RAloneMovesAlongTheRayFromProgramZero) {
  expect_near(last_end("X30 Y40#R10#M02#"), {6, 8, 0});
}

TEST(RomiPolarLine, RAloneIncrementalAddsToTheRadius) {
  expect_near(last_end("X30 Y40#G91 R5#M02#"), {33, 44, 0});
  expect_near(last_end("X30 Y40#r5#M02#"), {33, 44, 0});
}

TEST(RomiPolarLine, RAloneAtTheCentreIsAnError) {
  auto r = run_romi("R10#M02#");
  EXPECT_EQ(r->first_error(), Code::BadWordValue);
}

TEST(RomiPolarLine, CAloneTurnsAboutProgramZero) {
  expect_near(last_end("X10#C90#M02#"), {0, 10, 0});
}

TEST(RomiPolarLine, CUnderG91AddsToTheAngle) {
  expect_near(last_end("X10#G91 C90#C90#M02#"), {-10, 0, 0});
}

TEST(RomiPolarLine, LowerCaseCIsIncremental) {
  expect_near(last_end("X10#c90#c90#M02#"), {-10, 0, 0});
}

TEST(RomiPolarLine, RAGoesFromTheStartPoint) {
  expect_near(last_end("X5 Y5#R10 A90#M02#"), {5, 15, 0});
}

TEST(RomiPolarLine, RCIsAPointAboutTheCentre) {
  expect_near(last_end("X5 Y5#R5 C180#M02#"), {-5, 0, 0});
}

TEST(RomiPolarLine, IJMoveTheCentreForThisBlockOnly) {
  expect_near(last_end("X20 Y10#R5 I10 J10#M02#"), {15, 10, 0});
  expect_near(last_end("X20 Y10#C90 I10 J10#M02#"), {10, 20, 0});
  expect_near(last_end("X20 Y10#R3 C0 I10 J10#M02#"), {13, 10, 0});
  // The next block's centre is program zero again.
  expect_near(last_end("X20 Y10#C90 I10 J10#C0#M02#"), {std::hypot(10, 20), 0, 0});
}

TEST(RomiPolarLine, ZMayAccompanyAnyForm) {
  expect_near(last_end("X10#C90 Z-3#M02#"), {0, 10, -3});
}

TEST(RomiPolarLine, PolarWordsWithXYAreAnError) {
  auto r = run_romi("X10#R5 X3#M02#");
  EXPECT_EQ(r->first_error(), Code::PolarWithXy);
}

TEST(RomiPolarLine, AWithoutRIsAnError) {
  auto r = run_romi("X10#A45#M02#");
  EXPECT_EQ(r->first_error(), Code::MissingWord);
}

TEST(RomiPolarArc, CIJSweepsAboutTheCentre) {
  auto r = run_romi("X20 Y10#G03 C90 I10 J10 F100#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto a = r->all<canon::Arc>();
  ASSERT_EQ(a.size(), 1u);
  expect_near(a[0].to, {10, 20, 0});
  expect_near(a[0].center, {10, 10, 0});
  EXPECT_EQ(a[0].turn, 1);
}

TEST(RomiPolarArc, CAloneIsAboutProgramZero) {
  auto r = run_romi("X10#G02 C90 F100#M02#");
  const auto a = r->all<canon::Arc>();
  ASSERT_EQ(a.size(), 1u);
  expect_near(a[0].to, {0, -10, 0});
  EXPECT_EQ(a[0].turn, -1);
}

TEST(RomiPolarArc, RCIsTangentToThePreviousMove) {
  // As the seed's N0100: along +X, then G02 R70 C90.
  auto r = run_romi("G01 X10 F100#G02 R5 C90#M02#");
  const auto a = r->all<canon::Arc>();
  ASSERT_EQ(a.size(), 1u);
  expect_near(a[0].center, {10, -5, 0});
  expect_near(a[0].to, {15, -5, 0});
}

TEST(RomiPolarArc, RAEndsWhenTravelPointsAlongA) {
  auto r = run_romi("G01 X10 F100#G03 R5 A90#M02#");
  const auto a = r->all<canon::Arc>();
  ASSERT_EQ(a.size(), 1u);
  expect_near(a[0].center, {10, 5, 0});
  expect_near(a[0].to, {15, 5, 0});
}

TEST(RomiPolarArc, RACStartsTangentToA) {
  auto r = run_romi("G03 R5 A90 C180 F100#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto a = r->all<canon::Arc>();
  ASSERT_EQ(a.size(), 1u);
  expect_near(a[0].center, {-5, 0, 0});
  expect_near(a[0].to, {-10, 0, 0});
}

TEST(RomiPolarArc, RAloneBlendsIntoTheNextMove) {
  auto r = run_romi("G01 X10 F100#G03 R10#G01 X30 Y30#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto a = r->all<canon::Arc>();
  ASSERT_EQ(a.size(), 1u);
  const Vec3 c{10, 10, 0};
  expect_near(a[0].center, c);
  const Vec3 t = a[0].to;
  EXPECT_NEAR(std::hypot(t.x - c.x, t.y - c.y), 10, 1e-9);
  // The line from the tangent point to (30, 30) is perpendicular to the radius.
  EXPECT_NEAR((30 - t.x) * (t.x - c.x) + (30 - t.y) * (t.y - c.y), 0, 1e-9);
  // ... and leaves in the arc's (counter-clockwise) direction of travel.
  EXPECT_GT((30 - t.x) * -(t.y - c.y) + (30 - t.y) * (t.x - c.x), 0);
  expect_near(r->ends().back(), {30, 30, 0});
}

// A romi program is written a block a line, each ended by '#': nothing
// stands between the '#' and the newline, and the blend goes on to the
// next line's move (it was an error at that empty "block").
TEST(RomiPolarArc, ABlendAtALineEndBlendsIntoTheNextLinesMove) {
  auto lines = run_romi("G01 X10 F100#\nG03 R10#\n\nG01 X30 Y30#\nM02#\n");
  ASSERT_TRUE(lines->ok) << lines->first_error_text();
  auto one_line = run_romi("G01 X10 F100#G03 R10#G01 X30 Y30#M02#");
  ASSERT_TRUE(one_line->ok) << one_line->first_error_text();
  const auto a = lines->all<canon::Arc>();
  const auto b = one_line->all<canon::Arc>();
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), 1u);
  expect_near(a[0].to, b[0].to);
  expect_near(lines->ends().back(), {30, 30, 0});
  // A block with a comment is a block: the blend needs the move there.
  EXPECT_EQ(run_romi("G01 X10 F100#G03 R10#;a note#G01 X30 Y30#M02#")->first_error(),
            Code::BlendNeedsMove);
}

TEST(RomiPolarArc, BlendWithNoMoveAfterIsAnError) {
  auto r = run_romi("G01 X10 F100#G03 R10#G80#M02#");
  EXPECT_EQ(r->first_error(), Code::BlendNeedsMove);
  auto end = run_romi("G01 X10 F100#G03 R10#M02#");
  EXPECT_EQ(end->first_error(), Code::BlendNeedsMove);
}

TEST(RomiPolarArc, BlendIntoAnIncrementalMoveIsAnError) {
  auto r = run_romi("G01 X10 F100#G03 R10#G01 x20 Y30#M02#");
  EXPECT_EQ(r->first_error(), Code::BlendNeedsMove);
}

TEST(RomiPolarArc, TangentArcWithNoPreviousMoveIsAnError) {
  auto r = run_romi("G02 R5 C90 F100#M02#");
  EXPECT_EQ(r->first_error(), Code::NoTangentDirection);
}

// The direction of travel a tangent arc starts in: the last straight
// move's (here +Y, not +X), then the end tangent of the arc before it.
TEST(RomiPolarArc, TangentArcsFollowTheMoveAndTheArcBefore) {
  auto r = run_romi("G01 F100 X0 Y10#G03 R5 C90#G03 R5 C90#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto a = r->all<canon::Arc>();
  ASSERT_EQ(a.size(), 2u);
  expect_near(a[0].center, {-5, 10, 0});
  expect_near(a[0].to, {-5, 15, 0});
  expect_near(a[1].center, {-5, 10, 0});  // the same circle on
  expect_near(a[1].to, {-10, 10, 0});
}

TEST(RomiPolarArc, XYIJHasAnAbsoluteCentre) {
  auto r = run_romi("X20 Y10#G02 X30 Y10 I25 J10 F100#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto a = r->all<canon::Arc>();
  ASSERT_EQ(a.size(), 1u);
  expect_near(a[0].center, {25, 10, 0});
  EXPECT_EQ(a[0].turn, -1);
}

TEST(RomiPolarArc, EndOffTheCircleIsAnError) {
  auto ok = run_romi("G02 X10.009 Y0 I5 J0 F100#M02#");
  EXPECT_TRUE(ok->ok);
  auto r = run_romi("G02 X10.02 Y0 I5 J0 F100#M02#");
  EXPECT_EQ(r->first_error(), Code::ArcRadiusMismatch);
}

TEST(RomiPolarArc, XYRTakesTheShorterArcAndNegativeTheLonger) {
  auto r = run_romi("G02 X10 Y0 R10 F100#G00 X0 Y0#G02 X10 Y0 R-10#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto a = r->all<canon::Arc>();
  ASSERT_EQ(a.size(), 2u);
  EXPECT_LT(a[0].center.y, 0);  // clockwise, short way: centre below the chord
  EXPECT_GT(a[1].center.y, 0);
}

TEST(RomiPolarArc, RadiusTooSmallIsAnError) {
  auto r = run_romi("G02 X10 Y0 R4 F100#M02#");
  EXPECT_EQ(r->first_error(), Code::ArcRadiusTooSmall);
}

TEST(RomiPolarArc, Sweep360IsAFullCircle) {
  auto r = run_romi("X10#G03 C360 I0 J0 F100#M02#");
  const auto a = r->all<canon::Arc>();
  ASSERT_EQ(a.size(), 1u);
  expect_near(a[0].to, {10, 0, 0});
  EXPECT_EQ(a[0].turn, 1);
}

TEST(RomiPolarArc, ArcNeedsAFeed) {
  auto r = run_romi("X10#G03 C90#M02#");
  EXPECT_EQ(r->first_error(), Code::NoFeedRate);
}

TEST(RomiPolarArc, ArcWithXYAndCIsAnError) {
  auto r = run_romi("G03 X10 Y0 C90 F100#M02#");
  EXPECT_EQ(r->first_error(), Code::PolarWithXy);
}

}  // namespace
}  // namespace usina::gcode::romi_test
