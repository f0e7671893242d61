// The romi dialect's tool change, compensation register, cycles, patterns,
// pocket and transformations (spec/romi.md).
#include <cmath>

#include "romi_test_support.hpp"

namespace usina::gcode::romi_test {
namespace {

using core::Code;

InterpOptions with_tool(int number, double diameter) {
  InterpOptions o;
  ToolEntry t;
  t.number = number;
  t.diameter = diameter;
  o.tools.set(t);
  return o;
}

TEST(RomiToolChange, DiameterFromTheComment) {
  for (const char* c : {";fresa d10", ";broca d10mm", ";D10"}) {
    auto r = run_romi(std::string("T01 M06") + c + "#M02#");
    ASSERT_TRUE(r->ok) << c << ": " << r->first_error_text();
    const auto t = r->all<canon::ToolChange>();
    ASSERT_EQ(t.size(), 1u);
    EXPECT_EQ(t[0].tool, 1);
    EXPECT_EQ(t[0].diameter, 10.0);
  }
}

TEST(RomiToolChange, TheToolTableComesFirst) {
  auto r = run_romi("T03 M06;fresa d10#M02#", with_tool(3, 6));
  const auto t = r->all<canon::ToolChange>();
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].diameter, 6.0);
}

TEST(RomiToolChange, UnknownDiameterIsAnErrorNamingTheTool) {
  auto r = run_romi("T03 M06;fresa#M02#");
  EXPECT_EQ(r->first_error(), Code::UnknownToolDiameter);
  EXPECT_NE(r->first_error_text().find("T03"), std::string::npos);
}

TEST(RomiToolChange, XYIsTheChangePositionAndTheProgramGoesOn) {
  auto r = run_romi("G00 X500 Y280#X10 Y-50 T02 M06;broca d20mm#G91 X100#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto& ops = r->path.ops();
  // traverse, traverse to the change position, tool, traverse back, traverse.
  ASSERT_EQ(r->ends().size(), 4u);
  expect_near(r->ends()[1], {10, -50, 0});
  expect_near(r->ends()[2], {500, 280, 0});
  expect_near(r->ends()[3], {600, 280, 0});
  int excursion = 0;
  for (const canon::Op& op : ops) {
    if (op.origin == canon::Origin::ToolChange) ++excursion;
  }
  EXPECT_EQ(excursion, 3);  // there, the change, back
}

// usina draw --start: the tool starts there, and a lower-case increment or
// an omitted axis counts from it (romi's own point once ignored it).
TEST(RomiStart, TheToolStartsWhereTheRunSays) {
  InterpOptions o;
  o.start = {5, 5, 5};
  auto r = run_romi("G00 x10#G01 Y0 F100#M02#", o);
  ASSERT_TRUE(r->ok) << r->first_error_text();
  ASSERT_EQ(r->ends().size(), 2u);
  expect_near(r->ends()[0], {15, 5, 5});
  expect_near(r->ends()[1], {15, 0, 5});
}

TEST(RomiToolChange, M06WithoutTIsAnError) {
  auto r = run_romi("M06#M02#");
  EXPECT_EQ(r->first_error(), Code::MissingWord);
}

TEST(RomiComp, G41RadiusFromTheORegister) {
  auto r = run_romi("T1 M06;d10#O5#G41#G01 X0 Y10 F100#G40#M02#", with_tool(5, 4));
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_near(r->all<canon::Feed>()[0].to, {-2, 10, 0});
}

TEST(RomiComp, RadiusOfTheToolInTheSpindleWithoutATableEntry) {
  auto r = run_romi("T1 M06;d10#O5#G42#G01 X0 Y10 F100#G40#M02#");
  expect_near(r->all<canon::Feed>()[0].to, {5, 10, 0});
  auto tool =
      run_romi("T1 M06;d10#O5#G41#G01 X0 Y10 F100#G40#M02#", with_tool(5, 4), {"comp_radius=tool"});
  expect_near(tool->all<canon::Feed>()[0].to, {-5, 10, 0});
}

// The words reach the interpreter in millimetres: a concave corner gets
// LinuxCNC's metric slack (its G21 rule). This corner after an arc is a
// hair too tight for the 10 mm tool by the inch rule, within the metric one.
TEST(RomiComp, AConcaveCornerWithinTheMetricSlackIsNoGouge) {
  auto r = run_romi(
      "F605#T1 M06 ;tool d10#G00 X-36.546 Z20.686#G42 O3 G01 X5.532 Y8.815#"
      "G00 X-43.191 Y19.469#G3 X-18.473 Y-5.974 R-31.478#G00 Y-17.05#G40 X-18.473 Y-40#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  EXPECT_FALSE(r->has(Code::CutterGouge));
}

TEST(RomiDrill, G81IsModalUntilG80AndMakesHoles) {
  auto r = run_romi("T2 M06;d20#G81 R2 Z-40 D1.5 F150#X100 Y0#X200#G80#X300#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto h = r->all<canon::Hole>();
  ASSERT_EQ(h.size(), 2u);
  expect_near(h[0].at, {100, 0, 0});
  expect_near(h[1].at, {200, 0, 0});
  EXPECT_EQ(h[0].diameter, 20.0);
  EXPECT_EQ(h[0].depth, 40.0);  // the sign ignored, with a note
  EXPECT_TRUE(r->has(Code::DepthSignIgnored));
  EXPECT_EQ(r->all<canon::Dwell>().size(), 2u);
  bool bottom = false;
  for (const canon::Op& op : r->path.ops()) {
    if (const auto* f = std::get_if<canon::Feed>(&op.kind)) {
      bottom = bottom || f->to.z == -40;
      EXPECT_EQ(op.origin, canon::Origin::Cycle);
    }
  }
  EXPECT_TRUE(bottom);
  expect_near(r->ends().back(), {300, 0, 2});  // after G80 a plain move, from the R plane
}

TEST(RomiDrill, MotionCodeCancelsTheCycleOnlyWhenAsked) {
  const char* prog = "T2 M06;d20#G81 R2 Z40 F150#G00 X100#M02#";
  EXPECT_EQ(run_romi(prog)->all<canon::Hole>().size(), 1u);
  EXPECT_EQ(run_romi(prog, {}, {"motion_cancels_cycle=on"})->all<canon::Hole>().size(), 0u);
}

TEST(RomiDrill, G98RetractsToTheStartingHeight) {
  auto r = run_romi("T2 M06;d20#G00 Z10#G98 G81 R2 Z5 F100 X10#G99 X20#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto t = r->all<canon::Traverse>();
  // G98: back up to Z10 after the first hole; G99: only to the R plane.
  bool up_to_start = false;
  for (const canon::Traverse& m : t)
    up_to_start = up_to_start || (m.to.x == 10 && m.to.z == 10);
  EXPECT_TRUE(up_to_start);
  expect_near(r->ends().back(), {20, 0, 2});
}

// G81 refuses compensation when it starts; a G41 given while it is on
// would offset the approach of its holes and nothing of them.
TEST(RomiDrill, AHoleWithCompensationOnIsAnError) {
  auto r = run_romi("T2 M06;d20#G81 R2 Z5 F100#G41 X10 Y10#M02#");
  EXPECT_EQ(r->first_error(), Code::CompNotAllowed);
  EXPECT_NE(r->first_error_text().find("G40 first"), std::string::npos);
  EXPECT_TRUE(r->all<canon::Hole>().empty());
  EXPECT_TRUE(run_romi("T2 M06;d2#G81 R2 Z5 F100#X10 Y10#G80#G41 X20#G40 X30#M02#")->ok);
}

TEST(RomiDrill, HoleWithNoToolIsAnError) {
  auto r = run_romi("G81 R2 Z5 F100 X10#M02#");
  EXPECT_EQ(r->first_error(), Code::UnknownToolDiameter);
}

TEST(RomiDrill, G81NeedsADepth) {
  auto r = run_romi("T2 M06;d20#G81 R2 F150#M02#");
  EXPECT_EQ(r->first_error(), Code::MissingWord);
}

TEST(RomiPattern, G25GridRowByRowAlternating) {
  auto r = run_romi("T2 M06;d20#X500 Y280#G81 R2 Z40 F150#G25 X100 Y-80 I4 J3#G80#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto h = r->all<canon::Hole>();
  ASSERT_EQ(h.size(), 12u);
  const double want[12][2] = {{500, 280}, {600, 280}, {700, 280}, {800, 280},
                              {800, 200}, {700, 200}, {600, 200}, {500, 200},
                              {500, 120}, {600, 120}, {700, 120}, {800, 120}};
  for (std::size_t i = 0; i < 12; ++i)
    expect_near(h[i].at, {want[i][0], want[i][1], 0});
}

TEST(RomiPattern, G25WithoutACycleOnlyPositions) {
  auto r = run_romi("G25 X10 I3 J1#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  EXPECT_EQ(r->all<canon::Hole>().size(), 0u);
  expect_near(r->ends().back(), {20, 0, 0});
}

TEST(RomiPattern, G24BoltCircleCounterClockwise) {
  auto r = run_romi("T2 M06;d8#X60 Y50#G81 R2 Z10 F100#G24 I50 J50 K4 L3#G80#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto h = r->all<canon::Hole>();
  ASSERT_EQ(h.size(), 3u);
  expect_near(h[0].at, {60, 50, 0});
  expect_near(h[1].at, {50, 60, 0});
  expect_near(h[2].at, {40, 50, 0});
}

TEST(RomiPattern, G24StartAngleC) {
  auto r = run_romi("X60 Y50#G24 I50 J50 K4 L1 C90#M02#");
  expect_near(r->ends().back(), {50, 60, 0});
}

TEST(RomiPocket, OutlineFeatureAndCycleMoves) {
  auto r = run_romi("T1 M06;d10#G X250 Y220#G26 X400 Y300 Z-25 L2 D3 F100#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto p = r->all<canon::Pocket>();
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].depth, 25.0);
  EXPECT_EQ(p[0].outline.start.x, 400.0);
  EXPECT_EQ(p[0].outline.segs.size(), 9u);  // four sides, four R5 corners, closing half side
  int deepest = 0;
  for (const canon::Op& op : r->path.ops()) {
    if (const auto* f = std::get_if<canon::Feed>(&op.kind)) {
      EXPECT_EQ(op.origin, canon::Origin::Cycle);
      EXPECT_GE(f->to.x, 255 - 1e-9);  // the tool's edge stays inside the pocket
      EXPECT_LE(f->to.y, 295 + 1e-9);
      if (f->to.z == -25) ++deepest;
    }
  }
  EXPECT_GT(deepest, 0);
  expect_near(r->ends().back(), {250, 220, 0});
}

TEST(RomiPocket, AllowancesLeaveTheFinishToTheLastPass) {
  // 40 × 40 pocket, d10 tool: the wall pass runs 5 mm inside (5..35); with
  // I2 J2 K1 the roughing rings stop at 7..33 and at Z−9 of Z−10.
  auto r = run_romi("T1 M06;d10#G26 X40 Y40 Z10 I2 J2 K1 D2 L3 F100#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  double lowest_rough = 0;
  double widest_rough = 0;
  double widest = 0;
  for (const canon::Feed& f : r->all<canon::Feed>()) {
    widest = std::max(widest, f.to.x);
    if (f.to.z > -10 + 1e-9) {
      lowest_rough = std::min(lowest_rough, f.to.z);
      widest_rough = std::max(widest_rough, f.to.x);
    }
  }
  EXPECT_NEAR(lowest_rough, -9, 1e-9);
  EXPECT_NEAR(widest_rough, 33, 1e-9);
  EXPECT_NEAR(widest, 35, 1e-9);
}

TEST(RomiPocket, CircularWhenRIsHalfTheSide) {
  auto r = run_romi("T1 M06;d10#G26 X40 Y40 Z5 R20 F100#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  const auto p = r->all<canon::Pocket>();
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].outline.segs.size(), 4u);  // four quarter circles
}

TEST(RomiPocket, CornerRadiusSmallerThanTheToolIsAnError) {
  auto r = run_romi("T1 M06;d10#G26 X40 Y40 Z5 R4 F100#M02#");
  EXPECT_EQ(r->first_error(), Code::PocketTooSmall);
}

TEST(RomiPocket, PocketNarrowerThanTheToolIsAnError) {
  auto r = run_romi("T1 M06;d10#G26 X8 Y40 Z5 F100#M02#");
  EXPECT_NE(r->first_error(), Code::Message);
}

TEST(RomiTransform, MirrorOneAxisSwapsArcs) {
  auto r = run_romi("G31 X0#G00 X10#G02 C90 F100#G30#M02#");
  ASSERT_TRUE(r->ok) << r->first_error_text();
  expect_near(r->ends()[0], {-10, 0, 0});
  const auto a = r->all<canon::Arc>();
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].turn, 1);
  expect_near(a[0].to, {0, -10, 0});
}

TEST(RomiTransform, MirrorBothAxesKeepsArcs) {
  auto r = run_romi("G31 X0 Y0#G00 X10#G02 C90 F100#M02#");
  const auto a = r->all<canon::Arc>();
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].turn, -1);
  expect_near(a[0].to, {0, 10, 0});
}

TEST(RomiTransform, G31NeedsAnAxis) {
  EXPECT_EQ(run_romi("G31#M02#")->first_error(), Code::MissingWord);
}

TEST(RomiTransform, MirrorSwapsCompensationSides) {
  auto r = run_romi("T1 M06;d10#G31 X0#G41#G01 X0 Y10 F100#G40#M02#");
  // Mirrored in X, G41 works as G42: the tool on the +X side of a +Y move.
  expect_near(r->all<canon::Feed>()[0].to, {5, 10, 0});
}

TEST(RomiTransform, ScaleAndItsLimits) {
  expect_near(run_romi("G72 K2#X10 Y5#M02#")->ends().back(), {20, 10, 0});
  expect_near(run_romi("G72 X2 Y0.5#X10 Y10#M02#")->ends().back(), {20, 5, 0});
  EXPECT_EQ(run_romi("G72 K25#M02#")->first_error(), Code::ScaleOutOfRange);
  EXPECT_EQ(run_romi("G72 X0.01#M02#")->first_error(), Code::ScaleOutOfRange);
  EXPECT_EQ(run_romi("G72 X2 Y1#X10#G03 C90 F100#M02#")->first_error(), Code::UnequalScaleArc);
  expect_near(run_romi("G72 K2#G72 K1#X10#M02#")->ends().back(), {10, 0, 0});
}

TEST(RomiTransform, PocketUnderUnequalScaleIsAnError) {
  auto r = run_romi("T1 M06;d10#G72 X2 Y1#G26 X40 Y40 Z5 F100#M02#");
  EXPECT_EQ(r->first_error(), Code::UnequalScaleArc);
}

// An arc starts where the last move left the tool. A rotation (mirror,
// scale) given since then moves the programmed point, not the tool: the
// arc's start is off its circle, and romi says why, as the control would
// refuse the arc.
TEST(RomiTransform, AnArcAfterANewTransformationStartsWhereTheToolIs) {
  auto r = run_romi("G00 X10 Y0#G73 C90#G03 X0 Y0 I5 J0 F100#M02#");
  EXPECT_EQ(r->first_error(), Code::ArcRadiusMismatch);
  EXPECT_NE(r->first_error_text().find("changed since that move"), std::string::npos)
      << r->first_error_text();
  // A move to a point first: the arc is whole.
  auto ok = run_romi("G00 X10 Y0#G73 C90#G00 X10 Y0#G03 X0 Y0 I5 J0 F100#M02#");
  ASSERT_TRUE(ok->ok) << ok->first_error_text();
  expect_near(ok->ends().back(), {0, 0, 0});
  // A rotation about the tool's own point changes nothing of its start.
  EXPECT_TRUE(run_romi("G00 X10 Y0#G73 C90 I10 J0#G03 X0 Y0 I5 J0 F100#M02#")->ok);
}

TEST(RomiTransform, RotationAboutIJ) {
  expect_near(run_romi("G73 C90 I10 J0#X20#M02#")->ends().back(), {10, 10, 0});
  expect_near(run_romi("G73 C90#G73 C0#X20#M02#")->ends().back(), {20, 0, 0});
}

TEST(RomiTransform, OrderIsRotationScaleMirror) {
  // (10, 0) rotated 90 → (0, 10), scaled 2 → (0, 20), mirrored about Y = 5 → (0, -10).
  expect_near(run_romi("G73 C90#G72 K2#G31 Y5#X10#M02#")->ends().back(), {0, -10, 0});
}

}  // namespace
}  // namespace usina::gcode::romi_test
