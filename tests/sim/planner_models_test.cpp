// [planner] model: the choice in the profile, and the "linuxcnc" and "grbl"
// models on ops written by hand, against times worked out in the comments
// from LinuxCNC's and grbl's own equations (tests/programs/timing/ holds
// what LinuxCNC itself measured).
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "sim/machine_profile.hpp"
#include "sim/planner_grbl.hpp"
#include "sim/stats.hpp"

namespace usina::sim {
namespace {

constexpr const char* kAxes = R"(
[machine]
name = "m"
[axes.x]
min = -500
max = 500
rapid = 6000
max_feed = 6000
accel = 100
[axes.y]
min = -500
max = 500
rapid = 6000
max_feed = 6000
accel = 400
[axes.z]
min = -200
max = 200
rapid = 6000
max_feed = 6000
accel = 100
)";

std::optional<MachineProfile> read(const std::string& planner, core::DiagnosticList& diags) {
  return read_machine_profile(std::string(kAxes) + planner, 1, diags);
}

MachineProfile profile(const std::string& planner) {
  core::DiagnosticList diags;
  auto p = read(planner, diags);
  EXPECT_TRUE(p.has_value());
  return p.value_or(MachineProfile{});
}

struct Machine {
  explicit Machine(const MachineProfile& m) : profile(m), sink(profile, {}, diags) {}

  void operator()(canon::OpKind k) { sink.on(canon::Op{std::move(k), {0, 1, 1, 1, 0}}); }

  double motion() {
    sink.finish();
    const StatsReport r = sink.report();
    return r.total.cutting_s + r.total.rapid_s;
  }

  MachineProfile profile;
  core::DiagnosticList diags;
  StatsSink sink;
};

canon::Feed feed_to(core::Vec3 to, double f) {
  return canon::Feed{to, f, {}};
}

canon::PathMode mode(canon::PathMode::Mode m) {
  return canon::PathMode{m, 0.0, 0.0};
}

TEST(PlannerModels, TheModelIsTextbookUnlessTheProfileSaysOtherwise) {
  EXPECT_EQ(profile("").model, PlannerModel::Textbook);
  EXPECT_EQ(profile("[planner]\njunction_deviation = 0.02\n").model, PlannerModel::Textbook);
  EXPECT_EQ(profile("[planner]\nmodel = \"textbook\"\n").model, PlannerModel::Textbook);
  EXPECT_EQ(profile("[planner]\nmodel = \"linuxcnc\"\n").model, PlannerModel::Linuxcnc);
  EXPECT_EQ(profile("[planner]\nmodel = \"grbl\"\n").model, PlannerModel::Grbl);
}

TEST(PlannerModels, AnUnknownModelIsAnErrorNamingTheValidOnes) {
  for (const char* bad : {"model = \"fanuc\"", "model = 3"}) {
    core::DiagnosticList diags;
    EXPECT_FALSE(read(std::string("[planner]\n") + bad + "\n", diags).has_value()) << bad;
    ASSERT_EQ(diags.all().size(), 1u) << bad;
    const core::Diagnostic& d = diags.all()[0];
    EXPECT_EQ(d.code, core::Code::BadMachineProfile);
    for (const char* name : {"\"textbook\"", "\"linuxcnc\"", "\"grbl\""})
      EXPECT_NE(d.message.find(name), std::string::npos) << d.message;
  }
}

TEST(PlannerModels, TheModelsSettingsAreReadAndChecked) {
  const MachineProfile m = profile(
      "[planner]\nmodel = \"linuxcnc\"\nservo_period = 0.0005\nmax_velocity = 3000\n"
      "kink_ratio = 0.2\narc_blend = false\noptimization_depth = 30\narc_tolerance = 0.01\n");
  EXPECT_DOUBLE_EQ(m.linuxcnc.servo_period, 0.0005);
  EXPECT_DOUBLE_EQ(m.linuxcnc.max_velocity, 50.0);  // mm/s
  EXPECT_DOUBLE_EQ(m.linuxcnc.kink_ratio, 0.2);
  EXPECT_FALSE(m.linuxcnc.arc_blend);
  EXPECT_EQ(m.linuxcnc.optimization_depth, 30u);
  EXPECT_DOUBLE_EQ(m.arc_tolerance, 0.01);
  core::DiagnosticList diags;
  EXPECT_FALSE(read("[planner]\nservo_period = 0\n", diags).has_value());
  EXPECT_FALSE(read("[planner]\narc_blend = 1\n", diags).has_value());
}

// The textbook model ignores the path mode: today's times, bit for bit.
TEST(PlannerModels, TheTextbookModelIgnoresThePathMode) {
  const auto square = [](bool exact) {
    Machine run(profile(""));
    if (exact) run(mode(canon::PathMode::Mode::ExactStop));
    run(feed_to({100, 0, 0}, 3000));
    run(feed_to({100, 100, 0}, 3000));
    return run.motion();
  };
  EXPECT_EQ(square(false), square(true));
}

// LinuxCNC: the last move of a G64 run keeps its parabolic end and runs at
// a/2 = 50: 100 mm at 10 mm/s, ramps of 10/50 s: 100/10 + 10/50 = 10.2 s;
// under G61.1 at a = 100: 10.1 s.
TEST(LinuxcncModel, TheLastMoveOfARunHasHalfTheAcceleration) {
  const MachineProfile m = profile("[planner]\nmodel = \"linuxcnc\"\n");
  Machine blend(m);
  blend(feed_to({100, 0, 0}, 600));
  EXPECT_NEAR(blend.motion(), 10.2, 1e-3);
  Machine exact(m);
  exact(mode(canon::PathMode::Mode::ExactStop));
  exact(feed_to({100, 0, 0}, 600));
  EXPECT_NEAR(exact.motion(), 10.1, 1e-3);
}

// Before any G61/G64 LinuxCNC's corners nearly stop (measured); after G64
// the 90° corner between 40 mm lines at 20 mm/s is a blend arc (measured
// in XY on the same limits, tests/programs/timing/corner_40mm_*): the lines
// keep a = 100, tolerance 10 mm, R = 5.09 mm at 20 mm/s (blendmath.c).
TEST(LinuxcncModel, TheStartModeNearlyStopsWhereG64Blends) {
  const MachineProfile m = profile("[planner]\nmodel = \"linuxcnc\"\n");
  const auto corner = [&](bool g64) {
    Machine run(m);
    if (g64) run(mode(canon::PathMode::Mode::Blend));
    run(feed_to({40, 0, 0}, 1200));
    run(feed_to({40, 0, 40}, 1200));  // X then Z: 100 mm/s² both
    return run.motion();
  };
  // A stop: 40/20 + 20/100, then the last line at a/2 = 50: 40/20 + 20/50.
  const double stop = 2.0 + 0.2 + 2.0 + 0.4;
  EXPECT_LT(corner(false), stop);
  EXPECT_GT(corner(false), stop - 0.05);
  EXPECT_LT(corner(true), stop - 0.3);  // LinuxCNC: 4.192 s
  EXPECT_NEAR(corner(true), 4.192, 0.02);
}

// G61: both sides of the corner lose ARC_BLEND_KINK_RATIO (10 %): X side at
// 90 mm/s², Y side at 360: 100/50 + 50/90 and 100/50 + 50/360.
TEST(LinuxcncModel, ExactPathCornersCostTheKinkRatio) {
  Machine run(profile("[planner]\nmodel = \"linuxcnc\"\n"));
  run(mode(canon::PathMode::Mode::ExactPath));
  run(feed_to({100, 0, 0}, 3000));
  run(feed_to({100, 100, 0}, 3000));
  EXPECT_NEAR(run.motion(), 2.0 + 50.0 / 90.0 + 2.0 + 50.0 / 360.0, 2e-3);
}

// A circle of r = 20 in XY (a = min(100, 400) = 100): v ≤ √(√3/2·100·20) =
// 41.6 mm/s, then a/2 along the path, halved again as the last move: 25.
TEST(LinuxcncModel, ArcsRunAtRootOfSqrt3Over2ARAndHalfTheAcceleration) {
  Machine run(profile("[planner]\nmodel = \"linuxcnc\"\n"));
  run(canon::Arc{{0, 0, 0}, {20, 0, 0}, {0, 0, 1}, 1, 3000.0, {}});
  const double v = std::sqrt(std::sqrt(3.0) / 2.0 * 100.0 * 20.0);
  EXPECT_NEAR(run.motion(), 2.0 * std::numbers::pi * 20.0 / v + v / 25.0, 2e-3);
}

// grbl: the corner between X and Y moves: the junction's direction is
// (−1, 1)/√2, along which the axes allow min(100, 400)·√2 = 141.4 mm/s²;
// sin(θ/2) = √½: v² = 141.4·0.01·0.7071/0.2929 = 3.414, v = 1.848 mm/s.
// X side: 0 → 10 in 0.1 s (0.5 mm), 10 → 1.848 at 100 (0.483 mm, 0.0815 s),
// the rest at 10 mm/s: 1.08323 s. Y side at 400: 1.848 → 10 (0.1207 mm,
// 0.0204 s), 10 → 0 (0.125 mm, 0.025 s), the rest: 1.02081 s. Total 2.10404.
TEST(GrblModel, TheCornerTakesTheAccelerationAlongTheJunction) {
  Machine run(profile("[planner]\nmodel = \"grbl\"\njunction_deviation = 0.01\n"));
  run(feed_to({10, 0, 0}, 600));
  run(feed_to({10, 10, 0}, 600));
  EXPECT_NEAR(run.motion(), 2.10404, 1e-4);
  // The textbook model takes the smaller block acceleration (100): slower.
  Machine textbook(profile(""));
  textbook(feed_to({10, 0, 0}, 600));
  textbook(feed_to({10, 10, 0}, 600));
  EXPECT_GT(textbook.motion(), 2.10404 + 1e-3);
}

// mc_arc: floor(½·|sweep|·r / √(tol·(2r − tol))) chords: a quarter of
// r = 10 at $12 = 0.002: floor(7.854 / 0.2) = 39; a whole circle of r = 1:
// floor(3.1416 / 0.063214) = 49; never fewer than one.
TEST(GrblModel, AnArcRunsAsChordsWithinTheArcTolerance) {
  EXPECT_EQ(GrblPlanner::arc_segments(10.0, std::numbers::pi / 2.0, 0.002), 39u);
  EXPECT_EQ(GrblPlanner::arc_segments(1.0, 2.0 * std::numbers::pi, 0.002), 49u);
  EXPECT_EQ(GrblPlanner::arc_segments(0.001, 1.0, 0.002), 1u);
  const double limits[3] = {100.0, 400.0, 100.0};
  EXPECT_NEAR(GrblPlanner::along({0.6, 0.8, 0.0}, limits), 100.0 / 0.6, 1e-9);
}

// A circle of r = 20 at F3000 as 2π·20 / 0.4 chords... grbl has no v²/r
// limit: the chords' corners (θ = 2π/n) are nearly straight, so it runs at
// the feed, much faster than the textbook's v ≤ √(a·r) = 44.7 mm/s.
TEST(GrblModel, AnArcRunsAtTheFeedWhenItsChordsAreNearlyStraight) {
  Machine run(profile("[planner]\nmodel = \"grbl\"\n"));
  run(canon::Arc{{0, 0, 0}, {20, 0, 0}, {0, 0, 1}, 1, 3000.0, {}});
  const double length = 2.0 * std::numbers::pi * 20.0;
  EXPECT_LT(run.motion(), length / 50.0 + 1.0);
  EXPECT_GT(run.motion(), length / 50.0);
}

// 16 blocks (15 planned): 100 moves of 0.1 mm in a row must be able to stop
// within 15 of them (1.5 mm): at most √(2·100·1.5) = 17.3 mm/s, so 10 mm take
// at least 10/17.3 = 0.577 s; the textbook's 200 blocks see the whole 10 mm.
TEST(GrblModel, TheSixteenBlockBufferLimitsTheSpeedOfShortMoves) {
  const auto run_of = [](const std::string& planner) {
    Machine run(profile(planner));
    for (int i = 1; i <= 100; ++i)
      run(feed_to({0.1 * i, 0, 0}, 6000));
    return run.motion();
  };
  const double grbl = run_of("[planner]\nmodel = \"grbl\"\n");
  EXPECT_GT(grbl, 10.0 / std::sqrt(2.0 * 100.0 * 1.5));
  EXPECT_GT(grbl, run_of("") + 0.01);
}

}  // namespace
}  // namespace usina::sim
