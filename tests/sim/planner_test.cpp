// The planner against velocity profiles worked by hand. Unless a test says
// otherwise: accel a = 1000 mm/s², cruise v = 100 mm/s (F6000), junction
// deviation δ = 0.01 mm. From rest to rest a trapezoid takes L/v + v/a
// (ramps of v/a s each covering v²/2a mm, the rest at v); entering at v0 and
// leaving at v1 it takes L/v + (v−v0)²/(2av) + (v−v1)²/(2av).
#include "sim/planner.hpp"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "sim/planner_geometry.hpp"
#include "sim/planner_profile.hpp"

namespace usina::sim {
namespace {

constexpr double kA = 1000.0;
constexpr double kV = 100.0;
constexpr Vec3 kX{1, 0, 0};
constexpr Vec3 kY{0, 1, 0};

PlannedMove line(double length, Vec3 dir, double v = kV, Kinematics k = {kA, 0.0}) {
  PlannedMove m;
  m.length = length;
  m.start_dir = m.end_dir = dir;
  m.cruise = v;
  m.kin = k;
  return m;
}

double run(const std::vector<PlannedMove>& moves, PlannerSettings s = {}) {
  Planner p(s);
  for (const PlannedMove& m : moves)
    p.add(m);
  p.stop();
  return p.accounts().empty() ? 0.0 : p.accounts()[0].lookahead_s;
}

double exact(const std::vector<PlannedMove>& moves) {
  Planner p({});
  for (const PlannedMove& m : moves)
    p.add(m);
  p.stop();
  return p.accounts()[0].exact_stop_s;
}

// Changing the newest block and replanning (a blend trims it, or takes it
// out) plans the buffer as if the block had come so: the blocks before must
// be able to stop at its end, however far back the change reaches. Slow
// acceleration, so the speed builds over many 1 mm blocks.
std::vector<PlannedMove> ramp(std::size_t count) {
  return std::vector<PlannedMove>(count, line(1.0, kX, kV, {50.0, 0.0}));
}

double lookahead_time(Planner& p) {
  p.stop();
  return p.accounts()[0].lookahead_s;
}

TEST(Planner, ReplanningAChangedLastBlockPlansAsIfItCameSo) {
  Planner trimmed({});
  for (const PlannedMove& m : ramp(30))
    trimmed.add(m);
  trimmed.last_move().length = 0.01;
  trimmed.replan_last();
  std::vector<PlannedMove> moves = ramp(30);
  moves.back().length = 0.01;
  Planner direct({});
  for (const PlannedMove& m : moves)
    direct.add(m);
  EXPECT_DOUBLE_EQ(lookahead_time(trimmed), lookahead_time(direct));
}

TEST(Planner, DroppingTheLastBlockPlansTheRestToStopBeforeIt) {
  Planner dropped({});
  for (const PlannedMove& m : ramp(30))
    dropped.add(m);
  dropped.drop_last();
  Planner direct({});
  for (const PlannedMove& m : ramp(29))
    direct.add(m);
  EXPECT_DOUBLE_EQ(lookahead_time(dropped), lookahead_time(direct));
}

// 100 mm: 0.1 s up to 100 mm/s over 5 mm, 90 mm at 100 mm/s (0.9 s), 0.1 s
// down: 1.1 s = L/v + v/a.
TEST(Planner, SingleMoveReachesItsFeed) {
  EXPECT_NEAR(run({line(100, kX)}), 1.1, 1e-9);
}

// 4 mm is shorter than the 10 mm both ramps need: a triangle peaking at
// sqrt(a L) = 63.246 mm/s, taking 2 sqrt(L/a) = 0.126491 s.
TEST(Planner, ShortMoveIsTriangular) {
  EXPECT_NEAR(run({line(4, kX)}), 2.0 * std::sqrt(4.0 / kA), 1e-9);
  EXPECT_NEAR(run({line(4, kX)}), 0.126491, 1e-6);
}

// 50 + 50 mm in line: no stop between them, so the same 1.1 s as one
// 100 mm move; exact stop stops at the joint: 2 × (0.5 + 0.1) = 1.2 s.
TEST(Planner, CollinearMovesDoNotStop) {
  const std::vector<PlannedMove> moves{line(50, kX), line(50, kX)};
  EXPECT_NEAR(run(moves), 1.1, 1e-9);
  EXPECT_NEAR(exact(moves), 1.2, 1e-9);
}

// 100 mm along X, then 100 mm along Y. θ = 90°, sin(θ/2) = 0.707107:
// v_j² = a δ 0.707107 / 0.292893 = 24.1421, v_j = 4.913465 mm/s (nearly a
// stop). Each move: 1 + 0.05 + (100 − 4.913465)² / 200000 = 1.0952072 s.
TEST(Planner, RightAngleCornerNearlyStops) {
  EXPECT_NEAR(junction_speed(kX, kY, 0.01, kA), 4.913465, 1e-6);
  EXPECT_NEAR(run({line(100, kX), line(100, kY)}), 2.1904144, 1e-6);
  EXPECT_NEAR(exact({line(100, kX), line(100, kY)}), 2.2, 1e-9);
}

// A reversal stops: two moves from rest to rest, 2 × 1.1 s.
TEST(Planner, ReversalStops) {
  EXPECT_EQ(junction_speed(kX, -kX, 0.01, kA), 0.0);
  EXPECT_NEAR(run({line(100, kX), line(100, -kX)}), 2.2, 1e-9);
}

// The junction deviation sets the corner: δ = 1 mm gives v_j² = 2414.21,
// v_j = 49.13465 mm/s; each move 1 + 0.05 + (100 − 49.13465)² / 200000.
TEST(Planner, JunctionDeviationSetsTheCornerSpeed) {
  PlannerSettings s;
  s.junction_deviation = 1.0;
  const double each = 1.0 + 0.05 + std::pow(100.0 - 49.134647, 2) / 200000.0;
  EXPECT_NEAR(run({line(100, kX), line(100, kY)}, s), 2 * each, 1e-6);
}

// A corner between a fast and a slow move passes at most the slower cruise:
// 100 mm at 100 then 100 mm at 50 mm/s, in line: the first move slows to 50
// (1 + 0.05 + 50²/200000 = 1.0625 s), the second runs at 50 and stops
// (2 + 50²/(2·1000·50) = 2.025 s).
TEST(Planner, JunctionLimitedByTheSlowerMove) {
  EXPECT_NEAR(run({line(100, kX), line(100, kX, 50)}), 1.0625 + 2.025, 1e-9);
}

// Look-ahead is bounded: 1000 collinear moves of 0.1 mm. A buffer of 200
// blocks (20 mm) holds the 5 mm it takes to stop from 100 mm/s: 1.1 s as one
// move. A buffer of 10 blocks (1 mm) must be able to stop within 1 mm, so it
// cannot exceed sqrt(2 a 1 mm) = 44.7 mm/s: at least 100 / 44.7 = 2.24 s.
TEST(Planner, LookAheadIsBounded) {
  const std::vector<PlannedMove> moves(1000, line(0.1, kX));
  EXPECT_NEAR(run(moves), 1.1, 1e-6);
  PlannerSettings short_buffer;
  short_buffer.lookahead = 10;
  EXPECT_GT(run(moves, short_buffer), 100.0 / std::sqrt(2.0 * kA * 1.0));
}

// stop() (a dwell, a tool change) ends the motion at rest: 2 × 0.6 s + 2 s.
TEST(Planner, WaitStopsAndAddsItsTime) {
  Planner p({});
  p.add(line(50, kX));
  p.wait(2.0, 0);
  p.add(line(50, kX));
  p.stop();
  EXPECT_NEAR(p.accounts()[0].lookahead_s, 1.2 + 2.0, 1e-9);
  EXPECT_NEAR(p.accounts()[0].exact_stop_s, 1.2 + 2.0, 1e-9);
}

TEST(Planner, TimesGoToTheirAccounts) {
  Planner p({});
  PlannedMove a = line(100, kX);
  PlannedMove b = line(100, kY);
  b.account = 2;
  p.add(a);
  p.add(b);
  p.stop();
  ASSERT_EQ(p.accounts().size(), 3u);
  EXPECT_NEAR(p.accounts()[0].lookahead_s, 1.0952072, 1e-6);
  EXPECT_EQ(p.accounts()[1].lookahead_s, 0.0);
  EXPECT_NEAR(p.accounts()[2].lookahead_s, 1.0952072, 1e-6);
}

TEST(Planner, ZeroLengthMovesAreIgnored) {
  EXPECT_EQ(run({line(0, kX)}), 0.0);
  EXPECT_NEAR(run({line(50, kX), line(0, kY), line(50, kX)}), 1.1, 1e-9);
}

// --- S-curve ------------------------------------------------------------------

// Jerk j = 20000 mm/s³: a²/j = 50 mm/s < 100, so a change to 100 mm/s
// reaches the acceleration limit and takes v/a + a/j = 0.15 s, covering
// v/2 × 0.15 = 7.5 mm. From rest to rest: L/v + v/a + a/j = 1.15 s.
TEST(PlannerSCurve, LongMoveMatchesTheClosedForm) {
  const Kinematics k{kA, 20000.0};
  EXPECT_NEAR(change_time(100, k), 0.15, 1e-12);
  EXPECT_NEAR(change_distance(0, 100, k), 7.5, 1e-12);
  EXPECT_NEAR(run({line(100, kX, kV, k)}), 1.15, 1e-9);
}

// 1 mm with j = 20000: the acceleration never reaches its limit. Up and
// down to a peak vp take 2 sqrt(vp/j) each and cover vp × 2 sqrt(vp/j) =
// 1 mm: vp = (L sqrt(j) / 2)^(2/3) = 17.0998 mm/s, total 4 (L/2j)^(1/3) =
// 0.116961 s.
TEST(PlannerSCurve, ShortMoveMatchesTheClosedForm) {
  const Kinematics k{kA, 20000.0};
  EXPECT_NEAR(run({line(1, kX, kV, k)}), 4.0 * std::cbrt(1.0 / 40000.0), 1e-7);
}

// S-curve takes longer than the trapezoid on the same move.
TEST(PlannerSCurve, SlowerThanTrapezoid) {
  EXPECT_GT(run({line(100, kX, kV, {kA, 5000.0})}), run({line(100, kX)}));
}

// reachable_speed inverts change_distance, both below and above a²/j.
TEST(PlannerSCurve, ReachableSpeedInvertsTheDistance) {
  const Kinematics k{kA, 20000.0};
  for (const double v_end : {0.0, 10.0, 80.0}) {
    for (const double length : {0.01, 0.5, 3.0, 40.0}) {
      const double v = reachable_speed(v_end, length, k);
      EXPECT_NEAR(change_distance(v_end, v, k), length, 1e-9 * (1 + length))
          << v_end << " " << length;
    }
  }
  EXPECT_NEAR(reachable_speed(0, 5, {kA, 0.0}), 100.0, 1e-12);
}

// --- geometry ---------------------------------------------------------------

MachineProfile two_axis_profile() {
  MachineProfile m;
  for (std::size_t i = 0; i < 3; ++i) {
    m.axes[i] = {true, -1000, 1000, 12000, 6000, kA, 0};
  }
  m.axes[1].rapid = 6000;  // Y: 100 mm/s
  m.axes[2].jerk = 5000;
  return m;
}

// G0 X100 Y100: each axis moves 0.7071 mm per mm of path. X allows 200 /
// 0.7071 = 282.8 mm/s, Y 100 / 0.7071 = 141.42 mm/s: Y, the slowest, sets it.
TEST(PlannerGeometry, RapidLimitedByTheSlowestAxis) {
  const MachineProfile m = two_axis_profile();
  const AxisShare s = straight_share({0, 0, 0, 0, 0, 0}, {100, 100, 0, 0, 0, 0}, std::sqrt(2e4));
  int axis = -1;
  EXPECT_NEAR(along_path(m, s, AxisRate::Rapid, &axis), 100.0 * std::sqrt(2.0), 1e-9);
  EXPECT_EQ(axis, 1);
  EXPECT_NEAR(along_path(m, s, AxisRate::Accel), kA * std::sqrt(2.0), 1e-9);
  // X and Y have no jerk limit: trapezoidal.
  EXPECT_EQ(along_path(m, s, AxisRate::Jerk), 0.0);
  // Z alone: its jerk, S-curve.
  const AxisShare z = straight_share({0, 0, 0, 0, 0, 0}, {0, 0, 10, 0, 0, 0}, 10);
  EXPECT_EQ(along_path(m, z, AxisRate::Jerk), 5000.0);
}

// path_rates is along_path for every rate at once: the same numbers, bit
// for bit, on random profiles (axes absent, jerk 0) and moves (axes still).
TEST(PlannerGeometry, PathRatesAreAlongPathForEachRate) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> figure(0.0, 20000.0);
  std::uniform_real_distribution<double> delta(-50.0, 50.0);
  for (int n = 0; n < 5000; ++n) {
    MachineProfile m;
    for (AxisLimits& a : m.axes) {
      a.present = rng() % 4 != 0;
      a.rapid = figure(rng);
      a.max_feed = figure(rng);
      a.accel = figure(rng);
      a.jerk = rng() % 3 == 0 ? 0.0 : figure(rng);
    }
    Axes6 to{};
    for (double& d : to)
      d = rng() % 3 == 0 ? 0.0 : delta(rng);
    double length = 0.0;
    for (const double d : to)
      length += d * d;
    const AxisShare s = straight_share({}, to, std::sqrt(length));
    const PathRates r = path_rates(m, s);
    int axis = -2;
    EXPECT_EQ(r.max_feed, along_path(m, s, AxisRate::MaxFeed, &axis));
    EXPECT_EQ(r.max_feed_axis, axis);
    EXPECT_EQ(r.rapid, along_path(m, s, AxisRate::Rapid));
    EXPECT_EQ(r.accel, along_path(m, s, AxisRate::Accel));
    EXPECT_EQ(r.jerk, along_path(m, s, AxisRate::Jerk));
  }
}

// A half circle of radius 1 from (0,0) to (2,0) about (1,0), counter-
// clockwise: through (1,-1), length π.
TEST(PlannerGeometry, ArcPathAndExtent) {
  canon::Arc a;
  a.to = {2, 0, 0};
  a.center = {1, 0, 0};
  a.normal = {0, 0, 1};
  a.turn = 1;
  const auto p = arc_path({0, 0, 0}, a);
  ASSERT_TRUE(p.has_value());
  EXPECT_NEAR(p->radius, 1.0, 1e-12);
  EXPECT_NEAR(p->sweep, M_PI, 1e-12);
  EXPECT_NEAR(p->length, M_PI, 1e-12);
  EXPECT_NEAR(p->start_tangent.y, -1.0, 1e-12);  // leaves (0,0) going down
  EXPECT_NEAR(p->end_tangent.y, 1.0, 1e-12);
  Vec3 lo{1e9, 1e9, 1e9};
  Vec3 hi{-1e9, -1e9, -1e9};
  arc_extent(*p, lo, hi);
  EXPECT_NEAR(lo.y, -1.0, 1e-12);
  EXPECT_NEAR(hi.y, 0.0, 1e-12);
  EXPECT_NEAR(lo.x, 0.0, 1e-12);
  EXPECT_NEAR(hi.x, 2.0, 1e-12);
  // Clockwise the other half: through (1, 1).
  a.turn = -1;
  const auto q = arc_path({0, 0, 0}, a);
  ASSERT_TRUE(q.has_value());
  EXPECT_NEAR(q->sweep, -M_PI, 1e-12);
  lo = {1e9, 1e9, 1e9};
  hi = {-1e9, -1e9, -1e9};
  arc_extent(*q, lo, hi);
  EXPECT_NEAR(hi.y, 1.0, 1e-12);
  EXPECT_NEAR(lo.y, 0.0, 1e-12);
}

// A helix: two turns of radius 5 rising 10 mm along Z: length
// sqrt((2 · 2π · 5)² + 10²).
TEST(PlannerGeometry, HelixLength) {
  canon::Arc a;
  a.to = {5, 0, 10};
  a.center = {0, 0, 0};
  a.normal = {0, 0, 1};
  a.turn = 2;
  const auto p = arc_path({5, 0, 0}, a);
  ASSERT_TRUE(p.has_value());
  EXPECT_NEAR(p->length, std::hypot(4 * M_PI * 5, 10.0), 1e-9);
  EXPECT_NEAR(p->axial, 10.0, 1e-12);
}

TEST(PlannerGeometry, DegenerateArcIsNotAPath) {
  canon::Arc a;
  a.to = {0, 0, 0};
  a.center = {0, 0, 0};
  a.normal = {0, 0, 1};
  EXPECT_FALSE(arc_path({0, 0, 0}, a).has_value());
}

}  // namespace
}  // namespace usina::sim
