// The stats sink: totals, per-tool figures and every check, on ops written
// by hand (times worked out in the comments: a = 1000 mm/s², a trapezoid
// from rest to rest takes L/v + v/a, a triangle 2 sqrt(L/a)); then real
// programs of ../shared/conformance, read at test time, against sanity bounds.
#include "sim/stats.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/source.hpp"
#include "gcode/interp/interpreter.hpp"
#include "gcode/tool_table.hpp"

namespace usina::sim {
namespace {

constexpr double kA = 1000.0;

MachineProfile test_profile() {
  MachineProfile m;
  m.name = "test";
  for (std::size_t i = 0; i < 3; ++i)
    m.axes[i] = {true, -100, 100, 12000, 6000, kA, 0};  // rapid 200 mm/s, feed ≤ 100 mm/s
  m.spindle_max_rpm = 10000;
  m.spindle_accel_time = 2.0;
  m.tool_change_time = 5.0;
  m.cost_per_hour = 36.0;
  return m;
}

canon::Op at_line(canon::OpKind k, std::uint32_t line) {
  return canon::Op{std::move(k), core::SourceLoc{0, line, 1, 1, 0}};
}

canon::Feed feed_to(Vec3 to, std::optional<double> f) {
  return canon::Feed{to, f, {}};
}

canon::Arc half_circle(Vec3 from, double r, int turn, std::optional<double> f) {
  // From `from` to from + (2r, 0) about from + (r, 0).
  return canon::Arc{from + Vec3{2 * r, 0, 0}, from + Vec3{r, 0, 0}, {0, 0, 1}, turn, f, {}};
}

struct Machine {
  explicit Machine(MachineProfile m = test_profile(), StatsOptions o = {})
      : profile(std::move(m)), sink(profile, o, diags) {}

  void operator()(canon::OpKind k, std::uint32_t line = 1) { sink.on(at_line(std::move(k), line)); }

  StatsReport done() {
    sink.finish();
    return sink.report();
  }

  std::vector<const core::Diagnostic*> with(core::Code code) const {
    std::vector<const core::Diagnostic*> out;
    for (const core::Diagnostic& d : diags.all())
      if (d.code == code) out.push_back(&d);
    return out;
  }

  MachineProfile profile;
  core::DiagnosticList diags;
  StatsSink sink;
};

void spindle_on(Machine& run, double rpm = 5000) {
  run(canon::Spindle{rpm, canon::SpindleDir::Cw});
}

// Spindle 0 → 5000 of 10000 rpm: 2 s × 0.5 = 1 s. Rapid X10 (triangle,
// 2 sqrt(10/1000) = 0.2 s), feed Y10 at F600 = 10 mm/s (1 + 0.01 s), tool
// change 5 s, spindle 5000 → 10000: 1 s, dwell 1.5 s, a half circle of
// radius 5 at F600 (5π/10 + 0.01 s), a hole.
TEST(Stats, TotalsAndPerTool) {
  Machine run;
  spindle_on(run);
  run(canon::Traverse{{10, 0, 0}, {}});
  run(feed_to({10, 10, 0}, 600));
  run(canon::ToolChange{2, 6.0});
  run(canon::Spindle{10000, canon::SpindleDir::Cw});
  run(canon::Dwell{1.5});
  run(half_circle({10, 10, 0}, 5, 1, 600));
  // The interpreter's hole comes with its cycle's moves: counted, not drilled again.
  run.sink.on(canon::Op{canon::Hole{{0, 0, 0}, 6, 5}, {0, 1, 1, 1, 0}, canon::Origin::Cycle});
  run(canon::ProgramEnd{});
  const StatsReport r = run.done();
  ASSERT_EQ(r.tools.size(), 2u);
  const ToolStats& t0 = r.tools[0];
  const ToolStats& t2 = r.tools[1];
  EXPECT_EQ(t0.tool, 0);
  EXPECT_EQ(t2.tool, 2);
  EXPECT_NEAR(t0.other_s, 1.0, 1e-9);
  EXPECT_NEAR(t0.rapid_mm, 10.0, 1e-12);
  EXPECT_NEAR(t0.cutting_mm, 10.0, 1e-12);
  // The corner between the rapid and the feed does not stop; exact stop does.
  EXPECT_NEAR(t0.exact_stop_s, 1.0 + 0.2 + 1.01, 1e-9);
  EXPECT_LT(t0.rapid_s + t0.cutting_s, 0.2 + 1.01);
  EXPECT_NEAR(t2.other_s, 5.0 + 1.0 + 1.5, 1e-9);
  EXPECT_NEAR(t2.cutting_s, 5 * M_PI / 10 + 0.01, 1e-9);
  EXPECT_NEAR(t2.cutting_mm, 5 * M_PI, 1e-9);
  EXPECT_EQ(t2.counts.arcs, 1u);
  EXPECT_EQ(t2.counts.holes, 1u);
  EXPECT_EQ(t2.counts.tool_changes, 1u);
  EXPECT_EQ(t2.counts.dwells, 1u);
  EXPECT_EQ(t0.rpm.min, 5000.0);
  EXPECT_EQ(t2.rpm.max, 10000.0);
  EXPECT_EQ(r.total.counts.moves(), 3u);
  EXPECT_NEAR(r.total.total_s(), t0.total_s() + t2.total_s(), 1e-12);
  EXPECT_NEAR(r.cost, r.total.total_s() / 3600.0 * 36.0, 1e-12);
  EXPECT_EQ(r.total.feed.min, 600.0);
  EXPECT_GE(r.total.exact_stop_s, r.total.total_s());
}

// The half circle from (10,2) to (20,2) counter-clockwise dips to Y-3; the
// tool started at the origin.
// A generator's bare hole (canon/bare_hole.hpp) is drilled as G81 would:
// over it at 5 mm, down to R = 1, 11 mm at F600 (10 mm/s: 1.1 + 0.01 s),
// back up to 5. The 11 mm are cutting, the rest rapid.
TEST(Stats, ABareHoleIsTimedAsItsCycle) {
  Machine run;
  spindle_on(run);
  run(canon::Traverse{{0, 0, 5}, {}});
  run(feed_to({0, 0, 5}, 600));  // the feed the hole drills at
  run(canon::Hole{{10, 0, 1}, 6, 11});
  const StatsReport r = run.done();
  EXPECT_EQ(r.total.counts.holes, 1u);
  EXPECT_NEAR(r.total.cutting_mm, 11.0, 1e-12);
  EXPECT_NEAR(r.total.rapid_mm, 5.0 + 10.0 + 4.0 + 15.0, 1e-12);
  // Down at 10 mm/s: L/v, and at most v/a more from rest to rest (it enters
  // from the rapid down to R without stopping: the same direction).
  EXPECT_GT(r.total.cutting_s, 1.1);
  EXPECT_LE(r.total.cutting_s, 1.1 + 0.01 + 1e-9);
}

TEST(Stats, BoundsHoldTheArcsTrueExtent) {
  Machine run;
  spindle_on(run);
  run(canon::Traverse{{10, 2, 0}, {}});
  run(half_circle({10, 2, 0}, 5, 1, 600));
  const StatsReport r = run.done();
  EXPECT_NEAR(r.total.bounds.lo.y, -3.0, 1e-9);
  EXPECT_NEAR(r.total.bounds.hi.y, 2.0, 1e-9);
  EXPECT_NEAR(r.total.bounds.hi.x, 20.0, 1e-9);
  EXPECT_NEAR(r.tools[0].bounds.lo.x, 0.0, 1e-12);
}

// G0 X100 Y100 with Y's rapid 6000 mm/min (100 mm/s), X's 12000: along the
// diagonal Y allows 100 × √2 = 141.42 mm/s and 1000 × √2 mm/s², so the move
// takes L/v + v/a = 141.42/141.42 + 141.42/1414.2 = 1.1 s: Y's own 100 mm
// at 100 mm/s from rest to rest.
TEST(Stats, RapidLimitedByTheSlowestAxis) {
  MachineProfile m = test_profile();
  m.axes[1].rapid = 6000;
  Machine run(m);
  run(canon::Traverse{{100, 100, 0}, {}});
  const StatsReport r = run.done();
  EXPECT_NEAR(r.total.rapid_s, 1.1, 1e-9);
  EXPECT_NEAR(r.total.rapid_mm, 100 * std::sqrt(2.0), 1e-9);
}

TEST(Stats, SpindleStartUpScalesWithTheSpeed) {
  Machine run;
  spindle_on(run, 5000);                              // 0 → 5000: 1 s
  run(canon::Spindle{5000, canon::SpindleDir::Ccw});  // reversal: 5000 → 0 → 5000: 2 s
  run(canon::Spindle{0, canon::SpindleDir::Off});     // M5: no wait
  run(canon::Spindle{20000, canon::SpindleDir::Cw});  // above max: at most 2 × accel_time
  EXPECT_NEAR(run.done().total.other_s, 1.0 + 2.0 + 0.0 + 4.0, 1e-9);
}

// [times] block = 0.1 s: a 1 mm block cannot run faster than 10 mm/s:
// 1/10 + 10/1000 = 0.11 s instead of 2 sqrt(1/1000) = 0.063 s.
TEST(Stats, BlockTimeLimitsShortBlocks) {
  MachineProfile m = test_profile();
  m.block_time = 0.1;
  Machine run(m);
  spindle_on(run);
  run(feed_to({1, 0, 0}, 6000));
  EXPECT_NEAR(run.done().total.cutting_s, 0.11, 1e-9);
}

TEST(Stats, DefaultProfileHasNoTravelLimits) {
  Machine run(default_machine_profile());
  run(canon::Traverse{{1e6, -1e6, 1e5}, {}});
  run.done();
  EXPECT_TRUE(run.with(core::Code::OverTravel).empty());
}

TEST(Stats, JunctionDeviationIsAProfileKey) {
  const std::string base = R"([machine]
units = "UNITS"
[axes.x]
min = 0
max = 1
rapid = 1
max_feed = 1
accel = 1
[axes.y]
min = 0
max = 1
rapid = 1
max_feed = 1
accel = 1
[axes.z]
min = 0
max = 1
rapid = 1
max_feed = 1
accel = 1
)";
  const auto read = [&](const std::string& units, const std::string& extra) {
    std::string text = base;
    text.replace(text.find("UNITS"), 5, units);
    core::DiagnosticList diags;
    auto p = read_machine_profile(text + extra, 0, diags);
    EXPECT_TRUE(p.has_value()) << (diags.all().empty() ? "" : diags.all()[0].message);
    return p ? p->junction_deviation : -1.0;
  };
  EXPECT_EQ(read("mm", ""), 0.01);
  EXPECT_EQ(read("mm", "[planner]\njunction_deviation = 0.05\n"), 0.05);
  EXPECT_NEAR(read("inch", "[planner]\njunction_deviation = 0.001\n"), 0.0254, 1e-12);
  core::DiagnosticList diags;
  std::string text = base;
  text.replace(text.find("UNITS"), 5, "mm");
  EXPECT_FALSE(read_machine_profile(text + "[planner]\njunction_deviation = -1\n", 0, diags));
  ASSERT_FALSE(diags.all().empty());
  EXPECT_EQ(diags.all()[0].code, core::Code::BadMachineProfile);
}

// --- checks ---------------------------------------------------------------------

// Program zero 50 mm left of machine zero: X120 in the program is X70 on
// the machine (inside test_profile's -100..100).
TEST(StatsChecks, WorkZeroPlacesTheProgramOnTheMachine) {
  StatsOptions o;
  o.work_zero = Vec3{-50, 0, 0};
  Machine run(test_profile(), o);
  spindle_on(run);
  run(feed_to({120, 0, 0}, 600), 2);  // machine X70: inside
  run(feed_to({160, 0, 0}, 600), 3);  // machine X110: 10 above
  run.done();
  const auto d = run.with(core::Code::OverTravel);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0]->loc.line, 3u);
  EXPECT_EQ(d[0]->message, "X goes to 110.000 mm, 10.000 mm above its travel limit 100.000");
}

// Without a work zero only the extent can be checked: X from -30 to 180 is
// 210 mm, more than the 200 mm of travel of test_profile's X (-100..100);
// reported once, at the move that makes it too long.
TEST(StatsChecks, WithoutWorkZeroTheExtentIsChecked) {
  Machine run;
  spindle_on(run);
  run(feed_to({-30, 0, 0}, 600), 2);
  run(feed_to({160, 0, 0}, 600), 3);  // 190 mm: fits
  run(feed_to({180, 0, 0}, 600), 4);  // 210 mm: too long
  run(feed_to({190, 0, 0}, 600), 5);  // still too long: not again
  run.done();
  const auto d = run.with(core::Code::OverTravel);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0]->loc.line, 4u);
  EXPECT_EQ(d[0]->message,
            "X spans 210.000 mm (from -30.000 to 180.000), more than the 200.000 mm the axis "
            "travels; give the work zero (--work-zero or --var-file) to check the limits");
}

// The tests of the travel limits place program zero at machine zero.
StatsOptions at_machine_zero() {
  StatsOptions o;
  o.work_zero = Vec3{};
  return o;
}

TEST(StatsChecks, OverTravelOncePerExcursion) {
  Machine run(test_profile(), at_machine_zero());
  spindle_on(run);
  run(feed_to({120, 0, 0}, 600), 2);  // out: reported
  run(feed_to({130, 0, 0}, 600), 3);  // still out: counted only
  run(feed_to({50, 0, 0}, 600), 4);   // back in (counted: it starts outside)
  run(feed_to({101, 0, 0}, 600), 5);  // out again: reported
  const StatsReport r = run.done();
  const auto d = run.with(core::Code::OverTravel);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0]->loc.line, 2u);
  EXPECT_EQ(d[0]->severity, core::Severity::Warning);
  EXPECT_EQ(d[0]->message, "X goes to 120.000 mm, 20.000 mm above its travel limit 100.000");
  EXPECT_EQ(d[1]->loc.line, 5u);
  EXPECT_EQ(r.checks.at(core::Code::OverTravel), 4u);
}

// Both ends of the half circle lie within Y ≥ -3, its bottom (Y-5) does not.
TEST(StatsChecks, OverTravelOfAnArcUsesItsExtent) {
  MachineProfile m = test_profile();
  m.axes[1].min = -3;
  Machine run(m, at_machine_zero());
  spindle_on(run);
  run(half_circle({0, 0, 0}, 5, 1, 600), 7);
  run.done();
  const auto d = run.with(core::Code::OverTravel);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0]->loc.line, 7u);
  EXPECT_EQ(d[0]->message, "Y goes to -5.000 mm, 2.000 mm below its travel limit -3.000");
}

TEST(StatsChecks, OverTravelReportsAtMostTheCap) {
  StatsOptions o = at_machine_zero();
  o.max_reports_per_check = 10;
  Machine run(test_profile(), o);
  spindle_on(run);
  for (int i = 0; i < 12; ++i) {
    run(canon::Traverse{{0, 0, 150}, {}});
    run(canon::Traverse{{0, 0, 0}, {}});
  }
  const StatsReport r = run.done();
  EXPECT_EQ(run.with(core::Code::OverTravel).size(), 10u);
  EXPECT_EQ(r.checks.at(core::Code::OverTravel), 24u);  // out and back, 12 times
}

// No rate (a front end that gives none): timed at the max feed, 100 mm/s:
// 100 mm in 1.1 s.
TEST(StatsChecks, FeedWithoutRate) {
  Machine run;
  spindle_on(run);
  run(feed_to({100, 0, 0}, std::nullopt), 3);
  run(feed_to({0, 0, 0}, std::nullopt), 4);
  const StatsReport r = run.done();
  const auto d = run.with(core::Code::FeedWithoutRate);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0]->loc.line, 3u);
  EXPECT_NE(d[0]->message.find("timed at the axes' max feed"), std::string::npos);
  EXPECT_EQ(r.checks.at(core::Code::FeedWithoutRate), 2u);
  EXPECT_NEAR(r.total.cutting_s, 2.2, 1e-9);
}

// G93 F2: 100 mm in 1/2 min, 200 mm/min = 3.333 mm/s: 30 s + v/a
// (3.333/1000 s). A half circle of radius 5 (15.708 mm) in G93 F6: 10 s.
TEST(Stats, InverseTimeMovesTakeOneOverF) {
  using Mode = canon::ProgrammedFeed::Mode;
  Machine run;
  spindle_on(run);
  canon::Feed f = feed_to({100, 0, 0}, std::nullopt);
  f.programmed = {Mode::InverseTime, 2.0};
  run(f);
  canon::Arc a = half_circle({100, 0, 0}, 5, 1, std::nullopt);
  a.programmed = {Mode::InverseTime, 6.0};
  run(a);
  const StatsReport r = run.done();
  EXPECT_TRUE(run.with(core::Code::FeedWithoutRate).empty());
  const double v1 = 200.0 / 60.0;
  const double v2 = 5 * M_PI / 10.0;  // mm/s
  // Exact stop: each move from rest to rest, plus the spindle's 1 s start-up.
  EXPECT_NEAR(r.total.exact_stop_s, 1.0 + 30.0 + v1 / kA + 10.0 + v2 / kA, 1e-6);
  EXPECT_NEAR(r.total.feed.max, 200.0, 1e-9);
  EXPECT_NEAR(r.total.feed.min, 5 * M_PI * 6.0, 1e-9);  // 15.708 mm in 1/6 min
}

// G95 F0.1 at 5000 rpm: 500 mm/min; with the spindle stopped there is no rate.
TEST(Stats, PerRevolutionFeedRunsAtTheSpindleSpeed) {
  using Mode = canon::ProgrammedFeed::Mode;
  Machine run;
  spindle_on(run);
  canon::Feed f = feed_to({50, 0, 0}, std::nullopt);
  f.programmed = {Mode::PerRevolution, 0.1};
  run(f, 2);
  run(canon::Spindle{0, canon::SpindleDir::Off});
  canon::Feed g = feed_to({0, 0, 0}, std::nullopt);
  g.programmed = {Mode::PerRevolution, 0.1};
  run(g, 4);
  const StatsReport r = run.done();
  EXPECT_NEAR(r.total.feed.max, 500.0, 1e-9);
  const auto d = run.with(core::Code::FeedWithoutRate);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0]->loc.line, 4u);
}

TEST(StatsChecks, FeedWithTheSpindleStopped) {
  Machine run;
  run(feed_to({10, 0, 0}, 600), 2);  // never started
  spindle_on(run);
  run(feed_to({20, 0, 0}, 600), 4);  // fine
  run(canon::Spindle{0, canon::SpindleDir::Off});
  run(half_circle({20, 0, 0}, 1, 1, 600), 6);  // stopped again
  const StatsReport r = run.done();
  const auto d = run.with(core::Code::FeedSpindleStopped);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0]->loc.line, 2u);
  EXPECT_EQ(d[1]->loc.line, 6u);
  EXPECT_EQ(r.checks.at(core::Code::FeedSpindleStopped), 2u);
}

TEST(StatsChecks, RapidIntoTheStock) {
  StatsOptions o;
  o.stock_top = 0.0;
  Machine run(test_profile(), o);
  spindle_on(run);
  run(canon::Traverse{{0, 0, 5}, {}}, 2);   // above: fine
  run(canon::Traverse{{0, 0, -1}, {}}, 3);  // down into it: reported
  run(canon::Traverse{{10, 0, 5}, {}}, 4);  // across while inside: counted, same run
  run(feed_to({10, 0, -1}, 600), 5);
  run(canon::Traverse{{10, 0, 5}, {}}, 6);      // straight up out of the cut: fine
  run(canon::Traverse{{10, 10, -0.5}, {}}, 7);  // down again: reported
  const StatsReport r = run.done();
  const auto d = run.with(core::Code::RapidIntoStock);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0]->loc.line, 3u);
  EXPECT_EQ(d[0]->message,
            "rapid move down to Z-1.000, 1.000 mm below the stock top Z0.000: it would cut at "
            "rapid speed");
  EXPECT_EQ(d[1]->loc.line, 7u);
  EXPECT_EQ(r.checks.at(core::Code::RapidIntoStock), 3u);
}

TEST(StatsChecks, RapidAcrossInsideTheStock) {
  StatsOptions o;
  o.stock_top = 0.0;
  Machine run(test_profile(), o);
  spindle_on(run);
  run(feed_to({0, 0, -2}, 600));
  run(canon::Traverse{{10, 0, 1}, {}}, 9);  // starts inside, moves across
  run.done();
  const auto d = run.with(core::Code::RapidIntoStock);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0]->loc.line, 9u);
  EXPECT_NE(d[0]->message.find("across X/Y at Z-2.000"), std::string::npos);
}

TEST(StatsChecks, NoStockTopNoRapidCheck) {
  Machine run;
  run(canon::Traverse{{0, 0, -50}, {}});
  EXPECT_EQ(run.done().checks.count(core::Code::RapidIntoStock), 0u);
}

// Radius 1 mm at F6000 (100 mm/s): v²/r ≤ 1000 allows sqrt(1000) =
// 31.623 mm/s = 1897.4 mm/min, 68.4 % less. A half circle (π mm) from rest
// to rest at 31.623 mm/s: π / 31.623 + 31.623 / 1000 = 0.130969 s.
TEST(StatsChecks, ArcTooTightForItsFeed) {
  Machine run;
  spindle_on(run);
  run(half_circle({0, 0, 0}, 1, 1, 6000), 4);
  const StatsReport r = run.done();
  const auto d = run.with(core::Code::ArcFeedReduced);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0]->loc.line, 4u);
  EXPECT_EQ(d[0]->message,
            "arc of radius 1.000 mm too tight for F6000: at 1000 mm/s² the centripetal "
            "acceleration v²/r allows 1897.4 mm/min, so the feed is reduced by 68.4 %");
  EXPECT_NEAR(r.total.cutting_s, M_PI / std::sqrt(1000.0) + std::sqrt(1000.0) / 1000.0, 1e-9);
  EXPECT_NEAR(r.total.cutting_s, 0.130969, 1e-6);
}

TEST(StatsChecks, ArcWideEnoughIsNotReported) {
  Machine run;
  spindle_on(run);
  run(half_circle({0, 0, 0}, 20, 1, 6000));  // sqrt(1000 × 20) = 141 mm/s > 100
  run.done();
  EXPECT_TRUE(run.with(core::Code::ArcFeedReduced).empty());
}

// F9000 along X, whose max_feed is 6000: clamped, 100 mm at 100 mm/s = 1.1 s.
TEST(StatsChecks, FeedAboveTheAxisLimitIsClamped) {
  Machine run;
  spindle_on(run);
  run(feed_to({100, 0, 0}, 9000), 8);
  const StatsReport r = run.done();
  const auto d = run.with(core::Code::FeedClamped);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0]->loc.line, 8u);
  EXPECT_EQ(d[0]->message,
            "F9000 is above the max feed of axis X along this move: runs at "
            "6000.0 mm/min");
  EXPECT_NEAR(r.total.cutting_s, 1.1, 1e-9);
  EXPECT_EQ(r.total.feed.max, 9000.0);  // as programmed
}

// A run of clamped moves is reported at its first move.
TEST(StatsChecks, ClampedFeedsReportedOncePerRun) {
  Machine run;
  spindle_on(run);
  run(feed_to({10, 0, 0}, 9000), 2);
  run(feed_to({20, 0, 0}, 9000), 3);
  run(feed_to({30, 0, 0}, 3000), 4);
  run(feed_to({40, 0, 0}, 9000), 5);
  const StatsReport r = run.done();
  const auto d = run.with(core::Code::FeedClamped);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0]->loc.line, 2u);
  EXPECT_EQ(d[1]->loc.line, 5u);
  EXPECT_EQ(r.checks.at(core::Code::FeedClamped), 3u);
}

TEST(StatsChecks, TightArcsReportedOncePerRun) {
  Machine run;
  spindle_on(run);
  run(half_circle({0, 0, 0}, 1, 1, 6000), 2);
  run(half_circle({2, 0, 0}, 1, -1, 6000), 3);
  run(half_circle({4, 0, 0}, 50, 1, 6000), 4);
  run(half_circle({104, 0, 0}, 1, 1, 6000), 5);
  const StatsReport r = run.done();
  const auto d = run.with(core::Code::ArcFeedReduced);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[1]->loc.line, 5u);
  EXPECT_EQ(r.checks.at(core::Code::ArcFeedReduced), 3u);
}

// Along the diagonal X = Y each axis moves 0.707 mm per mm: F8000 is fine
// for the path (5657 mm/min per axis).
TEST(StatsChecks, FeedLimitIsPerAxis) {
  Machine run;
  spindle_on(run);
  run(feed_to({50, 50, 0}, 8000));
  run.done();
  EXPECT_TRUE(run.with(core::Code::FeedClamped).empty());
}

// --- real programs ----------------------------------------------------------------

struct ProgramFigures {
  bool ok = false;
  StatsReport report;
};

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

ProgramFigures run_program(const std::filesystem::path& program, const std::filesystem::path& tbl) {
  core::SourceManager sources;
  core::DiagnosticList diags;
  std::string err;
  auto file = core::SourceFile::open(program.string(), err);
  if (!file) return {};
  const std::uint32_t id = sources.add(std::move(file));
  gcode::InterpOptions opts;
  opts.machine_units = core::LengthUnit::Inch;
  opts.subroutine_path.push_back(program.parent_path().string());
  auto tf = core::SourceFile::from_string(tbl.string(), slurp(tbl));
  const std::uint32_t tid = sources.add(std::move(tf));
  auto table = gcode::read_tool_table(*sources.get(tid), tid, core::kMmPerInch, diags);
  if (table) opts.tools = std::move(*table);
  const MachineProfile m = default_machine_profile();
  core::DiagnosticList checks;
  StatsSink sink(m, {}, checks);
  gcode::Interpreter interp(sources, std::move(opts), sink, diags);
  ProgramFigures out;
  out.ok = interp.run(id) && !diags.has_errors();
  out.report = sink.report();
  return out;
}

// Every program of LinuxCNC's conformance set that runs: times finite, each
// move no faster than its feed (cutting time ≥ cutting distance / the
// highest feed; rapid time ≥ rapid distance / the fastest diagonal of the
// default profile's 10000 mm/min axes), exact stop never faster than
// look-ahead.
TEST(StatsPrograms, ConformanceProgramsWithinSanityBounds) {
  const std::filesystem::path root =
      std::filesystem::path(USINA_SHARED_DIR) / "conformance" / "rs274ngc";
  if (!std::filesystem::exists(root / "manifest.tsv")) GTEST_SKIP() << "no " << root;
  std::istringstream manifest(slurp(root / "manifest.tsv"));
  std::string line;
  int checked = 0;
  while (std::getline(manifest, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    std::string id, source, path, table;
    std::getline(row, id, '\t');
    std::getline(row, source, '\t');
    std::getline(row, path, '\t');
    std::getline(row, table, '\t');
    const ProgramFigures f = run_program(root / "programs" / (id + ".ngc"), root / "tools" / table);
    if (!f.ok) continue;
    const ToolStats& t = f.report.total;
    SCOPED_TRACE(id);
    if (f.report.checks.count(core::Code::FeedWithoutRate) != 0) continue;  // no feed to bound
    EXPECT_TRUE(std::isfinite(t.total_s()));
    EXPECT_GE(t.cutting_s, 0.0);
    if (!t.feed.empty() && t.cutting_mm > 0.0) {
      EXPECT_GE(t.cutting_s * (1 + 1e-9), t.cutting_mm / (t.feed.max / 60.0));
    }
    EXPECT_GE(t.rapid_s * (1 + 1e-9), t.rapid_mm / (10000.0 * std::sqrt(3.0) / 60.0));
    EXPECT_GE(t.exact_stop_s * (1 + 1e-9), t.total_s());
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

}  // namespace
}  // namespace usina::sim
