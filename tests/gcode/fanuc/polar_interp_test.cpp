// The fanuc dialect's G12.1/G13.1 polar coordinate interpolation
// (docs/fanuc.md §7): a contour in the virtual X-C plane becomes machine
// moves of X (the radius) and C (the angle) whose path, mapped back by
// (X cos C, X sin C), stays within kPolarChordTolerance of the contour;
// entering and leaving the mode; every alarm.
#include "gcode/fanuc/polar_interp.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "fanuc_test_support.hpp"

namespace usina::gcode::fanuc_test {
namespace {

using core::Code;
using core::Vec2;
using fanuc::kPolarChordTolerance;

constexpr double kRad = std::numbers::pi / 180.0;

struct Machine {
  double x, c, z;
};

// The feed moves' X, C and Z (every feed of these programs is in G12.1).
std::vector<Machine> feeds(const Run& r) {
  std::vector<Machine> out;
  for (const canon::Feed& f : r.all<canon::Feed>())
    out.push_back({f.to.x, f.abc[2], f.to.z});
  return out;
}

Vec2 virtual_of(double x, double c_deg, double zero = 0) {
  return {x * std::cos((c_deg - zero) * kRad), x * std::sin((c_deg - zero) * kRad)};
}

double segment_distance(Vec2 a, Vec2 b, Vec2 q) {
  const Vec2 ab = b - a;
  const double len2 = ab.x * ab.x + ab.y * ab.y;
  const double t = std::clamp(((q.x - a.x) * ab.x + (q.y - a.y) * ab.y) / len2, 0.0, 1.0);
  const Vec2 d = q - (a + ab * t);
  return std::hypot(d.x, d.y);
}

double polyline_distance(const std::vector<Vec2>& poly, Vec2 q) {
  double best = 1e300;
  for (std::size_t i = 0; i + 1 < poly.size(); ++i)
    best = std::min(best, segment_distance(poly[i], poly[i + 1], q));
  return best;
}

// Every machine move, sampled as the machine runs it (X and C together in a
// straight line), maps back within the tolerance of `distance`; C never
// jumps.
template <typename Distance>
void expect_follows(const std::vector<Machine>& m, Machine from, Distance distance) {
  Machine a = from;
  for (const Machine& b : m) {
    EXPECT_LE(std::fabs(b.c - a.c), 90.0 + 1e-9);  // no jump: a quarter turn at most
    for (int k = 0; k <= 16; ++k) {
      const double s = k / 16.0;
      const Vec2 q = virtual_of(a.x + (b.x - a.x) * s, a.c + (b.c - a.c) * s);
      ASSERT_LE(distance(q), kPolarChordTolerance + 1e-9) << "at (" << q.x << ", " << q.y << ")";
    }
    a = b;
  }
}

// --- the contour --------------------------------------------------------

TEST(FanucPolarInterp, SquareLiesOnTheSquare) {
  // From X20 C0: in to (10, 0), then the square of side 20 about the centre
  // counter-clockwise, back to (10, 0) and out to (20, 0).
  auto r = run_fanuc(
      "G0 X20. C0 Z0\nG12.1\nG1 X10. F100.\nC10.\nX-10.\nC-10.\nX10.\nC0\nX20.\nG13.1\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const std::vector<Vec2> square{{20, 0},    {10, 0},   {10, 10}, {-10, 10},
                                 {-10, -10}, {10, -10}, {10, 0},  {20, 0}};
  const auto m = feeds(*r);
  ASSERT_GT(m.size(), 8u);  // the sides are split
  expect_follows(m, {20, 0, 0}, [&](Vec2 q) { return polyline_distance(square, q); });
  // Each corner is a machine point: (10, 10) is X = 10√2 at C = 45°.
  bool corner = false;
  for (const Machine& p : m)
    corner = corner || (std::fabs(p.x - 10 * std::sqrt(2.0)) < 1e-9 && std::fabs(p.c - 45) < 1e-9);
  EXPECT_TRUE(corner);
  // Once round the centre: C ends at 360°, X at 20; the feed is F.
  EXPECT_NEAR(m.back().x, 20, 1e-9);
  EXPECT_NEAR(m.back().c, 360, 1e-9);
  EXPECT_DOUBLE_EQ(*r->all<canon::Feed>().front().f, 100);
}

TEST(FanucPolarInterp, ArcOffTheCentreStaysOnItsCircle) {
  // G02 from (10, 0) about (10, 5) (J5.) to (10, 10): the half circle of
  // radius 5 on the left, through (5, 5).
  auto r = run_fanuc("G0 X10. C0\nG12.1\nG2 X10. C10. I0 J5. F50.\nG13.1\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto m = feeds(*r);
  expect_follows(m, {10, 0, 0}, [](Vec2 q) {
    const double d = std::fabs(std::hypot(q.x - 10, q.y - 5) - 5);
    return q.x <= 10 + 1e-9 ? d : 1e9;  // the left half only
  });
  const Vec2 end = virtual_of(m.back().x, m.back().c);
  EXPECT_NEAR(end.x, 10, 1e-9);
  EXPECT_NEAR(end.y, 10, 1e-9);
}

TEST(FanucPolarInterp, ArcByRadiusAboutTheCentreTurnsCOnly) {
  // G03 R10. from (10, 0) to (-10, 0)... would be a half circle about the
  // centre; to (0, 10): a quarter. X stays 10, C goes 0 -> 90.
  auto r = run_fanuc("G0 X10. C0\nG12.1\nG3 X0 C10. R10. F50.\nG13.1\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  for (const Machine& p : feeds(*r))
    EXPECT_NEAR(p.x, 10, 1e-9);
  EXPECT_NEAR(feeds(*r).back().c, 90, 1e-9);
}

TEST(FanucPolarInterp, FullCircleAroundTheCentreWindsCOn) {
  // G03 I-10. from (10, 0): once round the centre, C 0 -> 360 (no jump).
  auto r = run_fanuc("G0 X10. C0\nG12.1\nG3 I-10. F50.\nG3 I-10.\nG13.1\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto m = feeds(*r);
  expect_follows(m, {10, 0, 0}, [](Vec2 q) { return std::fabs(std::hypot(q.x, q.y) - 10); });
  EXPECT_NEAR(m.back().c, 720, 1e-9);  // twice round
}

TEST(FanucPolarInterp, FullCircleBesideTheCentre) {
  // G02 I-3. from (10, 0): the circle of radius 3 about (7, 0), clockwise.
  auto r = run_fanuc("G0 X10. C0\nG12.1\nG2 I-3. F50.\nG13.1\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto m = feeds(*r);
  expect_follows(m, {10, 0, 0}, [](Vec2 q) { return std::fabs(std::hypot(q.x - 7, q.y) - 3); });
  EXPECT_NEAR(m.back().x, 10, 1e-9);
  EXPECT_NEAR(m.back().c, 0, 1e-9);  // the circle does not go round the centre
}

TEST(FanucPolarInterp, NearTheCentreTheLineIsStillFollowed) {
  // The manual's example: (10, 0.1) to (-10, 0.1) passes 0.1 mm from the
  // centre; C turns about 179° in the middle, X stays positive.
  auto r = run_fanuc("G0 X10. C0\nG12.1\nG1 C0.1 F1000.\nX-10.\nG13.1\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto m = feeds(*r);
  expect_follows(m, {10, 0, 0}, [](Vec2 q) {
    return std::min(segment_distance({10, 0}, {10, 0.1}, q),
                    segment_distance({10, 0.1}, {-10, 0.1}, q));
  });
  for (const Machine& p : m)
    EXPECT_GT(p.x, 0);
  EXPECT_NEAR(m.back().c, 180 - std::atan2(0.1, 10) / kRad, 1e-9);
}

// --- entering and leaving -------------------------------------------------

TEST(FanucPolarInterp, TheRotaryZeroIsWhereG121Found_C) {
  // C at 30° when G12.1 comes: that is angle 0, the virtual C is 0 there.
  // C5. -> (20, 5): X = √425, C = 30° + atan(5/20).
  auto r = run_fanuc("G0 X20. C30.\nG12.1\nG1 C5. F100.\nG13.1\nG0 X30. C45.\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto m = feeds(*r);
  EXPECT_NEAR(m.back().x, std::sqrt(425.0), 1e-9);
  EXPECT_NEAR(m.back().c, 30 + std::atan2(5.0, 20.0) / kRad, 1e-9);
  // After G13.1 X and C are plain axes again.
  const auto& t = r->all<canon::Traverse>().back();
  EXPECT_NEAR(t.to.x, 30, 1e-9);
  EXPECT_NEAR(t.abc[2], 45, 1e-9);
}

TEST(FanucPolarInterp, NegativeSideKeepsXNegative) {
  // at G12.1: the tool works on the negative side. (-20, 5) is
  // X = -√425 with the part turned by -atan(5/20).
  auto r = run_fanuc("G0 X-20. C0\nG112\nG1 C5. F100.\nG113\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto m = feeds(*r);
  EXPECT_NEAR(m.back().x, -std::sqrt(425.0), 1e-9);
  EXPECT_NEAR(m.back().c, -std::atan2(5.0, 20.0) / kRad, 1e-9);
  const Vec2 v = virtual_of(m.back().x, m.back().c);
  EXPECT_NEAR(v.x, -20, 1e-9);
  EXPECT_NEAR(v.y, 5, 1e-9);
}

TEST(FanucPolarInterp, IncrementalAndTheOtherAxesMoveAlong) {
  // G91 in the mode: C5. then X-10. from (20, 0) -> (20, 5) -> (10, 5);
  // Z-4. in the second block moves with it, in proportion. G91 stays.
  auto r = run_fanuc("G0 X20. C0 Z0\nG12.1\nG91 G1 C5. F100.\nX-10. Z-4.\nG13.1\nZ1.\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto m = feeds(*r);
  const Vec2 v = virtual_of(m[m.size() - 2].x, m[m.size() - 2].c);
  EXPECT_NEAR(v.x, 10, 1e-9);
  EXPECT_NEAR(v.y, 5, 1e-9);
  EXPECT_NEAR(m[m.size() - 2].z, -4, 1e-9);
  for (std::size_t i = 1; i + 1 < m.size(); ++i)
    EXPECT_LE(m[i].z, m[i - 1].z + 1e-12);  // Z goes down steadily
  EXPECT_NEAR(m.back().z, -3, 1e-9);        // G1 Z1. in G91 after G13.1
}

TEST(FanucPolarInterp, InchVirtualAxis) {
  // G20: the virtual C is in inches too. (1, 1) in is X = √2 in at 45°.
  auto r = run_fanuc("G20\nG0 X1. C0\nG12.1\nG1 C1. F10.\nG13.1\nM30\n");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto& f = r->all<canon::Feed>().back();
  EXPECT_NEAR(f.to.x, std::sqrt(2.0) * 25.4, 1e-9);
  EXPECT_NEAR(f.abc[2], 45, 1e-9);
}

TEST(FanucPolarInterp, OtherPolarAxes) {
  // polar_axes=XB: B carries the virtual axis.
  auto r = run_fanuc("G0 X20. B0\nG12.1\nG1 B5. F100.\nG13.1\nM30\n", {}, {"polar_axes=XB"});
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto& f = r->all<canon::Feed>().back();
  EXPECT_NEAR(f.to.x, std::sqrt(425.0), 1e-9);
  EXPECT_NEAR(f.abc[1], std::atan2(5.0, 20.0) / kRad, 1e-9);
}

TEST(FanucPolarInterp, ModalGroup21) {
  // #4021 is 12.1 in the mode, 13.1 outside (else the alarm stops the run).
  auto r = run_fanuc(
      "IF [#4021 NE 13.1] THEN #3000 = 1 (OFF)\nG0 X20. C0\nG12.1\n"
      "IF [#4021 NE 12.1] THEN #3000 = 2 (ON)\nG13.1\nM30\n");
  EXPECT_TRUE(r->ok) << r->first_error_text();
}

// --- alarms ---------------------------------------------------------------

Code error_of(const std::string& body, const std::vector<std::string>& options = {}) {
  auto r = run_fanuc("G0 X20. C0 Z0\n" + body + "\nM30\n", {}, options);
  EXPECT_FALSE(r->ok);
  return r->first_error();
}

TEST(FanucPolarInterpErrors, CodesNotAllowedInTheMode) {
  EXPECT_EQ(error_of("G12.1\nG0 X10."), Code::NotAllowedInMode);               // G00 (PS0146)
  EXPECT_EQ(error_of("G12.1\nX10."), Code::NotAllowedInMode);                  // modal G00
  EXPECT_EQ(error_of("G12.1\nG28 X0"), Code::NotAllowedInMode);                // reference return
  EXPECT_EQ(error_of("G12.1\nG17"), Code::NotAllowedInMode);                   // plane
  EXPECT_EQ(error_of("G12.1\nG54"), Code::NotAllowedInMode);                   // coordinate system
  EXPECT_EQ(error_of("G12.1\nG81 X0 Z-1. R1. F10."), Code::NotAllowedInMode);  // cycle
  EXPECT_EQ(error_of("G12.1\nG12.1"), Code::NotAllowedInMode);                 // twice
}

TEST(FanucPolarInterpErrors, G121AndG131StandAlone) {
  EXPECT_EQ(error_of("G12.1 G1 X10. F100."), Code::NotAllowedInMode);
  EXPECT_EQ(error_of("G12.1\nG1 X10. F100.\nG13.1 X20."), Code::NotAllowedInMode);
  EXPECT_EQ(error_of("G12.1 G13.1"), Code::NotAllowedInMode);
}

TEST(FanucPolarInterpErrors, StartConditions) {
  // G41 in force (PS0145), a canned cycle, G68 (not implemented together).
  EXPECT_EQ(error_of("G41 D0 G1 X30. F100.\nG12.1"), Code::NotAllowedInMode);
  EXPECT_EQ(error_of("G81 X20. Y0 Z-1. R1. F10.\nG12.1"), Code::NotAllowedInMode);
  EXPECT_EQ(error_of("G68 X0 Y0 R10.\nG12.1"), Code::Unsupported);
}

TEST(FanucPolarInterpErrors, CutterCompensationInTheModeIsNotImplemented) {
  EXPECT_EQ(error_of("G12.1\nG1 G42 X10. F100."), Code::Unsupported);
}

TEST(FanucPolarInterpErrors, ThroughTheCentre) {
  // A line through X0 C0, a circle through it, a start at it.
  EXPECT_EQ(error_of("G12.1\nG1 X-10. F100."), Code::PolarThroughCentre);
  EXPECT_EQ(error_of("G12.1\nG2 I-10. F100."), Code::PolarThroughCentre);
  auto r = run_fanuc("G0 X0 C0\nG12.1\nG1 X10. F100.\nM30\n");
  EXPECT_EQ(r->first_error(), Code::PolarThroughCentre);
}

TEST(FanucPolarInterpErrors, BadArcs) {
  EXPECT_EQ(error_of("G12.1\nG2 X10. C10. F100."), Code::ArcMissingCenter);
  EXPECT_EQ(error_of("G12.1\nG2 X10. C10. R2. F100."), Code::ArcRadiusTooSmall);
  EXPECT_EQ(error_of("G12.1\nG2 C10. R20. F100.\nG2 C10. R5."), Code::ArcZeroLength);
  EXPECT_EQ(error_of("G12.1\nG2 X10. C10. I0 J7. F100."), Code::ArcRadiusMismatch);
  EXPECT_EQ(error_of("G12.1\nG2 X10. I0 J0 F100."), Code::ArcZeroLength);
}

TEST(FanucPolarInterpErrors, AbsurdlyLongMoveIsBounded) {
  // A full circle of radius 10^9 mm (the largest in range) passing 20 mm
  // from the centre: far more than kMaxPolarPieces moves.
  EXPECT_EQ(error_of("G12.1\nG2 I-1000000000. F100."), Code::TooManyIterations);
  // Beyond the range of a word's value it is an error before any work.
  EXPECT_EQ(error_of("G12.1\nG2 I-10000000000. F100."), Code::ValueOutOfRange);
}

TEST(FanucPolarInterpErrors, NoFeedRate) {
  auto r = run_fanuc("G0 X20. C0\nG12.1\nG1 X10.\nM30\n");
  EXPECT_EQ(r->first_error(), Code::NoFeedRate);
}

// --- the geometry on its own ---------------------------------------------

TEST(FanucPolarGeometry, AxesOption) {
  const auto xc = fanuc::polar_axes_from("XC");
  ASSERT_TRUE(xc.has_value());
  EXPECT_EQ(xc->linear_letter(), 'X');
  EXPECT_EQ(xc->rotary_letter(), 'C');
  const auto zb = fanuc::polar_axes_from("zb");
  ASSERT_TRUE(zb.has_value());
  EXPECT_EQ(zb->centre_first(), 'K');
  EXPECT_EQ(zb->centre_second(), 'I');
  EXPECT_FALSE(fanuc::polar_axes_from("CX").has_value());
  EXPECT_FALSE(fanuc::polar_axes_from("X").has_value());
}

}  // namespace
}  // namespace usina::gcode::fanuc_test
