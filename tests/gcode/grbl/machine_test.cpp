// The grbl dialect's machine: Grbl's power-on G0 (an interpreter start
// option, not a patch of the text), soft limits (alarm 2, machine position =
// program + offsets + G43.1), homing with $23, and $RST= as Grbl's soft reset.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "gcode/grbl/machine_check.hpp"
#include "gcode/interp/interpreter.hpp"
#include "grbl_test_support.hpp"

namespace usina::gcode {
namespace {

using testing::run_grbl;

void expect_at(const core::Vec3& got, const core::Vec3& want) {
  EXPECT_NEAR(got.x, want.x, 1e-6);
  EXPECT_NEAR(got.y, want.y, 1e-6);
  EXPECT_NEAR(got.z, want.z, 1e-6);
}

const std::string kSoftLimits = "$22=1\n$20=1\n";

TEST(InterpStartMotion, IsADialectRule) {
  // A dialect's rule (DialectRules): G80 by default, anything a controller powers up in.
  for (const auto& [mode, kind] : {std::pair<GCode, const char*>{0, "traverse"}, {10, "feed"}}) {
    core::SourceManager sources;
    core::DiagnosticList diags;
    canon::Toolpath path;
    DialectRules rules;
    rules.start_motion = mode;
    Interpreter interp(sources, InterpOptions{}, path, diags, nullptr, rules);
    EXPECT_TRUE(interp.run(sources.add(core::SourceFile::from_string("t.ngc", "F100 X5\nM2\n"))));
    ASSERT_FALSE(path.ops().empty());
    EXPECT_EQ(canon::op_name(path.ops().front().kind), std::string(kind));
  }
  core::SourceManager sources;
  core::DiagnosticList diags;
  canon::Toolpath path;
  Interpreter interp(sources, InterpOptions{}, path, diags);
  EXPECT_FALSE(interp.run(sources.add(core::SourceFile::from_string("t.ngc", "X5\nM2\n"))));
}

TEST(GrblMachine, PowersUpInG0WithoutTouchingTheText) {
  auto r = run_grbl("G43.1 Z1\nX10 Y5\nG53 Z-1\n");
  EXPECT_TRUE(r->ok);
  const auto m = r->moves();
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].first, "traverse");
  expect_at(m[0].second, {10, 5, -1});  // the tool tip: 1 mm below machine Z0
}

TEST(GrblMachine, SoftLimitIsAlarm2AndEndsTheRun) {
  for (const char* mode : {"after_error=continue", "after_error=stop"}) {
    auto r = run_grbl(kSoftLimits + "G0 X-5\nG0 X1\nG0 X-10\nG1 X\n", {mode});
    EXPECT_FALSE(r->ok) << mode;
    const auto alarms = r->with(core::Code::GrblAlarm);
    ASSERT_EQ(alarms.size(), 1u) << mode;
    EXPECT_EQ(alarms[0]->loc.line, 4u);
    EXPECT_NE(alarms[0]->message.find("grbl ALARM:2 (Soft limit)"), std::string::npos);
    EXPECT_TRUE(r->with(core::Code::GrblError).empty()) << mode;  // line 6 is never read
    ASSERT_EQ(r->moves().size(), 1u) << mode;                     // the move before only
    expect_at(r->moves()[0].second, {-5, 0, 0});
  }
}

TEST(GrblMachine, SoftLimitsUseTheMachinePosition) {
  // Work offsets, G92 and G43.1 move the machine position; G53 is machine.
  auto fine = run_grbl(kSoftLimits +
                       "G10 L2 P1 X-100 Y-100 Z-50\nG0 X50 Y50 Z0\nG92 X0\nG0 X-100\nG43.1 Z10\nG0 "
                       "Z-10\nG53 G0 X-200 Y-200 Z-200\n");
  EXPECT_TRUE(fine->ok);
  EXPECT_EQ(fine->moves().size(), 4u);
  for (const char* beyond : {"G0 X101", "G0 Z51", "G43.1 Z60\nG0 Z-5", "G53 G0 Y-200.01",
                             "G92 X0\nG0 X1", "G1 Y-101 F100"}) {
    auto r = run_grbl(kSoftLimits + "G10 L2 P1 X-100 Y-100 Z-50\n" + beyond + "\n");
    EXPECT_EQ(r->with(core::Code::GrblAlarm).size(), 1u) << beyond;
  }
  // Soft limits off, or turned off with homing ($22=0): no check.
  for (const char* setup : {"", "$22=1\n$20=1\n$22=0\n", "$22=1\n$20=1\n$20=0\n"}) {
    auto r = run_grbl(std::string(setup) + "G0 X10\n");
    EXPECT_TRUE(r->ok) << setup;
  }
  // $130: the travel.
  auto wide = run_grbl(kSoftLimits + "$130=300\nG0 X-300\n");
  EXPECT_TRUE(wide->ok);
  auto narrow = run_grbl(kSoftLimits + "$131=10\nG0 Y-10.5\n");
  EXPECT_EQ(narrow->with(core::Code::GrblAlarm).size(), 1u);
}

TEST(GrblMachine, ArcsAreCheckedAlongTheirSegments) {
  // Both ends inside; the clockwise arc bulges over Y0, the other way not.
  auto over = run_grbl(kSoftLimits + "G0 X-20 Y-1\nG2 X-10 Y-1 R5 F100\n");
  ASSERT_EQ(over->with(core::Code::GrblAlarm).size(), 1u);
  EXPECT_EQ(over->with(core::Code::GrblAlarm)[0]->loc.line, 4u);
  auto under = run_grbl(kSoftLimits + "G0 X-20 Y-1\nG3 X-10 Y-1 R5 F100\n");
  EXPECT_TRUE(under->ok);
  // A probe's target too.
  auto probe = run_grbl(kSoftLimits + "G38.3 Z1 F100\n");
  EXPECT_EQ(probe->with(core::Code::GrblAlarm).size(), 1u);
}

// A straight move that went by unbuilt (usina check's sink reads no op)
// is where the next arc starts, whether soft limits are checked (the whole
// visit of the line's moves) or not (MachineCheck's shortcut for a plain
// line); after a probe too, whose end alone is unknown.
TEST(GrblMachine, AMoveThatWentByUnbuiltIsWhereTheNextArcStarts) {
  const core::SourceLoc src{0, 1, 1, 0, 0};
  for (const bool soft_limits : {false, true}) {
    // Inside the travel (machine space is negative) when it is checked.
    const core::Vec3 o = soft_limits ? core::Vec3{-100, -100, 0} : core::Vec3{0, 0, 0};
    grbl::MachineFacts facts;
    facts.travel.soft_limits = soft_limits;
    facts.travel.max = {1000, 1000, 1000};
    grbl::LineMoves probe;
    probe.built.push_back({canon::Probe{o + core::Vec3{0, 0, -5}, {}}, src});
    auto unbuilt = [&](double x) {
      grbl::LineMoves m;
      m.passed.push_back({0, src, o + core::Vec3{x, 0, 0}});
      return m;
    };
    // An arc about o to o + (0, 10): on its circle from o + (10, 0) only.
    grbl::LineMoves arc;
    arc.built.push_back(
        {canon::Arc{o + core::Vec3{0, 10, 0}, o, {0, 0, 1}, 1, 100.0, {}, {}}, src});
    grbl::MachineCheck check({0, 0, 0});
    EXPECT_FALSE(check.block(probe, facts)) << soft_limits;
    EXPECT_FALSE(check.block(unbuilt(5), facts)) << soft_limits;
    const std::optional<core::Diagnostic> off = check.block(arc, facts);  // 5 mm off its circle
    ASSERT_TRUE(off) << soft_limits;
    EXPECT_NE(off->message.find("error:33"), std::string::npos) << off->message;
    EXPECT_FALSE(check.block(unbuilt(10), facts)) << soft_limits;
    EXPECT_FALSE(check.block(arc, facts)) << soft_limits;
  }
}

TEST(GrblMachine, HomingIsNotCheckedAndFollows23) {
  // $23 bit set: that axis homes to its negative end: -travel + pull-off.
  auto r = run_grbl(kSoftLimits + "$23=5\n$130=300\n$H\nG0 X-1\n");
  EXPECT_TRUE(r->ok);
  const auto m = r->moves();
  ASSERT_EQ(m.size(), 2u);
  expect_at(m[0].second, {-299, -1, -199});
}

TEST(GrblMachine, ResetZeroesOffsetsAndRestoresPowerOnModes) {
  // $RST=#: G54 and the G28 position zero for the rest of the run.
  auto g54 = run_grbl("G10 L2 P1 X10\nG0 X0\n$RST=#\nG0 X0\n");
  ASSERT_EQ(g54->moves().size(), 2u);
  expect_at(g54->moves()[0].second, {10, 0, 0});
  expect_at(g54->moves()[1].second, {0, 0, 0});
  auto g28 = run_grbl("G0 X5 Y5\nG28.1\nG0 X1\n$RST=*\nG28\n");
  ASSERT_FALSE(g28->moves().empty());
  expect_at(g28->moves().back().second, {0, 0, 0});
  // Every $RST is a soft reset: G90, G92 and G43.1 cleared, F undefined.
  auto modes = run_grbl("G91 G1 X1 F100\n$RST=$\nG0 X1\nG1 X2\n");
  ASSERT_EQ(modes->moves().size(), 2u);
  expect_at(modes->moves()[1].second, {1, 0, 0});
  const auto e = modes->with(core::Code::GrblError);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0]->loc.line, 4u);
  EXPECT_NE(e[0]->message.find("error:22"), std::string::npos);
  auto g92 = run_grbl("G92 X5\nG0 X0\n$RST=$\nG0 X0\n");
  ASSERT_EQ(g92->moves().size(), 2u);
  expect_at(g92->moves()[0].second, {-5, 0, 0});
  expect_at(g92->moves()[1].second, {0, 0, 0});
  // $RST=$ restores the settings: soft limits off again.
  auto settings = run_grbl(kSoftLimits + "$RST=$\nG0 X10\n");
  EXPECT_TRUE(settings->ok);
}

}  // namespace
}  // namespace usina::gcode
