// Times are never negative, infinite or NaN: the stats sink checks canon's
// range (canon/limits.hpp) before it times an op, and the planner leaves out
// of every account a time that is not one (issue 11: `G2 X1 Y0 R[10**200]`
// gave a negative cycle time).
#include <cmath>
#include <limits>
#include <memory>

#include <gtest/gtest.h>

#include "canon/limits.hpp"
#include "sim/planner.hpp"
#include "sim/stats.hpp"

namespace usina::sim {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

bool is_time(double t) {
  return std::isfinite(t) && t >= 0.0;
}

void expect_times(const StatsReport& r) {
  EXPECT_TRUE(is_time(r.total.total_s())) << r.total.total_s();
  EXPECT_TRUE(is_time(r.total.exact_stop_s)) << r.total.exact_stop_s;
  EXPECT_TRUE(std::isfinite(r.total.cutting_mm)) << r.total.cutting_mm;
  EXPECT_TRUE(std::isfinite(r.cost)) << r.cost;
  for (const ToolStats& t : r.tools) {
    EXPECT_TRUE(is_time(t.cutting_s) && is_time(t.rapid_s) && is_time(t.other_s));
  }
}

int errors_of(const core::DiagnosticList& d, core::Code code) {
  int n = 0;
  for (const core::Diagnostic& x : d.all())
    n += x.code == code && x.severity == core::Severity::Error ? 1 : 0;
  return n;
}

struct Timed {
  core::DiagnosticList diags;
  MachineProfile profile = default_machine_profile();
  std::unique_ptr<StatsSink> sink;

  Timed() { sink = std::make_unique<StatsSink>(profile, StatsOptions{}, diags); }

  void operator()(canon::OpKind k) {
    sink->on(canon::Op{std::move(k), core::SourceLoc{0, 1, 1, 1, 0}});
  }

  StatsReport done() {
    sink->finish();
    return sink->report();
  }
};

TEST(FiniteTimes, AnArcWithANanCentreIsReportedAndLeftOut) {
  Timed run;
  run(canon::Feed{{10, 0, 0}, 600.0, {}});
  // What the interpreter sent before canon's range: the G2 R[10**200].
  run(canon::Arc{{1, 0, 0}, {-kNan, -kInf, 0}, {0, 0, 1}, -1, 100.0, {}});
  run(canon::Feed{{20, 0, 0}, 600.0, {}});
  const StatsReport r = run.done();
  expect_times(r);
  EXPECT_EQ(errors_of(run.diags, core::Code::ValueOutOfRange), 1);
  EXPECT_NEAR(r.total.cutting_mm, 20.0, 1e-9);  // the two good moves
}

TEST(FiniteTimes, PositionsBeyondTheRangeAreLeftOut) {
  Timed run;
  run(canon::Traverse{{1e308, 0, 0}});
  run(canon::Traverse{{kInf, 0, 0}});
  run(canon::Dwell{kInf});
  run(canon::Dwell{-5.0});
  run(canon::Spindle{kNan, canon::SpindleDir::Cw});
  const StatsReport r = run.done();
  expect_times(r);
  EXPECT_EQ(r.total.total_s(), 0.0);
  EXPECT_EQ(errors_of(run.diags, core::Code::ValueOutOfRange), 1);  // reported once
}

TEST(FiniteTimes, AHugeButInRangeMoveAtTheSmallestFeedHasAFiniteTime) {
  Timed run;
  run(canon::Feed{{1e9, 1e9, 1e9}, canon::kMinFeed, {}});
  run(canon::Arc{
      {-1e9, 1e9, 1e9}, {0, 1e9, 1e9}, {0, 0, 1}, canon::kMaxTurns, canon::kMinFeed, {}});
  const StatsReport r = run.done();
  expect_times(r);
  EXPECT_GT(r.total.cutting_s, 1e20);
  EXPECT_FALSE(run.diags.has_errors());
}

TEST(FiniteTimes, PlannerLeavesOutATimeThatIsNotOne) {
  Planner p(PlannerSettings{});
  PlannedMove good;
  good.length = 10.0;
  good.start_dir = good.end_dir = {1, 0, 0};
  good.cruise = 10.0;
  good.kin = {100.0, 0.0};
  p.add(good);
  PlannedMove no_accel = good;  // a profile's accel = 0: the ramps take forever
  no_accel.kin = {0.0, 0.0};
  p.add(no_accel);
  PlannedMove nan_length = good;
  nan_length.length = kNan;
  p.add(nan_length);
  p.wait(kNan, 0);
  p.wait(-1.0, 0);
  p.stop();
  ASSERT_FALSE(p.accounts().empty());
  EXPECT_TRUE(is_time(p.accounts()[0].lookahead_s)) << p.accounts()[0].lookahead_s;
  EXPECT_TRUE(is_time(p.accounts()[0].exact_stop_s)) << p.accounts()[0].exact_stop_s;
  EXPECT_GT(p.accounts()[0].lookahead_s, 1.0);  // the good move's 1.1 s at least
  EXPECT_GE(p.untimed(), 3u);
}

TEST(FiniteTimes, AnUntimedMoveIsAnErrorOfTheRun) {
  Timed run;
  run.profile.axes[0].accel = 0.0;
  run.sink = std::make_unique<StatsSink>(run.profile, StatsOptions{}, run.diags);
  run(canon::Feed{{10, 0, 0}, 600.0, {}});
  const StatsReport r = run.done();
  expect_times(r);
  EXPECT_EQ(errors_of(run.diags, core::Code::ValueOutOfRange), 1);
}

}  // namespace
}  // namespace usina::sim
