#include "gcode/interp/canned_cycles.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

// Expected moves come from three places, said at each test:
// - "conformance": a LinuxCNC 2.10 trace of shared/conformance/rs274ngc
//   (expected/<id>.jsonl), the program's blocks translated into run() calls
//   by hand (G20: every length x 25.4; its G0 lines become Machine::rapid);
// - "rs274": LinuxCNC 2.9's stand-alone interpreter (Debian linuxcnc-uspace,
//   shared/conformance/lcnc-trace.sh) on the program quoted in the test; its
//   G73/G83 peck clearance is 0.254 mm, so those tests set it;
// - by hand, from the rule the test names.
// The trailing spindle-off of M2 is left out of every trace.

namespace usina::gcode {
namespace {

using canon::SpindleDir;
using core::Code;
using core::Plane;

struct Op {
  enum class Kind { Traverse, Feed, Dwell, Spindle };
  Kind kind = Kind::Traverse;
  Vec3 to;
  double s = 0.0;
  SpindleDir dir = SpindleDir::Off;
};

Op rapid_to(double x, double y, double z) {
  return {Op::Kind::Traverse, {x, y, z}};
}

Op feed_to(double x, double y, double z) {
  return {Op::Kind::Feed, {x, y, z}};
}

Op dwell_for(double s) {
  return {Op::Kind::Dwell, {}, s};
}

constexpr Op kCw{Op::Kind::Spindle, {}, 0.0, SpindleDir::Cw};
constexpr Op kCcw{Op::Kind::Spindle, {}, 0.0, SpindleDir::Ccw};
constexpr Op kOff{Op::Kind::Spindle, {}, 0.0, SpindleDir::Off};

std::string describe(const Op& op) {
  switch (op.kind) {
  case Op::Kind::Traverse:
    return fmt::format("rapid_to({:g}, {:g}, {:g})", op.to.x, op.to.y, op.to.z);
  case Op::Kind::Feed: return fmt::format("feed_to({:g}, {:g}, {:g})", op.to.x, op.to.y, op.to.z);
  case Op::Kind::Dwell: return fmt::format("dwell_for({:g})", op.s);
  case Op::Kind::Spindle:
    return op.dir == SpindleDir::Cw ? "kCw" : (op.dir == SpindleDir::Ccw ? "kCcw" : "kOff");
  }
  return "?";
}

bool same(const Op& a, const Op& b, double tol) {
  if (a.kind != b.kind) return false;
  switch (a.kind) {
  case Op::Kind::Traverse:
  case Op::Kind::Feed: return distance(a.to, b.to) <= tol;
  case Op::Kind::Dwell: return std::abs(a.s - b.s) <= 1e-9;
  case Op::Kind::Spindle: return a.dir == b.dir;
  }
  return false;
}

// The moves in order; positions within `tol` mm (LinuxCNC's traces are
// printed to 4 decimals of the program's unit: 0.002 mm is the trace rule).
testing::AssertionResult same_ops(const std::vector<Op>& actual, const std::vector<Op>& expected,
                                  double tol = 1e-9) {
  std::size_t n = 0;
  while (n < actual.size() && n < expected.size() && same(actual[n], expected[n], tol))
    ++n;
  if (n == actual.size() && n == expected.size()) return testing::AssertionSuccess();
  auto r = testing::AssertionFailure();
  r << "first difference at op " << n << " (" << actual.size() << " ops, expected "
    << expected.size() << ")\n";
  for (std::size_t i = 0; i < std::max(actual.size(), expected.size()); ++i) {
    r << (i == n ? "> " : "  ") << (i < actual.size() ? describe(actual[i]) : "-") << "   "
      << (i < expected.size() ? describe(expected[i]) : "-") << "\n";
  }
  return r;
}

testing::AssertionResult ok(const std::optional<InterpError>& e) {
  if (!e) return testing::AssertionSuccess();
  return testing::AssertionFailure() << "error: " << e->message;
}

testing::AssertionResult fails(const std::optional<InterpError>& e, Code code,
                               const std::string& part) {
  if (!e) return testing::AssertionFailure() << "no error";
  if (e->code != code || e->message.find(part) == std::string::npos) {
    return testing::AssertionFailure()
           << "code " << static_cast<int>(e->code) << ": " << e->message;
  }
  return testing::AssertionSuccess();
}

class Recorder final : public MotionTarget {
 public:
  void traverse(const Vec3& to) override { record(rapid_to(to.x, to.y, to.z), to); }

  void feed(const Vec3& to) override { record(feed_to(to.x, to.y, to.z), to); }

  void arc(const Vec3&, const Vec3&, int) override { ADD_FAILURE() << "a cycle made an arc"; }

  void dwell(double s) override { ops.push_back(dwell_for(s)); }

  void spindle(SpindleDir d) override { ops.push_back({Op::Kind::Spindle, {}, 0.0, d}); }

  void hole(const Vec3& top, double depth) override { holes.emplace_back(top, depth); }

  Vec3 position() const override { return pos; }

  void set_source(const core::SourceLoc&) override {}

  Vec3 pos;
  std::vector<Op> ops;
  std::vector<std::pair<Vec3, double>> holes;

 private:
  void record(const Op& op, const Vec3& to) {
    ops.push_back(op);
    pos = to;
  }
};

// Calls the cycles as the interpreter must: motion_mode_changed when the
// last motion was another one, note_other_motion() for every other motion,
// and end_point() as the current point after a cycle block.
class Machine {
 public:
  explicit Machine(double unit = 1.0) { modal.length_unit = unit; }

  std::optional<InterpError> cycle(int motion, const CycleWords& w) {
    modal.motion = motion;
    modal.motion_mode_changed = motion != last_motion_;
    auto r = cycles.run(w, modal, rec);
    std::optional<InterpError> e;
    if (r) {
      rec.pos = cycles.end_point();
      last_motion_ = motion;
    } else {
      e = r.error();
    }
    return e;
  }

  void rapid(const Vec3& to) {
    cycles.note_other_motion();
    rec.traverse(to);
    last_motion_ = 0;
  }

  CycleModal modal;
  Recorder rec;
  CannedCycles cycles;

 private:
  int last_motion_ = 800;
};

constexpr double kInch = 25.4;

Vec3 inches(double x, double y, double z) {
  return Vec3{x, y, z} * kInch;
}

// A G20 block's words in mm.
CycleWords inches(CycleWords w) {
  for (std::optional<double>* v :
       {&w.x, &w.y, &w.z, &w.r, &w.q, &w.i, &w.j, &w.k, &w.e, &w.polar_radius}) {
    if (*v) **v *= kInch;
  }
  return w;
}

// The conformance programs tests/interp/{g81,g84}/{g17,g18,g19}/{g98,g99}
// share one shape. a, b, c are their three words in the order written:
// X Y Z in G17, X Z Y in G18, Y Z X in G19 (c is on the plane's normal).
Vec3 interp_test_point(Plane plane, double a, double b, double c) {
  switch (plane) {
  case Plane::XY: return inches(a, b, c);
  case Plane::ZX: return inches(a, c, b);
  case Plane::YZ: return inches(c, a, b);
  }
  return {};
}

CycleWords interp_test_words(Plane plane, double a, double b, double c, double r,
                             std::optional<double> l = std::nullopt) {
  const Vec3 p = interp_test_point(plane, a, b, c) / kInch;
  return inches({.x = p.x, .y = p.y, .z = p.z, .r = r, .l = l});
}

// g0 to (0 0 2); three absolute cycles, the first as `first_motion`; then
// three times: G90 G0 to (10|20|30, 0, 2), a G91 cycle repeated twice.
void run_interp_test_program(Machine& m, int first_motion, int motion) {
  const Plane pl = m.modal.plane;
  m.rapid(interp_test_point(pl, 0, 0, 2));
  EXPECT_TRUE(ok(m.cycle(first_motion, interp_test_words(pl, 1, 1, -1, 1))));
  EXPECT_TRUE(ok(m.cycle(motion, interp_test_words(pl, 1, 2, 0.5, 3))));
  EXPECT_TRUE(ok(m.cycle(motion, interp_test_words(pl, 1, 3, 4, 5))));
  // (bottom from R, R from the initial level) of the three G91 blocks
  const std::array<std::pair<double, double>, 3> incremental{{{-2, -1}, {-2.5, 1}, {-1, 3}}};
  double x = 10;
  for (const auto& [depth, r] : incremental) {
    m.modal.incremental = false;
    m.rapid(interp_test_point(pl, x, 0, 2));
    m.modal.incremental = true;
    EXPECT_TRUE(ok(m.cycle(motion, interp_test_words(pl, 1, 1, depth, r, 2))));
    x += 10;
  }
}

Machine interp_test_machine(Plane plane, bool g99, SpindleDir spindle = SpindleDir::Off) {
  Machine m(kInch);
  m.modal.plane = plane;
  m.modal.retract_to_r = g99;
  m.modal.spindle = spindle;
  if (spindle != SpindleDir::Off) m.rec.spindle(spindle);  // the program's M3
  return m;
}

// ---------------------------------------------------------------- G81

// conformance linuxcnc__tests__interp__g81__g17__g98__g17-g98-g81: all six
// orders of bottom, initial level and R, absolute and G91 with L2.
TEST(G81, MatchesLinuxCncTraceInG17WithG98) {
  Machine m = interp_test_machine(Plane::XY, false);
  run_interp_test_program(m, 810, 810);
  EXPECT_TRUE(same_ops(
      m.rec.ops,
      {rapid_to(0, 0, 50.8),        rapid_to(25.4, 25.4, 50.8),  rapid_to(25.4, 25.4, 25.4),
       feed_to(25.4, 25.4, -25.4),  rapid_to(25.4, 25.4, 50.8),  rapid_to(25.4, 25.4, 76.2),
       rapid_to(25.4, 50.8, 76.2),  feed_to(25.4, 50.8, 12.7),   rapid_to(25.4, 50.8, 76.2),
       rapid_to(25.4, 50.8, 127),   rapid_to(25.4, 76.2, 127),   feed_to(25.4, 76.2, 101.6),
       rapid_to(25.4, 76.2, 127),   rapid_to(254, 0, 50.8),      rapid_to(279.4, 25.4, 50.8),
       rapid_to(279.4, 25.4, 25.4), feed_to(279.4, 25.4, -25.4), rapid_to(279.4, 25.4, 50.8),
       rapid_to(304.8, 50.8, 50.8), rapid_to(304.8, 50.8, 25.4), feed_to(304.8, 50.8, -25.4),
       rapid_to(304.8, 50.8, 50.8), rapid_to(508, 0, 50.8),      rapid_to(508, 0, 76.2),
       rapid_to(533.4, 25.4, 76.2), feed_to(533.4, 25.4, 12.7),  rapid_to(533.4, 25.4, 76.2),
       rapid_to(558.8, 50.8, 76.2), feed_to(558.8, 50.8, 12.7),  rapid_to(558.8, 50.8, 76.2),
       rapid_to(762, 0, 50.8),      rapid_to(762, 0, 127),       rapid_to(787.4, 25.4, 127),
       feed_to(787.4, 25.4, 101.6), rapid_to(787.4, 25.4, 127),  rapid_to(812.8, 50.8, 127),
       feed_to(812.8, 50.8, 101.6), rapid_to(812.8, 50.8, 127)},
      2e-3));
}

// conformance linuxcnc__tests__interp__g81__g18__g99__g18-g99-g81: drills along Y.
TEST(G81, MatchesLinuxCncTraceInG18WithG99) {
  Machine m = interp_test_machine(Plane::ZX, true);
  run_interp_test_program(m, 810, 810);
  EXPECT_TRUE(same_ops(
      m.rec.ops,
      {rapid_to(0, 50.8, 0),        rapid_to(25.4, 50.8, 25.4),  rapid_to(25.4, 25.4, 25.4),
       feed_to(25.4, -25.4, 25.4),  rapid_to(25.4, 25.4, 25.4),  rapid_to(25.4, 76.2, 25.4),
       rapid_to(25.4, 76.2, 50.8),  feed_to(25.4, 12.7, 50.8),   rapid_to(25.4, 76.2, 50.8),
       rapid_to(25.4, 127, 50.8),   rapid_to(25.4, 127, 76.2),   feed_to(25.4, 101.6, 76.2),
       rapid_to(25.4, 127, 76.2),   rapid_to(254, 50.8, 0),      rapid_to(279.4, 50.8, 25.4),
       rapid_to(279.4, 25.4, 25.4), feed_to(279.4, -25.4, 25.4), rapid_to(279.4, 25.4, 25.4),
       rapid_to(304.8, 25.4, 50.8), feed_to(304.8, -25.4, 50.8), rapid_to(304.8, 25.4, 50.8),
       rapid_to(508, 50.8, 0),      rapid_to(508, 76.2, 0),      rapid_to(533.4, 76.2, 25.4),
       feed_to(533.4, 12.7, 25.4),  rapid_to(533.4, 76.2, 25.4), rapid_to(558.8, 76.2, 50.8),
       feed_to(558.8, 12.7, 50.8),  rapid_to(558.8, 76.2, 50.8), rapid_to(762, 50.8, 0),
       rapid_to(762, 127, 0),       rapid_to(787.4, 127, 25.4),  feed_to(787.4, 101.6, 25.4),
       rapid_to(787.4, 127, 25.4),  rapid_to(812.8, 127, 50.8),  feed_to(812.8, 101.6, 50.8),
       rapid_to(812.8, 127, 50.8)},
      2e-3));
}

// conformance linuxcnc__tests__interp__g81__g19__g98__g19-g98-g81: drills along X.
TEST(G81, MatchesLinuxCncTraceInG19WithG98) {
  Machine m = interp_test_machine(Plane::YZ, false);
  run_interp_test_program(m, 810, 810);
  EXPECT_TRUE(same_ops(
      m.rec.ops,
      {rapid_to(50.8, 0, 0),        rapid_to(50.8, 25.4, 25.4),  rapid_to(25.4, 25.4, 25.4),
       feed_to(-25.4, 25.4, 25.4),  rapid_to(50.8, 25.4, 25.4),  rapid_to(76.2, 25.4, 25.4),
       rapid_to(76.2, 25.4, 50.8),  feed_to(12.7, 25.4, 50.8),   rapid_to(76.2, 25.4, 50.8),
       rapid_to(127, 25.4, 50.8),   rapid_to(127, 25.4, 76.2),   feed_to(101.6, 25.4, 76.2),
       rapid_to(127, 25.4, 76.2),   rapid_to(50.8, 254, 0),      rapid_to(50.8, 279.4, 25.4),
       rapid_to(25.4, 279.4, 25.4), feed_to(-25.4, 279.4, 25.4), rapid_to(50.8, 279.4, 25.4),
       rapid_to(50.8, 304.8, 50.8), rapid_to(25.4, 304.8, 50.8), feed_to(-25.4, 304.8, 50.8),
       rapid_to(50.8, 304.8, 50.8), rapid_to(50.8, 508, 0),      rapid_to(76.2, 508, 0),
       rapid_to(76.2, 533.4, 25.4), feed_to(12.7, 533.4, 25.4),  rapid_to(76.2, 533.4, 25.4),
       rapid_to(76.2, 558.8, 50.8), feed_to(12.7, 558.8, 50.8),  rapid_to(76.2, 558.8, 50.8),
       rapid_to(50.8, 762, 0),      rapid_to(127, 762, 0),       rapid_to(127, 787.4, 25.4),
       feed_to(101.6, 787.4, 25.4), rapid_to(127, 787.4, 25.4),  rapid_to(127, 812.8, 50.8),
       feed_to(101.6, 812.8, 50.8), rapid_to(127, 812.8, 50.8)},
      2e-3));
}

// conformance linuxcnc__nc_files__hole-circle:
//   G20 G17 G90 / G0 X1.5 Y0 Z0 / G91 G81 R.1 Z-.5 ^60 L6 F10
TEST(G81, IncrementalPolarAngleStepsRoundABoltCircle) {
  Machine m(kInch);
  m.rapid(inches(1.5, 0, 0));
  m.modal.incremental = true;
  EXPECT_TRUE(ok(m.cycle(810, inches({.z = -.5, .r = .1, .l = 6, .polar_angle = 60}))));
  EXPECT_TRUE(same_ops(m.rec.ops,
                       {rapid_to(38.1, 0, 0),
                        rapid_to(38.1, 0, 2.54),
                        rapid_to(19.05, 32.9946, 2.54),
                        feed_to(19.05, 32.9946, -10.16),
                        rapid_to(19.05, 32.9946, 2.54),
                        rapid_to(-19.05, 32.9946, 2.54),
                        feed_to(-19.05, 32.9946, -10.16),
                        rapid_to(-19.05, 32.9946, 2.54),
                        rapid_to(-38.1, 0, 2.54),
                        feed_to(-38.1, 0, -10.16),
                        rapid_to(-38.1, 0, 2.54),
                        rapid_to(-19.05, -32.9946, 2.54),
                        feed_to(-19.05, -32.9946, -10.16),
                        rapid_to(-19.05, -32.9946, 2.54),
                        rapid_to(19.05, -32.9946, 2.54),
                        feed_to(19.05, -32.9946, -10.16),
                        rapid_to(19.05, -32.9946, 2.54),
                        rapid_to(38.1, 0, 2.54),
                        feed_to(38.1, 0, -10.16),
                        rapid_to(38.1, 0, 2.54)},
                       2e-3));
}

// conformance linuxcnc__nc_files__polar, up to its G90 G0 X2 Y0:
//   G20 G90 / G0 X0 Y0 Z0 / G0 X2.5 Y0 / G81 R.1 Z-0.5 F60 / ^120 / ^240 /
//   G90 @1 ^33 / G91 G81 @1 R.1 Z-0.5 L5
// Every block starts below R (the initial level is Z0), so each rises to R
// in place first.
TEST(G81, PolarWordsPlaceAndStepHoles) {
  Machine m(kInch);
  m.rapid(inches(0, 0, 0));
  m.rapid(inches(2.5, 0, 0));
  EXPECT_TRUE(ok(m.cycle(810, inches({.z = -0.5, .r = .1}))));
  EXPECT_TRUE(ok(m.cycle(810, {.polar_angle = 120})));
  EXPECT_TRUE(ok(m.cycle(810, {.polar_angle = 240})));
  EXPECT_TRUE(ok(m.cycle(810, inches({.polar_radius = 1, .polar_angle = 33}))));
  m.modal.incremental = true;
  EXPECT_TRUE(ok(m.cycle(810, inches({.z = -0.5, .r = .1, .l = 5, .polar_radius = 1}))));
  EXPECT_TRUE(same_ops(m.rec.ops,
                       {rapid_to(0, 0, 0),
                        rapid_to(63.5, 0, 0),
                        rapid_to(63.5, 0, 2.54),
                        rapid_to(63.5, 0, 2.54),
                        feed_to(63.5, 0, -12.7),
                        rapid_to(63.5, 0, 2.54),
                        rapid_to(63.5, 0, 2.54),
                        rapid_to(-31.75, 54.99354, 2.54),
                        feed_to(-31.75, 54.99354, -12.7),
                        rapid_to(-31.75, 54.99354, 2.54),
                        rapid_to(-31.75, 54.99354, 2.54),
                        rapid_to(-31.75, -54.99354, 2.54),
                        feed_to(-31.75, -54.99354, -12.7),
                        rapid_to(-31.75, -54.99354, 2.54),
                        rapid_to(-31.75, -54.99354, 2.54),
                        rapid_to(21.30298, 13.83284, 2.54),
                        feed_to(21.30298, 13.83284, -12.7),
                        rapid_to(21.30298, 13.83284, 2.54),
                        rapid_to(21.30298, 13.83284, 2.54),
                        rapid_to(42.60342, 27.66822, 2.54),
                        feed_to(42.60342, 27.66822, -10.16),
                        rapid_to(42.60342, 27.66822, 2.54),
                        rapid_to(63.9064, 41.50106, 2.54),
                        feed_to(63.9064, 41.50106, -10.16),
                        rapid_to(63.9064, 41.50106, 2.54),
                        rapid_to(85.20938, 55.33644, 2.54),
                        feed_to(85.20938, 55.33644, -10.16),
                        rapid_to(85.20938, 55.33644, 2.54),
                        rapid_to(106.51236, 69.16928, 2.54),
                        feed_to(106.51236, 69.16928, -10.16),
                        rapid_to(106.51236, 69.16928, 2.54),
                        rapid_to(127.8128, 83.00212, 2.54),
                        feed_to(127.8128, 83.00212, -10.16),
                        rapid_to(127.8128, 83.00212, 2.54)},
                       2e-3));
}

// By hand: G98 from Z10: over the hole, down to R, feed, back to Z10.
TEST(G81, RetractsToTheInitialLevelWithG98) {
  Machine m;
  m.rapid({0, 0, 10});
  EXPECT_TRUE(ok(m.cycle(810, {.x = 1, .y = 2, .z = -3, .r = 2})));
  EXPECT_TRUE(same_ops(m.rec.ops, {rapid_to(0, 0, 10), rapid_to(1, 2, 10), rapid_to(1, 2, 2),
                                   feed_to(1, 2, -3), rapid_to(1, 2, 10)}));
  EXPECT_EQ(m.cycles.end_point(), (Vec3{1, 2, 10}));
}

TEST(G81, RetractsToRWithG99) {
  Machine m;
  m.modal.retract_to_r = true;
  m.rapid({0, 0, 10});
  EXPECT_TRUE(ok(m.cycle(810, {.x = 1, .y = 2, .z = -3, .r = 2})));
  EXPECT_TRUE(same_ops(m.rec.ops, {rapid_to(0, 0, 10), rapid_to(1, 2, 10), rapid_to(1, 2, 2),
                                   feed_to(1, 2, -3), rapid_to(1, 2, 2)}));
  EXPECT_EQ(m.cycles.end_point(), (Vec3{1, 2, 2}));
}

// interp_cycles.cc: "if we're below the R plane, rapid straight up to the R plane".
TEST(G81, RisesStraightToRWhenStartingBelowIt) {
  Machine m;
  m.rapid({0, 0, 1});
  EXPECT_TRUE(ok(m.cycle(810, {.x = 4, .y = 5, .z = -3, .r = 2})));
  EXPECT_TRUE(same_ops(m.rec.ops, {rapid_to(0, 0, 1), rapid_to(0, 0, 2), rapid_to(4, 5, 2),
                                   feed_to(4, 5, -3), rapid_to(4, 5, 2)}));
}

// The brief's example: G81 X1 Y1 Z-1 R0.1, then X2 Y2 drills again.
TEST(G81, StickyWordsDrillAgainOnTheNextBlock) {
  Machine m;
  m.rapid({0, 0, 5});
  EXPECT_TRUE(ok(m.cycle(810, {.x = 1, .y = 1, .z = -1, .r = 0.1})));
  EXPECT_TRUE(ok(m.cycle(810, {.x = 2, .y = 2})));
  EXPECT_TRUE(same_ops(m.rec.ops, {rapid_to(0, 0, 5), rapid_to(1, 1, 5), rapid_to(1, 1, 0.1),
                                   feed_to(1, 1, -1), rapid_to(1, 1, 5), rapid_to(2, 2, 5),
                                   rapid_to(2, 2, 0.1), feed_to(2, 2, -1), rapid_to(2, 2, 5)}));
}

// LinuxCNC keeps the level of the first cycle block (cycle_il) for G98 until
// another motion runs: a G99 block in between does not change it.
TEST(G81, KeepsTheInitialLevelUntilAnotherMotion) {
  Machine m;
  m.rapid({0, 0, 10});
  EXPECT_TRUE(ok(m.cycle(810, {.x = 1, .z = -1, .r = 2})));
  m.modal.retract_to_r = true;
  EXPECT_TRUE(ok(m.cycle(810, {.x = 2})));
  m.modal.retract_to_r = false;
  EXPECT_TRUE(ok(m.cycle(810, {.x = 3})));
  m.rapid({4, 0, 5});
  EXPECT_TRUE(ok(m.cycle(810, {.x = 5, .z = -1, .r = 2})));
  EXPECT_TRUE(same_ops(m.rec.ops, {rapid_to(0, 0, 10), rapid_to(1, 0, 10), rapid_to(1, 0, 2),
                                   feed_to(1, 0, -1), rapid_to(1, 0, 10),  // G98
                                   rapid_to(2, 0, 10), rapid_to(2, 0, 2), feed_to(2, 0, -1),
                                   rapid_to(2, 0, 2),  // G99
                                   rapid_to(3, 0, 10), rapid_to(3, 0, 2), feed_to(3, 0, -1),
                                   rapid_to(3, 0, 10),  // G98: Z10 again
                                   rapid_to(4, 0, 5), rapid_to(5, 0, 5), rapid_to(5, 0, 2),
                                   feed_to(5, 0, -1), rapid_to(5, 0, 5)}));
}

// NCMS p. 98: under G91 R counts from the initial level and the bottom from
// R; X and Y step from hole to hole.
TEST(G81, IncrementalRepeatsStepFromHoleToHole) {
  Machine m;
  m.modal.incremental = true;
  m.rapid({0, 0, 10});
  EXPECT_TRUE(ok(m.cycle(810, {.x = 5, .y = 1, .z = -4, .r = -8, .l = 3})));
  EXPECT_TRUE(same_ops(
      m.rec.ops, {rapid_to(0, 0, 10), rapid_to(5, 1, 10), rapid_to(5, 1, 2), feed_to(5, 1, -2),
                  rapid_to(5, 1, 10), rapid_to(10, 2, 10), rapid_to(10, 2, 2), feed_to(10, 2, -2),
                  rapid_to(10, 2, 10), rapid_to(15, 3, 10), rapid_to(15, 3, 2), feed_to(15, 3, -2),
                  rapid_to(15, 3, 10)}));
}

// rs274: G20 G17 G90 G99 / G0 X0 Y0 Z0.345 / G91 G81 X0.1 R-0.095 Z-0.065 / X0.1
// R is 0.345 - 0.095 = 0.24999999999999997 in, and the first block ends
// there; the second starts "at R", not above it (0.25), so it makes no
// second move down to R. usina carries LinuxCNC's own numbers over.
TEST(G81, CarriesLinuxCncsOwnNumbersToTheNextBlock) {
  Machine m(kInch);
  m.modal.retract_to_r = true;
  m.rapid(inches(0, 0, 0.345));
  m.modal.incremental = true;
  EXPECT_TRUE(ok(m.cycle(810, inches({.x = 0.1, .z = -0.065, .r = -0.095}))));
  EXPECT_TRUE(ok(m.cycle(810, inches({.x = 0.1}))));
  EXPECT_TRUE(same_ops(m.rec.ops,
                       {rapid_to(0, 0, 8.763), rapid_to(2.54, 0, 8.763), rapid_to(2.54, 0, 6.35),
                        feed_to(2.54, 0, 4.699), rapid_to(2.54, 0, 6.35), rapid_to(5.08, 0, 6.35),
                        feed_to(5.08, 0, 4.699), rapid_to(5.08, 0, 6.35)},
                       2e-3));
}

// interp_cycles.cc: L > 1 in G90 means "do the same thing in the same place".
TEST(G81, AbsoluteRepeatsDrillTheSameHoleAgain) {
  Machine m;
  m.rapid({0, 0, 10});
  EXPECT_TRUE(ok(m.cycle(810, {.x = 1, .y = 1, .z = -1, .r = 2, .l = 2})));
  EXPECT_TRUE(same_ops(m.rec.ops, {rapid_to(0, 0, 10), rapid_to(1, 1, 10), rapid_to(1, 1, 2),
                                   feed_to(1, 1, -1), rapid_to(1, 1, 10), rapid_to(1, 1, 10),
                                   rapid_to(1, 1, 2), feed_to(1, 1, -1), rapid_to(1, 1, 10)}));
}

TEST(G81, ReportsOneHoleFeaturePerHoleAtR) {
  Machine m;
  m.modal.incremental = true;
  m.rapid({0, 0, 10});
  EXPECT_TRUE(ok(m.cycle(810, {.x = 5, .z = -4, .r = -8, .l = 2})));
  ASSERT_EQ(m.rec.holes.size(), 2u);
  EXPECT_EQ(m.rec.holes[0].first, (Vec3{5, 0, 2}));
  EXPECT_EQ(m.rec.holes[1].first, (Vec3{10, 0, 2}));
  EXPECT_DOUBLE_EQ(m.rec.holes[0].second, 4.0);
}

TEST(G81, HoleFeatureIsOnThePlaneNormal) {
  Machine m;
  m.modal.plane = Plane::YZ;
  m.rapid({10, 0, 0});
  EXPECT_TRUE(ok(m.cycle(810, {.x = -4, .y = 1, .z = 2, .r = 3})));
  ASSERT_EQ(m.rec.holes.size(), 1u);
  EXPECT_EQ(m.rec.holes[0].first, (Vec3{3, 1, 2}));
  EXPECT_DOUBLE_EQ(m.rec.holes[0].second, 7.0);
}

// ---------------------------------------------------------------- G82

// rs274: G21 G19 G90 G99 / G0 X10 Y0 Z0 / G82 Y1 Z2 R3 X-4 P0.5 / Y4 Z5
TEST(G82, DwellsAtTheBottomAndKeepsP) {
  Machine m;
  m.modal.plane = Plane::YZ;
  m.modal.retract_to_r = true;
  m.rapid({10, 0, 0});
  EXPECT_TRUE(ok(m.cycle(820, {.x = -4, .y = 1, .z = 2, .r = 3, .p = 0.5})));
  EXPECT_TRUE(ok(m.cycle(820, {.y = 4, .z = 5})));
  EXPECT_TRUE(
      same_ops(m.rec.ops, {rapid_to(10, 0, 0), rapid_to(10, 1, 2), rapid_to(3, 1, 2),
                           feed_to(-4, 1, 2), dwell_for(0.5), rapid_to(3, 1, 2), rapid_to(3, 4, 5),
                           feed_to(-4, 4, 5), dwell_for(0.5), rapid_to(3, 4, 5)}));
}

// ---------------------------------------------------------------- G73

// rs274: G21 G17 G90 G98 / G0 X0 Y0 Z10 / G73 X5 Y6 R2 Z-3.5 Q1.5
TEST(G73, BacksOffByThePeckClearanceBetweenPecks) {
  Machine m;
  m.modal.peck_clearance = 0.254;
  m.rapid({0, 0, 10});
  EXPECT_TRUE(ok(m.cycle(730, {.x = 5, .y = 6, .z = -3.5, .r = 2, .q = 1.5})));
  EXPECT_TRUE(same_ops(
      m.rec.ops,
      {rapid_to(0, 0, 10), rapid_to(5, 6, 10), rapid_to(5, 6, 2), feed_to(5, 6, 0.5),
       rapid_to(5, 6, 0.754), feed_to(5, 6, -1), rapid_to(5, 6, -0.746), feed_to(5, 6, -2.5),
       rapid_to(5, 6, -2.246), feed_to(5, 6, -3.5), rapid_to(5, 6, 10)},
      1e-9));
}

// By hand: R0 Q1 Z-3: pecks to -1 and -2; the last feed goes to the bottom.
TEST(G73, ExactMultipleOfQEndsWithOneFeedToTheBottom) {
  Machine m;
  m.modal.retract_to_r = true;
  m.rapid({0, 0, 0});
  EXPECT_TRUE(ok(m.cycle(730, {.z = -3, .r = 0, .q = 1})));
  EXPECT_TRUE(same_ops(
      m.rec.ops, {rapid_to(0, 0, 0), rapid_to(0, 0, 0), feed_to(0, 0, -1), rapid_to(0, 0, 0),
                  feed_to(0, 0, -2), rapid_to(0, 0, -1), feed_to(0, 0, -3), rapid_to(0, 0, 0)}));
}

// rs274: G20 G17 G90 G99 / G0 X0 Y0 Z1 / G73 X0 Y0 R0.1 Z-0.23 Q0.11.
// In inches 0.1 - 3 x 0.11 stays a hair above -0.23, so LinuxCNC pecks a
// third time before its feed to the bottom; 0.1 x 25.4 / 25.4 is not 0.1,
// so usina must get the inch numbers back exactly to do the same.
TEST(G73, ReproducesLinuxCncsExtraPeckAtAnInchMultiple) {
  Machine m(kInch);
  m.modal.peck_clearance = 0.254;
  m.modal.retract_to_r = true;
  m.rapid(inches(0, 0, 1));
  EXPECT_TRUE(ok(m.cycle(730, inches({.x = 0, .y = 0, .z = -0.23, .r = 0.1, .q = 0.11}))));
  EXPECT_TRUE(same_ops(
      m.rec.ops,
      {rapid_to(0, 0, 25.4), rapid_to(0, 0, 25.4), rapid_to(0, 0, 2.54), feed_to(0, 0, -0.254),
       rapid_to(0, 0, 0), feed_to(0, 0, -3.048), rapid_to(0, 0, -2.794), feed_to(0, 0, -5.842),
       rapid_to(0, 0, -5.588), feed_to(0, 0, -5.842), rapid_to(0, 0, 2.54)},
      2e-3));
}

// ---------------------------------------------------------------- G83

// rs274: G21 G17 G90 G99 / G0 X0 Y0 Z10 / G83 X5 Y6 R2 Z-3.5 Q1.5
TEST(G83, RetractsToRBetweenPecks) {
  Machine m;
  m.modal.peck_clearance = 0.254;
  m.modal.retract_to_r = true;
  m.rapid({0, 0, 10});
  EXPECT_TRUE(ok(m.cycle(830, {.x = 5, .y = 6, .z = -3.5, .r = 2, .q = 1.5})));
  EXPECT_TRUE(same_ops(
      m.rec.ops, {rapid_to(0, 0, 10), rapid_to(5, 6, 10), rapid_to(5, 6, 2), feed_to(5, 6, 0.5),
                  rapid_to(5, 6, 2), rapid_to(5, 6, 0.754), feed_to(5, 6, -1), rapid_to(5, 6, 2),
                  rapid_to(5, 6, -0.746), feed_to(5, 6, -2.5), rapid_to(5, 6, 2),
                  rapid_to(5, 6, -2.246), feed_to(5, 6, -3.5), rapid_to(5, 6, 2)}));
}

// The 2.10 setting: with clearance 0 the drill rapids back to the last depth.
TEST(G83, PeckClearanceIsASetting) {
  Machine m;
  m.modal.peck_clearance = 0.0;
  m.rapid({0, 0, 2});
  EXPECT_TRUE(ok(m.cycle(830, {.z = -2, .r = 2, .q = 1.5})));
  EXPECT_TRUE(same_ops(
      m.rec.ops, {rapid_to(0, 0, 2), rapid_to(0, 0, 2), feed_to(0, 0, 0.5), rapid_to(0, 0, 2),
                  rapid_to(0, 0, 0.5), feed_to(0, 0, -1), rapid_to(0, 0, 2), rapid_to(0, 0, -1),
                  feed_to(0, 0, -2), rapid_to(0, 0, 2)}));
}

// rs274: G20 G17 G90 G98 / G0 X0 Y0 Z1 / G83 X0 Y0 R0.1 Z-0.26 Q0.06.
// LinuxCNC steps 0.1 - 0.06 - ... in inches and makes 5 pecks; the same
// steps in mm would make 6 (the last at -0.26 + 1e-16).
TEST(G83, CountsPecksInTheProgramsUnitAsLinuxCnc) {
  Machine m(kInch);
  m.modal.peck_clearance = 0.254;
  m.rapid(inches(0, 0, 1));
  EXPECT_TRUE(ok(m.cycle(830, inches({.x = 0, .y = 0, .z = -0.26, .r = 0.1, .q = 0.06}))));
  EXPECT_TRUE(same_ops(m.rec.ops,
                       {rapid_to(0, 0, 25.4),  rapid_to(0, 0, 25.4), rapid_to(0, 0, 2.54),
                        feed_to(0, 0, 1.016),  rapid_to(0, 0, 2.54), rapid_to(0, 0, 1.27),
                        feed_to(0, 0, -0.508), rapid_to(0, 0, 2.54), rapid_to(0, 0, -0.254),
                        feed_to(0, 0, -2.032), rapid_to(0, 0, 2.54), rapid_to(0, 0, -1.778),
                        feed_to(0, 0, -3.556), rapid_to(0, 0, 2.54), rapid_to(0, 0, -3.302),
                        feed_to(0, 0, -5.08),  rapid_to(0, 0, 2.54), rapid_to(0, 0, -4.826),
                        feed_to(0, 0, -6.604), rapid_to(0, 0, 25.4)},
                       2e-3));
}

TEST(G83, KeepsQFromTheLastBlock) {
  Machine m;
  m.modal.peck_clearance = 0.0;
  m.rapid({0, 0, 2});
  EXPECT_TRUE(ok(m.cycle(830, {.z = -1, .r = 2, .q = 2})));
  m.rec.ops.clear();
  EXPECT_TRUE(ok(m.cycle(830, {.x = 1})));
  EXPECT_TRUE(same_ops(m.rec.ops, {rapid_to(1, 0, 2), feed_to(1, 0, 0), rapid_to(1, 0, 2),
                                   rapid_to(1, 0, 0), feed_to(1, 0, -1), rapid_to(1, 0, 2)}));
}

// ---------------------------------------------------------------- G74

// rs274: G21 G17 G90 G98 / M4 S300 / G0 X0 Y0 Z10 / G74 X5 Y6 R2 Z-4
TEST(G74, TapsLeftHandReversingTheSpindleAtTheBottom) {
  Machine m;
  m.modal.spindle = SpindleDir::Ccw;
  m.rapid({0, 0, 10});
  EXPECT_TRUE(ok(m.cycle(740, {.x = 5, .y = 6, .z = -4, .r = 2})));
  EXPECT_TRUE(same_ops(
      m.rec.ops, {rapid_to(0, 0, 10), rapid_to(5, 6, 10), rapid_to(5, 6, 2), feed_to(5, 6, -4),
                  kOff, kCw, dwell_for(0), feed_to(5, 6, 10), kOff, kCcw}));
}

// ---------------------------------------------------------------- G84

// conformance linuxcnc__tests__interp__g84__g17__g98__g17-g98-g84.
TEST(G84, MatchesLinuxCncTraceInG17WithG98) {
  Machine m = interp_test_machine(Plane::XY, false, SpindleDir::Cw);
  run_interp_test_program(m, 840, 840);
  EXPECT_TRUE(same_ops(m.rec.ops,
                       {kCw,
                        rapid_to(0, 0, 50.8),
                        rapid_to(25.4, 25.4, 50.8),
                        rapid_to(25.4, 25.4, 25.4),
                        feed_to(25.4, 25.4, -25.4),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(25.4, 25.4, 50.8),
                        kOff,
                        kCw,
                        rapid_to(25.4, 25.4, 76.2),
                        rapid_to(25.4, 50.8, 76.2),
                        feed_to(25.4, 50.8, 12.7),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(25.4, 50.8, 76.2),
                        kOff,
                        kCw,
                        rapid_to(25.4, 50.8, 127),
                        rapid_to(25.4, 76.2, 127),
                        feed_to(25.4, 76.2, 101.6),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(25.4, 76.2, 127),
                        kOff,
                        kCw,
                        rapid_to(254, 0, 50.8),
                        rapid_to(279.4, 25.4, 50.8),
                        rapid_to(279.4, 25.4, 25.4),
                        feed_to(279.4, 25.4, -25.4),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(279.4, 25.4, 50.8),
                        kOff,
                        kCw,
                        rapid_to(304.8, 50.8, 50.8),
                        rapid_to(304.8, 50.8, 25.4),
                        feed_to(304.8, 50.8, -25.4),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(304.8, 50.8, 50.8),
                        kOff,
                        kCw,
                        rapid_to(508, 0, 50.8),
                        rapid_to(508, 0, 76.2),
                        rapid_to(533.4, 25.4, 76.2),
                        feed_to(533.4, 25.4, 12.7),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(533.4, 25.4, 76.2),
                        kOff,
                        kCw,
                        rapid_to(558.8, 50.8, 76.2),
                        feed_to(558.8, 50.8, 12.7),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(558.8, 50.8, 76.2),
                        kOff,
                        kCw,
                        rapid_to(762, 0, 50.8),
                        rapid_to(762, 0, 127),
                        rapid_to(787.4, 25.4, 127),
                        feed_to(787.4, 25.4, 101.6),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(787.4, 25.4, 127),
                        kOff,
                        kCw,
                        rapid_to(812.8, 50.8, 127),
                        feed_to(812.8, 50.8, 101.6),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(812.8, 50.8, 127),
                        kOff,
                        kCw},
                       2e-3));
}

// conformance linuxcnc__tests__interp__g84__g18__g99__g18-g99-g84 (its
// first hole is a G81). LinuxCNC's G84 feeds in G18 go to (bottom, Z, X)
// instead of (X, bottom, Z); the positioning moves are right.
TEST(G84, FeedsOffTheHoleInG18AsLinuxCncDoes) {
  Machine m = interp_test_machine(Plane::ZX, true, SpindleDir::Cw);
  run_interp_test_program(m, 810, 840);
  EXPECT_TRUE(same_ops(m.rec.ops,
                       {kCw,
                        rapid_to(0, 50.8, 0),
                        rapid_to(25.4, 50.8, 25.4),
                        rapid_to(25.4, 25.4, 25.4),
                        feed_to(25.4, -25.4, 25.4),
                        rapid_to(25.4, 25.4, 25.4),
                        rapid_to(25.4, 76.2, 25.4),
                        rapid_to(25.4, 76.2, 50.8),
                        feed_to(12.7, 50.8, 25.4),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(76.2, 50.8, 25.4),
                        kOff,
                        kCw,
                        rapid_to(25.4, 127, 50.8),
                        rapid_to(25.4, 127, 76.2),
                        feed_to(101.6, 76.2, 25.4),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(127, 76.2, 25.4),
                        kOff,
                        kCw,
                        rapid_to(254, 50.8, 0),
                        rapid_to(279.4, 50.8, 25.4),
                        rapid_to(279.4, 25.4, 25.4),
                        feed_to(-25.4, 25.4, 279.4),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(25.4, 25.4, 279.4),
                        kOff,
                        kCw,
                        rapid_to(304.8, 25.4, 50.8),
                        feed_to(-25.4, 50.8, 304.8),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(25.4, 50.8, 304.8),
                        kOff,
                        kCw,
                        rapid_to(508, 50.8, 0),
                        rapid_to(508, 76.2, 0),
                        rapid_to(533.4, 76.2, 25.4),
                        feed_to(12.7, 25.4, 533.4),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(76.2, 25.4, 533.4),
                        kOff,
                        kCw,
                        rapid_to(558.8, 76.2, 50.8),
                        feed_to(12.7, 50.8, 558.8),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(76.2, 50.8, 558.8),
                        kOff,
                        kCw,
                        rapid_to(762, 50.8, 0),
                        rapid_to(762, 127, 0),
                        rapid_to(787.4, 127, 25.4),
                        feed_to(101.6, 25.4, 787.4),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(127, 25.4, 787.4),
                        kOff,
                        kCw,
                        rapid_to(812.8, 127, 50.8),
                        feed_to(101.6, 50.8, 812.8),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(127, 50.8, 812.8),
                        kOff,
                        kCw},
                       2e-3));
}

// conformance linuxcnc__tests__interp__g84__g19__g98__g19-g98-g84: in G19
// the feeds go to (Z, bottom, Y).
TEST(G84, FeedsOffTheHoleInG19AsLinuxCncDoes) {
  Machine m = interp_test_machine(Plane::YZ, false, SpindleDir::Cw);
  run_interp_test_program(m, 840, 840);
  EXPECT_TRUE(same_ops(m.rec.ops,
                       {kCw,
                        rapid_to(50.8, 0, 0),
                        rapid_to(50.8, 25.4, 25.4),
                        rapid_to(25.4, 25.4, 25.4),
                        feed_to(25.4, -25.4, 25.4),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(25.4, 50.8, 25.4),
                        kOff,
                        kCw,
                        rapid_to(76.2, 25.4, 25.4),
                        rapid_to(76.2, 25.4, 50.8),
                        feed_to(50.8, 12.7, 25.4),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(50.8, 76.2, 25.4),
                        kOff,
                        kCw,
                        rapid_to(127, 25.4, 50.8),
                        rapid_to(127, 25.4, 76.2),
                        feed_to(76.2, 101.6, 25.4),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(76.2, 127, 25.4),
                        kOff,
                        kCw,
                        rapid_to(50.8, 254, 0),
                        rapid_to(50.8, 279.4, 25.4),
                        rapid_to(25.4, 279.4, 25.4),
                        feed_to(25.4, -25.4, 279.4),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(25.4, 50.8, 279.4),
                        kOff,
                        kCw,
                        rapid_to(50.8, 304.8, 50.8),
                        rapid_to(25.4, 304.8, 50.8),
                        feed_to(50.8, -25.4, 304.8),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(50.8, 50.8, 304.8),
                        kOff,
                        kCw,
                        rapid_to(50.8, 508, 0),
                        rapid_to(76.2, 508, 0),
                        rapid_to(76.2, 533.4, 25.4),
                        feed_to(25.4, 12.7, 533.4),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(25.4, 76.2, 533.4),
                        kOff,
                        kCw,
                        rapid_to(76.2, 558.8, 50.8),
                        feed_to(50.8, 12.7, 558.8),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(50.8, 76.2, 558.8),
                        kOff,
                        kCw,
                        rapid_to(50.8, 762, 0),
                        rapid_to(127, 762, 0),
                        rapid_to(127, 787.4, 25.4),
                        feed_to(25.4, 101.6, 787.4),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(25.4, 127, 787.4),
                        kOff,
                        kCw,
                        rapid_to(127, 812.8, 50.8),
                        feed_to(50.8, 101.6, 812.8),
                        kOff,
                        kCcw,
                        dwell_for(0),
                        feed_to(50.8, 127, 812.8),
                        kOff,
                        kCw},
                       2e-3));
}

// LinuxCNC's interpreter carries on from over the hole at the clear level,
// not from where the odd retract feed went.
TEST(G84, EndPointIsOverTheHoleAfterTheG18Retract) {
  Machine m;
  m.modal.plane = Plane::ZX;
  m.modal.spindle = SpindleDir::Cw;
  m.rapid({1, 10, 2});
  EXPECT_TRUE(ok(m.cycle(840, {.x = 3, .y = -4, .z = 5, .r = 2})));
  EXPECT_EQ(m.rec.ops.back().kind, Op::Kind::Spindle);
  EXPECT_EQ(m.cycles.end_point(), (Vec3{3, 10, 5}));
}

// LinuxCNC reads G74/G84's dwell from P, else from the last P of any cycle.
TEST(G84, DwellsForTheLastPOfAnyCycle) {
  Machine m;
  m.modal.spindle = SpindleDir::Cw;
  m.rapid({0, 0, 5});
  EXPECT_TRUE(ok(m.cycle(820, {.z = -1, .r = 1, .p = 1.5})));
  m.rapid({0, 0, 5});
  m.rec.ops.clear();
  EXPECT_TRUE(ok(m.cycle(840, {.x = 1, .z = -1, .r = 1})));
  EXPECT_TRUE(same_ops(m.rec.ops, {rapid_to(1, 0, 5), rapid_to(1, 0, 1), feed_to(1, 0, -1), kOff,
                                   kCcw, dwell_for(1.5), feed_to(1, 0, 5), kOff, kCw}));
}

// ---------------------------------------------------------------- G85 - G89

// rs274: G21 G17 G90 G98 / G0 X0 Y0 Z10 / G85 X1 Y2 R2 Z-4
TEST(G85, FeedsOutToRThenRapidsToTheClearLevel) {
  Machine m;
  m.rapid({0, 0, 10});
  EXPECT_TRUE(ok(m.cycle(850, {.x = 1, .y = 2, .z = -4, .r = 2})));
  EXPECT_TRUE(same_ops(m.rec.ops, {rapid_to(0, 0, 10), rapid_to(1, 2, 10), rapid_to(1, 2, 2),
                                   feed_to(1, 2, -4), feed_to(1, 2, 2), rapid_to(1, 2, 10)}));
}

// rs274: G21 G18 G90 G98 / M3 S300 / G0 X0 Y10 Z0 / G86 X1 Z2 R2 Y-4 P1.5
TEST(G86, StopsTheSpindleToRapidOutInG18) {
  Machine m;
  m.modal.plane = Plane::ZX;
  m.modal.spindle = SpindleDir::Cw;
  m.rapid({0, 10, 0});
  EXPECT_TRUE(ok(m.cycle(860, {.x = 1, .y = -4, .z = 2, .r = 2, .p = 1.5})));
  EXPECT_TRUE(
      same_ops(m.rec.ops, {rapid_to(0, 10, 0), rapid_to(1, 10, 2), rapid_to(1, 2, 2),
                           feed_to(1, -4, 2), dwell_for(1.5), kOff, rapid_to(1, 10, 2), kCw}));
}

// rs274: G21 G17 G90 G98 / M3 S300 / G0 X0 Y0 Z10 /
//   G87 X10 Y20 R2 Z-8 I-1.5 J0.5 K-6 / G91 X5 R0 Z-8 K3
// Under G91 the initial level Z10 still holds, so R is 10, the bottom 2 and
// the top of the back bore (K from the bottom) 5.
TEST(G87, BackBoresThroughTheOffsetAbsoluteAndIncremental) {
  Machine m;
  m.modal.spindle = SpindleDir::Cw;
  m.rapid({0, 0, 10});
  EXPECT_TRUE(ok(m.cycle(870, {.x = 10, .y = 20, .z = -8, .r = 2, .i = -1.5, .j = 0.5, .k = -6})));
  m.modal.incremental = true;
  EXPECT_TRUE(ok(m.cycle(870, {.x = 5, .z = -8, .r = 0, .k = 3})));
  EXPECT_TRUE(same_ops(m.rec.ops, {rapid_to(0, 0, 10),
                                   rapid_to(10, 20, 10),
                                   rapid_to(10, 20, 2),
                                   rapid_to(8.5, 20.5, 2),
                                   kOff,
                                   rapid_to(8.5, 20.5, -8),
                                   rapid_to(10, 20, -8),
                                   kCw,
                                   feed_to(10, 20, -6),
                                   feed_to(10, 20, -8),
                                   kOff,
                                   rapid_to(8.5, 20.5, -8),
                                   rapid_to(8.5, 20.5, 10),
                                   rapid_to(10, 20, 10),
                                   kCw,
                                   rapid_to(15, 20, 10),
                                   rapid_to(13.5, 20.5, 10),
                                   kOff,
                                   rapid_to(13.5, 20.5, 2),
                                   rapid_to(15, 20, 2),
                                   kCw,
                                   feed_to(15, 20, 5),
                                   feed_to(15, 20, 2),
                                   kOff,
                                   rapid_to(13.5, 20.5, 2),
                                   rapid_to(13.5, 20.5, 10),
                                   rapid_to(15, 20, 10),
                                   kCw}));
}

// rs274: G21 G18 G90 G99 / M4 S300 / G0 X0 Y10 Z0 / G87 X10 Z20 R2 Y-8 I-1.5 J-6 K0.5
// In G18 the offset is (K, I) along (Z, X) and J is the top of the bore.
TEST(G87, UsesKAndIAsTheOffsetInG18) {
  Machine m;
  m.modal.plane = Plane::ZX;
  m.modal.retract_to_r = true;
  m.modal.spindle = SpindleDir::Ccw;
  m.rapid({0, 10, 0});
  EXPECT_TRUE(ok(m.cycle(870, {.x = 10, .y = -8, .z = 20, .r = 2, .i = -1.5, .j = -6, .k = 0.5})));
  EXPECT_TRUE(same_ops(
      m.rec.ops, {rapid_to(0, 10, 0), rapid_to(10, 10, 20), rapid_to(10, 2, 20),
                  rapid_to(8.5, 2, 20.5), kOff, rapid_to(8.5, -8, 20.5), rapid_to(10, -8, 20), kCcw,
                  feed_to(10, -6, 20), feed_to(10, -8, 20), kOff, rapid_to(8.5, -8, 20.5),
                  rapid_to(8.5, 2, 20.5), rapid_to(10, 2, 20), kCcw}));
}

// rs274: G21 G17 G90 G98 / M4 S300 / G0 X0 Y0 Z10 / G88 X1 Y2 R2 Z-4 P2 L2
// No retract: the operator's; the next repeat leaves from the bottom.
TEST(G88, StopsAtTheBottomForAManualRetract) {
  Machine m;
  m.modal.spindle = SpindleDir::Ccw;
  m.rapid({0, 0, 10});
  EXPECT_TRUE(ok(m.cycle(880, {.x = 1, .y = 2, .z = -4, .r = 2, .p = 2, .l = 2})));
  EXPECT_TRUE(
      same_ops(m.rec.ops, {rapid_to(0, 0, 10), rapid_to(1, 2, 10), rapid_to(1, 2, 2),
                           feed_to(1, 2, -4), dwell_for(2), kOff, kCcw, rapid_to(1, 2, 10),
                           rapid_to(1, 2, 2), feed_to(1, 2, -4), dwell_for(2), kOff, kCcw}));
  EXPECT_EQ(m.cycles.end_point(), (Vec3{1, 2, 10}));
}

// rs274: G21 G17 G90 G98 / G0 X0 Y0 Z10 / G89 X1 Y2 R2 Z-4 P0.25
TEST(G89, DwellsThenFeedsOutToTheClearLevel) {
  Machine m;
  m.rapid({0, 0, 10});
  EXPECT_TRUE(ok(m.cycle(890, {.x = 1, .y = 2, .z = -4, .r = 2, .p = 0.25})));
  EXPECT_TRUE(same_ops(m.rec.ops, {rapid_to(0, 0, 10), rapid_to(1, 2, 10), rapid_to(1, 2, 2),
                                   feed_to(1, 2, -4), dwell_for(0.25), feed_to(1, 2, 10)}));
}

// ---------------------------------------------------------------- G76

// rs274: G21 G18 G90 / M3 S300 / G0 X10 Z5 /
//   G76 P1.5 Z-20 I-1 J0.4 K1 R1.5 Q29.5 H1 E2 L3
// External thread: passes at depths 1.4, 1.4 + 0.4 * 2^(1/1.5), ..., the
// full depth twice (H1), each entering and leaving along a 2 mm taper.
TEST(G76, CutsAnExternalThreadWithTapersAndASpringPass) {
  Machine m;
  m.modal.plane = Plane::ZX;
  m.modal.spindle = SpindleDir::Cw;
  m.rapid({10, 0, 5});
  EXPECT_TRUE(ok(m.cycle(760, {.z = -20,
                               .r = 1.5,
                               .q = 29.5,
                               .i = -1,
                               .j = 0.4,
                               .k = 1,
                               .p = 1.5,
                               .l = 3,
                               .h = 1,
                               .e = 2})));
  EXPECT_TRUE(same_ops(m.rec.ops,
                       {rapid_to(10, 0, 5),
                        rapid_to(10.6, 0, 4.7737),
                        feed_to(9.6, 0, 4.7737),
                        feed_to(8.6, 0, 2.7737),
                        feed_to(8.6, 0, -17.6605),
                        feed_to(9.6, 0, -19.6605),
                        rapid_to(10.6, 0, -19.6605),
                        rapid_to(10.365, 0, 4.6408),
                        feed_to(9.365, 0, 4.6408),
                        feed_to(8.365, 0, 2.6408),
                        feed_to(8.365, 0, -17.7935),
                        feed_to(9.365, 0, -19.7935),
                        rapid_to(10.365, 0, -19.7935),
                        rapid_to(10.168, 0, 4.5293),
                        feed_to(9.168, 0, 4.5293),
                        feed_to(8.168, 0, 2.5293),
                        feed_to(8.168, 0, -17.905),
                        feed_to(9.168, 0, -19.905),
                        rapid_to(10.168, 0, -19.905),
                        rapid_to(10, 0, 4.4342),
                        feed_to(9, 0, 4.4342),
                        feed_to(8, 0, 2.4342),
                        feed_to(8, 0, -18),
                        feed_to(9, 0, -20),
                        rapid_to(10, 0, -20),
                        rapid_to(10, 0, 4.4342),
                        feed_to(9, 0, 4.4342),
                        feed_to(8, 0, 2.4342),
                        feed_to(8, 0, -18),
                        feed_to(9, 0, -20),
                        rapid_to(10, 0, -20),
                        rapid_to(10, 0, -20)},
                       2e-3));
}

// rs274: G21 G18 G7 G90 / M4 S300 / G0 X16 Z2 / G76 P1 Z12 I1 J0.4 K1.2
// Internal (I > 0) towards +Z in diameter mode: X16 is radius 8 and I, J, K
// are halved.
TEST(G76, CutsAnInternalThreadInDiameterMode) {
  Machine m;
  m.modal.plane = Plane::ZX;
  m.modal.spindle = SpindleDir::Ccw;
  m.modal.diameter_mode = true;
  m.rapid({8, 0, 2});
  EXPECT_TRUE(ok(m.cycle(760, {.z = 12, .i = 1, .j = 0.4, .k = 1.2, .p = 1})));
  EXPECT_TRUE(same_ops(
      m.rec.ops, {rapid_to(8, 0, 2), rapid_to(7.6, 0, 2), rapid_to(8.7, 0, 2), feed_to(8.7, 0, 12),
                  rapid_to(7.6, 0, 12), rapid_to(7.8, 0, 2), rapid_to(8.9, 0, 2),
                  feed_to(8.9, 0, 12), rapid_to(7.8, 0, 12), rapid_to(8, 0, 2), rapid_to(9.1, 0, 2),
                  feed_to(9.1, 0, 12), rapid_to(8, 0, 12), rapid_to(8, 0, 12)}));
}

// rs274: G21 G18 G90 / M3 S300 / G0 X10 Z-20 / G76 P1.5 Z0 I-1 J0.5 K1 R2 Q30 E1.5 L1
// Towards +Z the compound angle and the taper turn round; entry taper only.
TEST(G76, CutsTowardsPlusZWithAnEntryTaper) {
  Machine m;
  m.modal.plane = Plane::ZX;
  m.modal.spindle = SpindleDir::Cw;
  m.rapid({10, 0, -20});
  EXPECT_TRUE(ok(m.cycle(
      760, {.z = 0, .r = 2, .q = 30, .i = -1, .j = 0.5, .k = 1, .p = 1.5, .l = 1, .e = 1.5})));
  EXPECT_TRUE(same_ops(m.rec.ops,
                       {rapid_to(10, 0, -20),
                        rapid_to(10.5, 0, -19.7113),
                        feed_to(9.5, 0, -19.7113),
                        feed_to(8.5, 0, -18.2113),
                        feed_to(8.5, 0, -0.2887),
                        rapid_to(10.5, 0, -0.2887),
                        rapid_to(10.2929, 0, -19.5918),
                        feed_to(9.2929, 0, -19.5918),
                        feed_to(8.2929, 0, -18.0918),
                        feed_to(8.2929, 0, -0.1691),
                        rapid_to(10.2929, 0, -0.1691),
                        rapid_to(10.134, 0, -19.5),
                        feed_to(9.134, 0, -19.5),
                        feed_to(8.134, 0, -18),
                        feed_to(8.134, 0, -0.0774),
                        rapid_to(10.134, 0, -0.0774),
                        rapid_to(10, 0, -19.4226),
                        feed_to(9, 0, -19.4226),
                        feed_to(8, 0, -17.9226),
                        feed_to(8, 0, 0),
                        rapid_to(10, 0, 0),
                        rapid_to(10, 0, 0)},
                       2e-3));
}

// find_ends: under G91 X and Z of G76 are increments; the cycle ends there.
TEST(G76, IncrementalEndPoint) {
  Machine m;
  m.modal.spindle = SpindleDir::Cw;
  m.modal.incremental = true;
  m.rapid({10, 0, 5});
  EXPECT_TRUE(ok(m.cycle(760, {.x = 1, .z = -10, .i = -0.5, .j = 0.2, .k = 0.4, .p = 1})));
  EXPECT_TRUE(same_ops({m.rec.ops.back()}, {rapid_to(11, 0, -5)}));
  EXPECT_EQ(m.cycles.end_point(), (Vec3{11, 0, -5}));
}

// convert_motion: G76 is not a canned cycle, so a cycle after it takes a new
// initial level.
TEST(G76, EndsTheCycleSequence) {
  Machine m;
  m.modal.spindle = SpindleDir::Cw;
  m.rapid({0, 0, 10});
  EXPECT_TRUE(ok(m.cycle(810, {.z = -1, .r = 2})));
  EXPECT_TRUE(ok(m.cycle(760, {.z = 4, .i = -0.5, .j = 0.2, .k = 0.4, .p = 1})));
  m.rec.ops.clear();
  EXPECT_TRUE(ok(m.cycle(810, {.z = -1, .r = 2})));
  EXPECT_TRUE(same_ops(
      m.rec.ops, {rapid_to(0, 0, 4), rapid_to(0, 0, 2), feed_to(0, 0, -1), rapid_to(0, 0, 4)}));
}

// ---------------------------------------------------------------- errors

TEST(CannedCycleErrors, RMissingWhenTheCycleStarts) {
  Machine m;
  EXPECT_TRUE(fails(m.cycle(810, {.x = 1, .z = -1}), Code::MissingWord, "G81 needs R"));
  EXPECT_TRUE(m.rec.ops.empty());
}

// LinuxCNC: R and the bottom are kept only for the same cycle.
TEST(CannedCycleErrors, AnotherCycleNeedsRAgain) {
  Machine m;
  EXPECT_TRUE(ok(m.cycle(810, {.z = -1, .r = 1})));
  EXPECT_TRUE(fails(m.cycle(820, {.x = 2, .p = 1}), Code::MissingWord, "G82 needs R"));
  EXPECT_TRUE(
      fails(m.cycle(820, {.x = 2, .r = 1, .p = 1}), Code::MissingWord, "needs Z, the bottom"));
}

TEST(CannedCycleErrors, BottomMissingNamesThePlanesNormal) {
  Machine m;
  m.modal.plane = Plane::ZX;
  EXPECT_TRUE(fails(m.cycle(810, {.x = 1, .z = -1, .r = 1}), Code::MissingWord,
                    "G81 in the ZX plane (G18) needs Y"));
  m.modal.plane = Plane::YZ;
  EXPECT_TRUE(fails(m.cycle(810, {.y = 1, .z = -1, .r = 1}), Code::MissingWord, "needs X"));
}

TEST(CannedCycleErrors, RBelowTheBottom) {
  Machine m;
  EXPECT_TRUE(fails(m.cycle(810, {.z = 3, .r = 2}), Code::CycleBadValue,
                    "R (Z2 mm) is below the bottom of the hole (Z3 mm)"));
}

TEST(CannedCycleErrors, IncrementalBottomAboveR) {
  Machine m;
  m.modal.incremental = true;
  m.rec.pos = {0, 0, 10};
  EXPECT_TRUE(fails(m.cycle(810, {.z = 1, .r = -2}), Code::CycleBadValue,
                    "R (Z8 mm) is below the bottom of the hole (Z9 mm)"));
}

TEST(CannedCycleErrors, LMustBeAPositiveWholeNumber) {
  Machine m;
  EXPECT_TRUE(fails(m.cycle(810, {.z = -1, .r = 1, .l = 0}), Code::BadWordValue, "G81 L0"));
  EXPECT_TRUE(fails(m.cycle(810, {.z = -1, .r = 1, .l = -2}), Code::BadWordValue, "L-2"));
  EXPECT_TRUE(fails(m.cycle(810, {.z = -1, .r = 1, .l = 1.5}), Code::BadWordValue, "L1.5"));
  EXPECT_TRUE(fails(m.cycle(810, {.z = -1, .r = 1, .l = 1e7}), Code::TooManyIterations, "L1e+07"));
  EXPECT_TRUE(ok(m.cycle(810, {.z = -1, .r = 1, .l = 1.99999})));  // within 0.0001, as LinuxCNC
}

// LinuxCNC reads L within 0.0001 of a whole number: L0.00001 is L0.
TEST(CannedCycleErrors, LThatReadsAsZero) {
  Machine m;
  EXPECT_TRUE(fails(m.cycle(810, {.z = -1, .r = 1, .l = 0.00001}), Code::BadWordValue, "G81 L0"));
}

TEST(CannedCycleErrors, MessagesShowWordsInTheProgramsUnit) {
  Machine m(kInch);
  EXPECT_TRUE(fails(m.cycle(810, inches({.z = 3, .r = 2})), Code::CycleBadValue,
                    "R (Z2 in) is below the bottom of the hole (Z3 in)"));
  EXPECT_TRUE(fails(m.cycle(830, inches({.z = -1, .r = 1, .q = -0.01})), Code::CycleBadValue,
                    "G83 Q-0.01: the peck depth"));
}

TEST(CannedCycleErrors, WordsMustBeFinite) {
  Machine m;
  EXPECT_TRUE(fails(m.cycle(810, {.z = -1, .r = std::nan("")}), Code::BadWordValue,
                    "R is not a finite number"));
}

TEST(CannedCycleErrors, QMissingWhenG83OrG73Starts) {
  Machine m;
  EXPECT_TRUE(fails(m.cycle(830, {.z = -1, .r = 1}), Code::MissingWord, "G83 needs Q"));
  EXPECT_TRUE(fails(m.cycle(730, {.z = -1, .r = 1}), Code::MissingWord, "G73 needs Q"));
}

TEST(CannedCycleErrors, QMustBePositive) {
  Machine m;
  EXPECT_TRUE(fails(m.cycle(830, {.z = -1, .r = 1, .q = 0}), Code::CycleBadValue, "G83 Q0"));
  EXPECT_TRUE(fails(m.cycle(730, {.z = -1, .r = 1, .q = -0.5}), Code::CycleBadValue, "Q-0.5"));
}

TEST(CannedCycleErrors, TinyQIsTooManyPecks) {
  Machine m;
  EXPECT_TRUE(fails(m.cycle(830, {.z = -100, .r = 1, .q = 1e-6}), Code::TooManyIterations, "G83"));
  EXPECT_TRUE(m.rec.ops.empty());
}

TEST(CannedCycleErrors, PMissingWhenADwellingCycleStarts) {
  for (const int g : {820, 860, 880, 890}) {
    Machine m;
    m.modal.spindle = SpindleDir::Cw;
    EXPECT_TRUE(fails(m.cycle(g, {.z = -1, .r = 1}), Code::MissingWord,
                      fmt::format("G{} needs P", g / 10)));
  }
}

// LinuxCNC would dwell a negative time; usina refuses it.
TEST(CannedCycleErrors, NegativeDwell) {
  Machine m;
  EXPECT_TRUE(fails(m.cycle(820, {.z = -1, .r = 1, .p = -2}), Code::BadWordValue, "G82 P-2"));
}

TEST(CannedCycleErrors, G87NeedsIJK) {
  Machine m;
  m.modal.spindle = SpindleDir::Cw;
  EXPECT_TRUE(
      fails(m.cycle(870, {.z = -1, .r = 1, .i = 1, .j = 1}), Code::MissingWord, "K is missing"));
}

TEST(CannedCycleErrors, TappingNeedsTheSpindleTheRightWay) {
  Machine m;
  EXPECT_TRUE(fails(m.cycle(840, {.z = -1, .r = 1}), Code::NotAllowedInMode, "it is stopped"));
  m.modal.spindle = SpindleDir::Ccw;
  EXPECT_TRUE(
      fails(m.cycle(840, {.z = -1, .r = 1}), Code::NotAllowedInMode, "turning counter-clockwise"));
  m.modal.spindle = SpindleDir::Cw;
  EXPECT_TRUE(fails(m.cycle(740, {.z = -1, .r = 1}), Code::NotAllowedInMode, "turning clockwise"));
  EXPECT_TRUE(m.rec.ops.empty());
}

TEST(CannedCycleErrors, BoringCyclesNeedTheSpindleTurning) {
  Machine m;
  EXPECT_TRUE(fails(m.cycle(860, {.z = -1, .r = 1, .p = 1}), Code::NotAllowedInMode, "G86 needs"));
  EXPECT_TRUE(fails(m.cycle(870, {.z = -1, .r = 1, .i = 1, .j = 1, .k = 0}), Code::NotAllowedInMode,
                    "G87 needs"));
  EXPECT_TRUE(fails(m.cycle(880, {.z = -1, .r = 1, .p = 1}), Code::NotAllowedInMode, "G88 needs"));
}

TEST(CannedCycleErrors, PolarOnlyInG17) {
  Machine m;
  m.modal.plane = Plane::ZX;
  EXPECT_TRUE(fails(m.cycle(810, {.y = -1, .r = 1, .polar_angle = 90}), Code::NotAllowedInMode,
                    "only in the XY plane"));
}

// interp_cycles.cc: "Incremental motion with polar coordinates is
// indeterminate when at the origin". LinuxCNC has made the rise to R by
// then; usina checks before the first move.
TEST(CannedCycleErrors, IncrementalPolarFromTheOrigin) {
  Machine m;
  m.modal.incremental = true;
  EXPECT_TRUE(fails(m.cycle(810, {.z = -3, .r = 2, .polar_angle = 90}), Code::CycleBadValue,
                    "no direction"));
  EXPECT_TRUE(m.rec.ops.empty());
}

TEST(CannedCycleErrors, NotACycle) {
  Machine m;
  EXPECT_TRUE(fails(m.cycle(10, {.z = -1, .r = 1}), Code::Unsupported, "G1 is not"));
}

// A failed block changes nothing: the next block still uses the old words.
TEST(CannedCycleErrors, FailedBlockKeepsTheStickyWords) {
  Machine m;
  m.rapid({0, 0, 5});
  EXPECT_TRUE(ok(m.cycle(810, {.z = -1, .r = 1})));
  EXPECT_TRUE(fails(m.cycle(810, {.x = 9, .z = 7, .r = 8, .l = 0}), Code::BadWordValue, "L0"));
  EXPECT_TRUE(fails(m.cycle(810, {.x = 9, .z = 7, .r = 6}), Code::CycleBadValue, "below"));
  m.rec.ops.clear();
  EXPECT_TRUE(ok(m.cycle(810, {.x = 2})));
  EXPECT_TRUE(same_ops(
      m.rec.ops, {rapid_to(2, 0, 5), rapid_to(2, 0, 1), feed_to(2, 0, -1), rapid_to(2, 0, 5)}));
}

TEST(G76Errors, WordsLinuxCncRequires) {
  Machine m;
  m.modal.spindle = SpindleDir::Cw;
  EXPECT_TRUE(
      fails(m.cycle(760, {.z = -5, .i = -1, .j = 0.2, .k = 1}), Code::MissingWord, "needs P"));
  EXPECT_TRUE(
      fails(m.cycle(760, {.z = -5, .i = -1, .j = 0.2, .p = 1}), Code::MissingWord, "K is missing"));
}

TEST(G76Errors, DepthsLinuxCncRefuses) {
  Machine m;
  m.modal.spindle = SpindleDir::Cw;
  EXPECT_TRUE(fails(m.cycle(760, {.z = -5, .i = 0, .j = 0.2, .k = 1, .p = 1}), Code::CycleBadValue,
                    "G76 I0"));
  EXPECT_TRUE(fails(m.cycle(760, {.z = -5, .i = -1, .j = 0, .k = 1, .p = 1}), Code::CycleBadValue,
                    "G76 J0"));
  EXPECT_TRUE(fails(m.cycle(760, {.z = -5, .i = -1, .j = 0.5, .k = 0.5, .p = 1}),
                    Code::CycleBadValue, "K0.5: the thread depth must be greater than J0.5"));
}

TEST(G76Errors, SpindleStopped) {
  Machine m;
  EXPECT_TRUE(fails(m.cycle(760, {.z = -5, .i = -1, .j = 0.2, .k = 1, .p = 1}),
                    Code::NotAllowedInMode, "G76 needs the spindle turning"));
}

TEST(G76Errors, HAndLAreWholeNumbers) {
  Machine m;
  m.modal.spindle = SpindleDir::Cw;
  EXPECT_TRUE(fails(m.cycle(760, {.z = -5, .i = -1, .j = 0.2, .k = 1, .p = 1, .h = -1}),
                    Code::BadWordValue, "H-1"));
  EXPECT_TRUE(fails(m.cycle(760, {.z = -5, .i = -1, .j = 0.2, .k = 1, .p = 1, .l = 1.5}),
                    Code::BadWordValue, "L1.5"));
}

// A huge degression R makes the depth grow so slowly that the passes never end.
TEST(G76Errors, TooManyPasses) {
  Machine m;
  m.modal.spindle = SpindleDir::Cw;
  EXPECT_TRUE(fails(m.cycle(760, {.z = -5, .r = 100, .i = -1, .j = 0.1, .k = 1, .p = 1}),
                    Code::TooManyIterations, "passes"));
  EXPECT_TRUE(m.rec.ops.empty());
}

}  // namespace
}  // namespace usina::gcode
