#include "gcode/interp/cutter_comp.hpp"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/arc.hpp"
#include "core/units.hpp"

namespace usina::gcode {
namespace {

using core::Code;
using core::Plane;

constexpr double kInch = core::kMmPerInch;
// Reference traces print four decimals of the program's unit
// (spec/trace.md, "Comparing two traces").
constexpr double kTraceTolerance = 0.002;

enum class Kind { Traverse, Feed, Arc, Dwell };

struct Op {
  Kind kind = Kind::Feed;
  Vec3 to;
  Vec3 center;
  int turn = 0;
  double f = 0.0;  // feed rate in effect; a dwell's seconds
  std::uint32_t line = 0;
};

// Records what it is told; `at` is the interpreter's current point.
class Recorder : public MotionTarget {
 public:
  void traverse(const Vec3& to) override {
    ops.push_back({Kind::Traverse, to, {}, 0, rate, line_});
  }

  void feed(const Vec3& to) override { ops.push_back({Kind::Feed, to, {}, 0, rate, line_}); }

  void arc(const Vec3& to, const Vec3& center, int turn) override {
    ops.push_back({Kind::Arc, to, center, turn, rate, line_});
  }

  void dwell(double seconds) override { ops.push_back({Kind::Dwell, {}, {}, 0, seconds, line_}); }

  void spindle(canon::SpindleDir /*dir*/) override {}

  void hole(const Vec3& /*top*/, double /*depth*/) override {}

  Vec3 position() const override { return at; }

  void set_source(const core::SourceLoc& loc) override { line_ = loc.line; }

  std::vector<Op> ops;
  Vec3 at;
  double rate = 0.0;

 private:
  std::uint32_t line_ = 0;
};

// A step's error, or nullopt when it succeeded (the harness reads errors).
std::optional<InterpError> failure_of(const InterpResult& r) {
  if (r) return std::nullopt;
  return r.error();
}

// Drives CutterComp as cutter_comp.hpp tells the interpreter to: one block a
// line, programmed ends in, the current point kept as the programmed end of
// the last block. Words: G0-G3 (modal), G4 P, G17, G18, G40, G41/G42 (radius
// from `tool_diameter`), G41.1/G42.1 D, X Y Z, I J K (incremental), R, F (per
// minute), M0, M2. Other words are ignored. `unit`: mm per program unit.
class Blocks {
 public:
  explicit Blocks(double unit = 1.0) : unit_(unit) {}

  // The first error; its block's line in `error_line`.
  std::optional<InterpError> run(std::string_view text) {
    while (!text.empty()) {
      const std::size_t eol = std::min(text.find('\n'), text.size());
      ++line_;
      if (auto e = block(text.substr(0, eol))) {
        error_line = line_;
        return e;
      }
      text.remove_prefix(std::min(eol + 1, text.size()));
    }
    return std::nullopt;
  }

  Recorder out;
  CutterComp comp;
  double tool_diameter = 0.0;  // program units
  int orientation = 0;
  std::uint32_t error_line = 0;

 private:
  using Words = std::vector<std::pair<char, double>>;

  static Words words(std::string_view text) {
    std::string s;
    bool comment = false;
    for (const char c : text) {
      if (c == '(' || c == ')') comment = c == '(';
      if (!comment && c != ')' && std::isspace(static_cast<unsigned char>(c)) == 0) {
        s += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      }
    }
    Words w;
    for (std::size_t i = 0; i < s.size();) {
      const char letter = s[i++];
      const std::size_t n = s.find_first_not_of("+-.0123456789", i);
      w.emplace_back(letter, std::stod(s.substr(i, n - i)));
      i = std::min(n, s.size());
    }
    return w;
  }

  static std::optional<double> get(const Words& w, char letter) {
    for (const auto& [l, v] : w) {
      if (l == letter) return v;
    }
    return std::nullopt;
  }

  std::optional<InterpError> block(std::string_view text) {
    const Words w = words(text);
    core::SourceLoc loc;
    loc.line = line_;
    if (auto f = get(w, 'F')) {
      const double rate = *f * unit_;
      comp.defer(
          loc, [rate](MotionTarget& t) { static_cast<Recorder&>(t).rate = rate; }, out);
    }
    for (const auto& [letter, value] : w) {
      if (letter != 'G') continue;
      if (auto e = g_code(static_cast<int>(std::lround(value * 10)), w, loc)) return e;
    }
    if (auto e = motion(w, loc)) return e;
    const std::optional<double> m = get(w, 'M');
    if (m && (*m == 0 || *m == 1 || *m == 2)) {
      if (auto e = failure_of(comp.flush(out))) return e;
      if (*m == 2) comp.reset();
    }
    return std::nullopt;
  }

  std::optional<InterpError> g_code(int g, const Words& w, const core::SourceLoc& loc) {
    if (g == 0 || g == 10 || g == 20 || g == 30) motion_ = g / 10;
    if (g == 40) {
      const double p = get(w, 'P').value_or(0.0);
      comp.defer(
          loc, [p](MotionTarget& t) { t.dwell(p); }, out);
    }
    if (g == 170) plane_ = Plane::XY;
    if (g == 180) plane_ = Plane::ZX;
    if (g == 400) return failure_of(comp.stop(out));
    if (g == 410 || g == 420 || g == 411 || g == 421) {
      const CompSide side = g / 10 == 41 ? CompSide::Left : CompSide::Right;
      const double d = g % 10 == 1 ? get(w, 'D').value_or(0.0) : tool_diameter;
      return failure_of(comp.start(side, d * unit_ / 2, plane_, g % 10 == 1 ? 0 : orientation));
    }
    return std::nullopt;
  }

  std::optional<InterpError> motion(const Words& w, const core::SourceLoc& loc) {
    const Vec3 from = out.at;
    Vec3 to = from;
    Vec3 offset;
    bool moves = false;
    for (const auto& [letter, value] : w) {
      if (letter >= 'X' && letter <= 'Z') to[letter - 'X'] = value * unit_, moves = true;
      if (letter >= 'I' && letter <= 'K') offset[letter - 'I'] = value * unit_, moves = true;
      if (letter == 'R') moves = true;
    }
    if (!moves || get(w, 'G') == 4.0) return std::nullopt;
    std::optional<InterpError> e;
    if (motion_ <= 1) {
      e = failure_of(comp.straight(to, motion_ == 0, loc, out));
    } else {
      Vec3 center = from + offset;
      if (auto r = get(w, 'R')) {
        const auto c = core::arc_center_from_radius(
            core::in_plane(from, plane_), core::in_plane(to, plane_), *r * unit_, motion_ == 3);
        center = core::from_plane(*c, from[core::axes_of(plane_).axial], plane_);
      }
      e = failure_of(comp.arc(to, center, motion_ == 3 ? 1 : -1, loc, out));
    }
    if (!e) out.at = to;
    return e;
  }

  double unit_;
  int motion_ = 1;
  Plane plane_ = Plane::XY;
  std::uint32_t line_ = 0;
};

struct Want {
  // `f`: the feed rate in effect (a dwell's seconds); < 0: not checked.
  Want(Kind k, Vec3 t, Vec3 c = {}, int tu = 0, double feed = -1.0)
      : kind(k), to(t), center(c), turn(tu), f(feed) {}

  Kind kind;
  Vec3 to;
  Vec3 center;
  int turn;
  double f;
};

void expect_near(const Vec3& got, const Vec3& want, double tol) {
  EXPECT_NEAR(got.x, want.x, tol);
  EXPECT_NEAR(got.y, want.y, tol);
  EXPECT_NEAR(got.z, want.z, tol);
}

void expect_op(const Op& got, const Want& want, double tol) {
  EXPECT_EQ(got.kind, want.kind);
  expect_near(got.to, want.to, tol);
  if (want.kind == Kind::Arc) {
    expect_near(got.center, want.center, tol);
    EXPECT_EQ(got.turn, want.turn);
  }
  if (want.f >= 0.0) {
    EXPECT_NEAR(got.f, want.f, 1e-6);
  }
}

void expect_ops(const std::vector<Op>& got, const std::vector<Want>& want, double tol = 1e-9) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    SCOPED_TRACE("op " + std::to_string(i + 1));
    expect_op(got[i], want[i], tol);
  }
}

// --- Hand-worked cases: mm, tool radius 1 (G41.1/G42.1 D2). ---

TEST(CutterComp, EntryMoveEndsARadiusFromItsEndPerpendicularToIt) {
  Blocks left;
  ASSERT_FALSE(left.run("G0 X0 Y0\nG41.1 D2\nG1 X10 Y0\nG40"));
  expect_ops(left.out.ops, {{Kind::Traverse, {0, 0, 0}}, {Kind::Feed, {10, 1, 0}}});
  Blocks right;
  ASSERT_FALSE(right.run("G0 X0 Y0\nG42.1 D2\nG1 X10 Y10\nG40"));
  expect_ops(right.out.ops, {{Kind::Traverse, {0, 0, 0}},
                             {Kind::Feed, {10 + std::sqrt(0.5), 10 - std::sqrt(0.5), 0}}});
}

TEST(CutterComp, MoveIsHeldUntilTheNextMoveIsKnown) {
  Blocks b;
  ASSERT_FALSE(b.run("G0 X0 Y0\nG41.1 D2\nG1 X10"));
  EXPECT_EQ(b.out.ops.size(), 1U);
  EXPECT_TRUE(b.comp.holding());
  ASSERT_FALSE(b.run("X20"));
  EXPECT_EQ(b.out.ops.size(), 2U);
}

TEST(CutterComp, TangentMovesGetNoCorner) {
  Blocks b;
  ASSERT_FALSE(b.run("G0 X0 Y0\nG41.1 D2\nG1 X10\nX20\nG40"));
  expect_ops(b.out.ops,
             {{Kind::Traverse, {0, 0, 0}}, {Kind::Feed, {10, 1, 0}}, {Kind::Feed, {20, 1, 0}}});
}

TEST(CutterComp, ConvexCornerGetsArcOfToolRadius) {
  Blocks b;
  ASSERT_FALSE(b.run("G0 X-5 Y0\nG42.1 D2\nG1 X0\nX10\nY10\nG40"));
  expect_ops(b.out.ops, {{Kind::Traverse, {-5, 0, 0}},
                         {Kind::Feed, {0, -1, 0}},
                         {Kind::Feed, {10, -1, 0}},
                         {Kind::Arc, {11, 0, 0}, {10, 0, 0}, 1},
                         {Kind::Feed, {11, 10, 0}}});
  // The corner arc belongs to the block that turns the corner.
  EXPECT_EQ(b.out.ops[2].line, 4U);
  EXPECT_EQ(b.out.ops[3].line, 5U);
  EXPECT_EQ(b.out.ops[4].line, 5U);
}

TEST(CutterComp, ConcaveCornerIsIntersected) {
  Blocks b;
  ASSERT_FALSE(b.run("G0 X-5 Y0\nG41.1 D2\nG1 X0\nX10\nY10\nG40"));
  expect_ops(b.out.ops, {{Kind::Traverse, {-5, 0, 0}},
                         {Kind::Feed, {0, 1, 0}},
                         {Kind::Feed, {9, 1, 0}},
                         {Kind::Feed, {9, 10, 0}}});
}

TEST(CutterComp, SquareWithG42OutsideGetsAnArcAtEveryCorner) {
  Blocks b;
  ASSERT_FALSE(b.run("G0 X-5 Y0\nG42.1 D2\nG1 X0\nX10\nY10\nX0\nY0\nG40\nG1 X-5 Y-5"));
  expect_ops(b.out.ops, {{Kind::Traverse, {-5, 0, 0}},
                         {Kind::Feed, {0, -1, 0}},
                         {Kind::Feed, {10, -1, 0}},
                         {Kind::Arc, {11, 0, 0}, {10, 0, 0}, 1},
                         {Kind::Feed, {11, 10, 0}},
                         {Kind::Arc, {10, 11, 0}, {10, 10, 0}, 1},
                         {Kind::Feed, {0, 11, 0}},
                         {Kind::Arc, {-1, 10, 0}, {0, 10, 0}, 1},
                         {Kind::Feed, {-1, 0, 0}},
                         {Kind::Feed, {-5, -5, 0}}});
}

TEST(CutterComp, SquareWithG41InsideIsIntersectedAtEveryCorner) {
  Blocks b;
  ASSERT_FALSE(b.run("G0 X5 Y5\nG41.1 D2\nG1 Y0\nX10\nY10\nX0\nY0\nX5\nG40\nG1 Y5"));
  expect_ops(b.out.ops, {{Kind::Traverse, {5, 5, 0}},
                         {Kind::Feed, {6, 1, 0}},
                         {Kind::Feed, {9, 1, 0}},
                         {Kind::Feed, {9, 9, 0}},
                         {Kind::Feed, {1, 9, 0}},
                         {Kind::Feed, {1, 1, 0}},
                         {Kind::Feed, {5, 1, 0}},
                         {Kind::Feed, {5, 5, 0}}});
}

TEST(CutterComp, RapidAroundConvexCornerIsStraightTraverse) {
  Blocks b;
  ASSERT_FALSE(b.run("G0 X-5 Y0\nG42.1 D2\nX0\nX10\nY10\nG40"));
  expect_ops(b.out.ops, {{Kind::Traverse, {-5, 0, 0}},
                         {Kind::Traverse, {0, -1, 0}},
                         {Kind::Traverse, {10, -1, 0}},
                         {Kind::Traverse, {11, 0, 0}},
                         {Kind::Traverse, {11, 10, 0}}});
}

TEST(CutterComp, MoveWithoutMotionInThePlaneFollowsTheCornerOfTheMoveBefore) {
  Blocks b;
  ASSERT_FALSE(b.run("G0 X-5 Y0\nG41.1 D2\nG1 X0\nX10\nZ-1\nY10\nG40"));
  expect_ops(b.out.ops, {{Kind::Traverse, {-5, 0, 0}},
                         {Kind::Feed, {0, 1, 0}},
                         {Kind::Feed, {9, 1, 0}},
                         {Kind::Feed, {9, 1, -1}},
                         {Kind::Feed, {9, 10, -1}}});
}

TEST(CutterComp, ArcIsOffsetByChangingItsRadius) {
  Blocks outside;  // right of a counter-clockwise arc
  ASSERT_FALSE(outside.run("G0 X10 Y-5\nG42.1 D2\nG1 Y0\nG3 X-10 Y0 I-10 J0\nG40"));
  expect_ops(outside.out.ops, {{Kind::Traverse, {10, -5, 0}},
                               {Kind::Feed, {11, 0, 0}},
                               {Kind::Arc, {-11, 0, 0}, {0, 0, 0}, 1}});
  Blocks inside;
  ASSERT_FALSE(inside.run("G0 X10 Y-5\nG41.1 D2\nG1 Y0\nG3 X-10 Y0 I-10 J0\nG40"));
  expect_ops(inside.out.ops, {{Kind::Traverse, {10, -5, 0}},
                              {Kind::Feed, {9, 0, 0}},
                              {Kind::Arc, {-9, 0, 0}, {0, 0, 0}, 1}});
}

TEST(CutterComp, EntryArcStartsAtTheToolAndEndsARadiusFromItsEnd) {
  // Tool inside: the end moves a radius toward the centre, (9, 0); the arc's
  // centre is on the line to the programmed centre, as far from both ends.
  Blocks b;
  ASSERT_FALSE(b.run("G0 X0 Y0\nG41.1 D2\nG3 X10 Y0 I5 J0\nG40"));
  expect_ops(b.out.ops, {{Kind::Traverse, {0, 0, 0}}, {Kind::Arc, {9, 0, 0}, {4.5, 0, 0}, 1}});
}

TEST(CutterComp, StraightToArcConcaveCornerEndsOnTheOffsetCircle) {
  // y = -1 meets the circle of radius 6 about (5, 0) at x = 5 - √35.
  Blocks b;
  ASSERT_FALSE(b.run("G0 X-10 Y0\nG42.1 D2\nG1 X0\nG3 X10 Y0 I5 J0\nG40"));
  expect_ops(b.out.ops, {{Kind::Traverse, {-10, 0, 0}},
                         {Kind::Feed, {5 - std::sqrt(35.0), -1, 0}},
                         {Kind::Arc, {11, 0, 0}, {5, 0, 0}, 1}});
}

TEST(CutterComp, ArcToStraightConcaveCornerEndsTheArcOnTheOffsetLine) {
  Blocks b;
  ASSERT_FALSE(b.run("G0 X0 Y-10\nG41.1 D2\nG1 Y0\nG2 X10 Y0 I5 J0\nG1 X20\nG40"));
  expect_ops(b.out.ops, {{Kind::Traverse, {0, -10, 0}},
                         {Kind::Feed, {-1, 0, 0}},
                         {Kind::Arc, {5 + std::sqrt(35.0), 1, 0}, {5, 0, 0}, -1},
                         {Kind::Feed, {20, 1, 0}}});
}

TEST(CutterComp, ArcToArcConcaveCornerEndsWhereTheOffsetCirclesMeet) {
  // The valley of an "m": circles of radius 6 about (5, 0) and (15, 0).
  Blocks b;
  ASSERT_FALSE(b.run("G0 X0 Y-10\nG41.1 D2\nG1 Y0\nG2 X10 Y0 I5 J0\nG2 X20 Y0 I5 J0\nG40"));
  expect_ops(b.out.ops, {{Kind::Traverse, {0, -10, 0}},
                         {Kind::Feed, {-1, 0, 0}},
                         {Kind::Arc, {10, std::sqrt(11.0), 0}, {5, 0, 0}, -1},
                         {Kind::Arc, {21, 0, 0}, {15, 0, 0}, -1}});
}

TEST(CutterComp, ConvexCornerBetweenArcsGetsArcAboutTheProgrammedCorner) {
  // Right of two clockwise half circles: the tool is inside both.
  Blocks b;
  ASSERT_FALSE(b.run("G0 X0 Y-10\nG42.1 D2\nG1 Y0\nG2 X10 Y0 I5 J0\nG2 X20 Y0 I5 J0\nG40"));
  expect_ops(b.out.ops, {{Kind::Traverse, {0, -10, 0}},
                         {Kind::Feed, {1, 0, 0}},
                         {Kind::Arc, {9, 0, 0}, {5, 0, 0}, -1},
                         {Kind::Arc, {11, 0, 0}, {10, 0, 0}, 1},
                         {Kind::Arc, {19, 0, 0}, {15, 0, 0}, -1}});
}

TEST(CutterComp, TurningBackOffTheTopOfAnArcKeepsTheToolAboveIt) {
  // LinuxCNC's "h" shape: right of a counter-clockwise half circle, then
  // straight back up. Not a loop below the corner: the arc ends where
  // x = -4 meets its offset circle of radius 6.
  Blocks b;
  ASSERT_FALSE(b.run("G0 X5 Y-10\nG42.1 D2\nG1 Y0\nG3 X-5 Y0 I-5 J0\nG1 Y10\nG40"));
  expect_ops(b.out.ops, {{Kind::Traverse, {5, -10, 0}},
                         {Kind::Feed, {6, 0, 0}},
                         {Kind::Arc, {-4, std::sqrt(20.0), 0}, {0, 0, 0}, 1},
                         {Kind::Feed, {-4, 10, 0}}});
}

TEST(CutterComp, StopReleasesTheHeldMoveAndTheExitMoveIsPlain) {
  Blocks b;
  ASSERT_FALSE(b.run("G0 X0 Y0\nG41.1 D2\nG1 X10\nG40\nG1 X20 Y5"));
  EXPECT_FALSE(b.comp.active());
  expect_ops(b.out.ops,
             {{Kind::Traverse, {0, 0, 0}}, {Kind::Feed, {10, 1, 0}}, {Kind::Feed, {20, 5, 0}}});
}

TEST(CutterComp, FlushReleasesTheHeldMoveAndCompensationStaysOn) {
  Blocks b;
  ASSERT_FALSE(b.run("G0 X-5 Y0\nG41.1 D2\nG1 X0\nX10\nM0"));
  EXPECT_TRUE(b.comp.active());
  EXPECT_FALSE(b.comp.holding());
  ASSERT_FALSE(b.run("Y10\nG40"));
  // After M0 nothing is held, so the concave corner is not trimmed.
  expect_ops(b.out.ops, {{Kind::Traverse, {-5, 0, 0}},
                         {Kind::Feed, {0, 1, 0}},
                         {Kind::Feed, {10, 1, 0}},
                         {Kind::Feed, {9, 10, 0}}});
}

TEST(CutterComp, DeferredWorkComesOutAfterTheHeldMove) {
  Blocks b;
  ASSERT_FALSE(b.run("G0 X0 Y0\nF50\nG41.1 D2\nG1 X10\nF100\nG4 P1.5\nX20\nG40"));
  expect_ops(b.out.ops, {{Kind::Traverse, {0, 0, 0}},
                         {Kind::Feed, {10, 1, 0}, {}, 0, 50},
                         {Kind::Dwell, {}, {}, 0, 1.5},
                         {Kind::Feed, {20, 1, 0}, {}, 0, 100}});
}

TEST(CutterComp, DeferredWorkRunsAtOnceWhenNothingIsHeld) {
  Blocks b;
  ASSERT_FALSE(b.run("F50\nG4 P2"));
  EXPECT_EQ(b.out.rate, 50);
  expect_ops(b.out.ops, {{Kind::Dwell, {}, {}, 0, 2}});
}

TEST(CutterComp, NegativeRadiusSwapsTheSide) {
  Blocks b;
  ASSERT_FALSE(b.run("G0 X0 Y0\nG41.1 D-2\nG1 X10\nG40"));
  expect_ops(b.out.ops, {{Kind::Traverse, {0, 0, 0}}, {Kind::Feed, {10, -1, 0}}});
}

TEST(CutterComp, ZeroRadiusPassesMovesThrough) {
  Blocks b;
  ASSERT_FALSE(b.run("G0 X0 Y0\nG41.1 D0\nG1 X10\nG3 X20 Y0 I5"));
  EXPECT_TRUE(b.comp.active());
  EXPECT_FALSE(b.comp.holding());
  EXPECT_FALSE(b.comp.programmed_position());
  expect_ops(b.out.ops, {{Kind::Traverse, {0, 0, 0}},
                         {Kind::Feed, {10, 0, 0}},
                         {Kind::Arc, {20, 0, 0}, {15, 0, 0}, 1}});
}

TEST(CutterComp, ProgrammedPositionIsKeptApartFromTheTool) {
  Blocks b;
  ASSERT_FALSE(b.run("G0 X0 Y0 Z3\nG41.1 D2"));
  EXPECT_FALSE(b.comp.programmed_position());
  ASSERT_FALSE(b.run("G1 X10"));
  ASSERT_TRUE(b.comp.programmed_position());
  EXPECT_EQ(*b.comp.programmed_position(), (Vec3{10, 0, 3}));
}

TEST(CutterComp, G18CompensatesInTheZXPlane) {
  // Along +Z the left side is +X (Z is the plane's first axis, X its second).
  Blocks b;
  ASSERT_FALSE(b.run("G18\nG0 X0 Z0\nG41.1 D2\nG1 Z10\nG40"));
  expect_ops(b.out.ops, {{Kind::Traverse, {0, 0, 0}}, {Kind::Feed, {1, 0, 10}}});
}

TEST(CutterComp, LatheToolOrientationMovesTheEmittedPointToTheToolOrigin) {
  // LinuxCNC tests/ccomp/lathe-comp/test.ngc, T2 (D0.1 in, orientation 2)
  // and its expected canon calls.
  Blocks b(kInch);
  b.tool_diameter = 0.1;
  b.orientation = 2;
  ASSERT_FALSE(b.run("G18\nG0 X.3 Z0\nG41\nG1 X.1\nG3 X0 Z.1 R.1\nG1 Z1\nG40\nG0 X.3"));
  const double i = kInch;
  expect_ops(b.out.ops, {{Kind::Traverse, {.3 * i, 0, 0}},
                         {Kind::Feed, {.05 * i, 0, 0}},
                         {Kind::Arc, {0, 0, .05 * i}, {.05 * i, 0, .05 * i}, 1},
                         {Kind::Feed, {0, 0, .95 * i}},
                         {Kind::Traverse, {.3 * i, 0, 1 * i}}});
}

TEST(CutterComp, EntryMoveOfExactlyTheRadiusIsAllowed) {
  // nc_files/useful-subroutines.ngc o100: a 1/8" tool enters a 1/8" hole by
  // exactly its radius; LinuxCNC's reference trace shows no error.
  Blocks b(kInch);
  b.tool_diameter = 0.125;
  ASSERT_FALSE(b.run("G0 X.0625 Y.0625\nG41 G0 X0 Y.0625\nG3 X0 Y.0625 I0 J-.0625\nG40"));
  expect_ops(b.out.ops, {{Kind::Traverse, {.0625 * kInch, .0625 * kInch, 0}},
                         {Kind::Traverse, {0, 0, 0}},
                         {Kind::Arc, {0, 0, 0}, {0, 0, 0}, 1}});
}

// --- Errors ---

TEST(CutterComp, StartWhileOnIsAnError) {
  Blocks b;
  const auto e = b.run("G41.1 D2\nG42.1 D2");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code, Code::CompNotAllowed);
  EXPECT_EQ(b.error_line, 2U);
}

TEST(CutterComp, StartOutsideTheXYAndZXPlanesIsAnError) {
  CutterComp comp;
  const auto e = failure_of(comp.start(CompSide::Left, 1.0, Plane::YZ));
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code, Code::CompNotAllowed);
  EXPECT_FALSE(comp.active());
  const auto lathe = failure_of(comp.start(CompSide::Left, 1.0, Plane::XY, 3));
  ASSERT_TRUE(lathe);
  EXPECT_EQ(lathe->code, Code::CompNotAllowed);
}

TEST(CutterComp, EntryMoveNotLongerThanTheRadiusIsAnError) {
  Blocks b;
  const auto e = b.run("G0 X0 Y0\nG41.1 D2\nG1 X0.5");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code, Code::CompEntryMove);
  EXPECT_NE(e->message.find("0.5"), std::string::npos);
  EXPECT_EQ(b.error_line, 3U);
}

TEST(CutterComp, EntryArcNotLongerThanTheRadiusIsAnError) {
  Blocks b;
  const auto e = b.run("G0 X0 Y0\nG41.1 D2\nG2 X0.5 I0.25");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code, Code::CompEntryMove);
}

TEST(CutterComp, ToolInsideAnArcNotLargerThanItIsAnError) {
  Blocks entry;
  const auto e1 = entry.run("G0 X0 Y0\nG41.1 D4\nG3 X3 Y0 I1.5");
  ASSERT_TRUE(e1);
  EXPECT_EQ(e1->code, Code::CompToolTooBig);
  Blocks later;
  const auto e2 = later.run("G0 X0 Y-10\nG41.1 D4\nG1 Y0\nG3 X3 Y0 I1.5");
  ASSERT_TRUE(e2);
  EXPECT_EQ(e2->code, Code::CompToolTooBig);
  EXPECT_EQ(later.error_line, 4U);
}

TEST(CutterComp, ArcJustAfterStopIsAnError) {
  // LinuxCNC tests/interp/bad/ccomp-arcexit.ngc.
  Blocks b;
  const auto e = b.run("G0 X0 Y0 Z0\nG41.1 D.25\nG1 X1 F1\nG1 X2\nG40\nG2 I1");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code, Code::CompNotAllowed);
  EXPECT_FALSE(b.comp.arc_allowed());
  ASSERT_FALSE(b.run("G1 X3\nG2 X5 I1"));
  EXPECT_TRUE(b.comp.arc_allowed());
}

TEST(CutterComp, ConcaveCornerAfterTooShortAMoveIsGouging) {
  // LinuxCNC tests/interp/bad/ccomp-gouging.ngc: the 0.1 mm move cannot hold
  // a 0.25 mm tool turning back. The failed block changes nothing.
  Blocks b;
  const auto e = b.run("G0 X0 Y0 Z0\nG41.1 D.25\nG1 X1 F1\nG1 X2\nG1 Y.1\nG1 X1");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code, Code::CutterGouge);
  EXPECT_EQ(b.error_line, 6U);
  EXPECT_EQ(b.out.ops.size(), 3U);
  EXPECT_TRUE(b.comp.holding());
  ASSERT_TRUE(b.comp.programmed_position());
  EXPECT_EQ(*b.comp.programmed_position(), (Vec3{2, 0.1, 0}));
}

TEST(CutterComp, ConcaveCornerBackPastTheStartOfAnArcIsGouging) {
  Blocks b;
  const auto e = b.run("G0 X0 Y-10\nG41.1 D2\nG1 Y0\nG2 X0.1339746 Y0.5 I1 J0\nG1 X-5");
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code, Code::CutterGouge);
  EXPECT_EQ(b.error_line, 5U);
}

TEST(CutterComp, ConcaveCornersWhoseOffsetPathsDoNotMeetAreGouging) {
  Blocks arcs;  // the 0.1 mm offset of the small arc misses the large one
  const auto e1 = arcs.run("G0 X0 Y-10\nG41.1 D1.8\nG1 Y0\nG2 X10 Y0 I5\nG3 X11 Y1 J1");
  ASSERT_TRUE(e1);
  EXPECT_EQ(e1->code, Code::CutterGouge);
  Blocks line;
  const auto e2 = line.run("G0 X-10 Y0\nG41.1 D2.6\nG1 X0\nG3 X-2 Y2 I-1 J1");
  ASSERT_TRUE(e2);
  EXPECT_EQ(e2->code, Code::CutterGouge);
}

// --- LinuxCNC's reference traces (shared/conformance/rs274ngc/expected): the
// programs' blocks as written, inches; tool diameters from tools/*.tbl. ---

TEST(CutterComp, MatchesLinuxCncCompG1StraightEntryAndConvexCorners) {
  // nc_files/comp-g1.ngc lines 25-36 (T4: D0.005), trace ops 11-23.
  Blocks b(kInch);
  b.out.at = {50.8, 76.2, 25.4};
  b.tool_diameter = 0.005;
  ASSERT_FALSE(b.run(R"(G0 X0 Y3.5
G1 Z0
G41
G1 X2 Y3
G2 X3 Y2 J-1
G1 Y-1
G2 X2 Y-2 I-1
G1 X-3
G1 X1.4 Y2.8
G2 X2 Y3 i.6 J-.8
G40
G1 X3 Y3.5)"));
  expect_ops(b.out.ops,
             {
                 {Kind::Traverse, {0, 88.9, 25.4}},
                 {Kind::Feed, {0, 88.9, 0}},
                 {Kind::Feed, {50.80762, 76.2635, 0}},
                 {Kind::Arc, {76.2635, 50.8, 0}, {50.8, 50.8, 0}, -1},
                 {Kind::Feed, {76.2635, -25.4, 0}},
                 {Kind::Arc, {50.8, -50.8635, 0}, {50.8, -25.4, 0}, -1},
                 {Kind::Feed, {-76.2, -50.8635, 0}},
                 {Kind::Arc, {-76.24572, -50.75682, 0}, {-76.2, -50.8, 0}, -1},
                 {Kind::Feed, {35.51428, 71.16318, 0}},
                 {Kind::Arc, {35.5219, 71.1708, 0}, {35.56, 71.12, 0}, -1},
                 {Kind::Arc, {50.8, 76.2635, 0}, {50.8, 50.8, 0}, -1},
                 {Kind::Feed, {76.2, 88.9, 0}},
             },
             kTraceTolerance);
}

TEST(CutterComp, MatchesLinuxCncCompInTheZXPlane) {
  // nc_files/comp.ngc lines 39-57 (G18, D1: D0.125), trace ops 31-45.
  Blocks b(kInch);
  b.tool_diameter = 0.125;
  ASSERT_FALSE(b.run(R"(G18
g0x-.2z-.2y0
g42 d1
g1x0z0
g1z1
g2r.25x-.25z1.25
g1x-.5
g3r.25x-.75z1.5
g1z1.75
g40
g0x.2z-.2y0
g41 d1
g1x0z0
g1z1
g2r.25x-.25z1.25
g1x-.5
g3r.25x-.75z1.5
g1z1.75
g40
g0x.2z-.2y0)"));
  expect_ops(b.out.ops,
             {
                 {Kind::Traverse, {-5.08, 0, -5.08}},
                 {Kind::Feed, {-1.5875, 0, 0.65786}},
                 {Kind::Feed, {-1.5875, 0, 25.4}},
                 {Kind::Arc, {-6.35, 0, 30.1625}, {-6.35, 0, 25.4}, -1},
                 {Kind::Feed, {-12.7, 0, 30.1625}},
                 {Kind::Arc, {-20.6375, 0, 38.1}, {-12.7, 0, 38.1}, 1},
                 {Kind::Feed, {-20.6375, 0, 44.45}},
                 {Kind::Traverse, {5.08, 0, -5.08}},
                 {Kind::Feed, {1.5875, 0, 0.65786}},
                 {Kind::Feed, {1.5875, 0, 25.4}},
                 {Kind::Arc, {-6.35, 0, 33.3375}, {-6.35, 0, 25.4}, -1},
                 {Kind::Feed, {-12.7, 0, 33.3375}},
                 {Kind::Arc, {-17.4625, 0, 38.1}, {-12.7, 0, 38.1}, 1},
                 {Kind::Feed, {-17.4625, 0, 44.45}},
                 {Kind::Traverse, {5.08, 0, -5.08}},
             },
             kTraceTolerance);
}

TEST(CutterComp, MatchesLinuxCncComp311ArcToArcCorners) {
  // nc_files/comp311.ngc lines 24-35 (T4: D0.005), trace ops 14-24.
  Blocks b(kInch);
  b.out.at = {50.8, 76.2, 25.4};
  b.tool_diameter = 0.005;
  ASSERT_FALSE(b.run(R"(g0 x1 y5
g1 z0
g41 g1 y4
g3 x2 y3 i1
g2 x3 y2 j-1
g1 y-1
g2 x2 y-2 i-1
g1 x-2
g2 x-2.6 y-0.2 j1
g1 x1.4 y2.8
g2 x2 y3 i.6 j-.8
g40)"));
  expect_ops(b.out.ops,
             {
                 {Kind::Traverse, {25.4, 127, 25.4}},
                 {Kind::Feed, {25.4, 127, 0}},
                 {Kind::Feed, {25.4635, 101.6, 0}},
                 {Kind::Arc, {50.8, 76.2635, 0}, {50.8, 101.6, 0}, 1},
                 {Kind::Arc, {76.2635, 50.8, 0}, {50.8, 50.8, 0}, -1},
                 {Kind::Feed, {76.2635, -25.4, 0}},
                 {Kind::Arc, {50.8, -50.8635, 0}, {50.8, -25.4, 0}, -1},
                 {Kind::Feed, {-50.8, -50.8635, 0}},
                 {Kind::Arc, {-66.0781, -5.0292, 0}, {-50.8, -25.4, 0}, -1},
                 {Kind::Feed, {35.5219, 71.1708, 0}},
                 {Kind::Arc, {50.8, 76.2635, 0}, {50.8, 50.8, 0}, -1},
             },
             kTraceTolerance);
}

TEST(CutterComp, MatchesLinuxCncGmoccapyHelicalArcEntryAndDeferredFeed) {
  // nc_files/gmoccapy_2_tools_with_cutter_radius_compensation.ngc lines
  // 31-52 (mm, T3: D0.201 in), trace ops 3-8: the entry arc keeps F250
  // although F2000 comes before it is released.
  Blocks b;
  b.out.at = {50, 50, 30};
  b.tool_diameter = 0.201 * kInch;
  ASSERT_FALSE(b.run(R"(G0 Z10
F250
G1 Z0
G41
G3 X70 Y50 Z-1 I10 J0
F2000
G3 I -20
G3 X50 Y50 Z1 I-10 J0
G0 Z30
M9
G40)"));
  expect_ops(b.out.ops,
             {
                 {Kind::Traverse, {50, 50, 10}},
                 {Kind::Feed, {50, 50, 0}, {}, 0, 250},
                 {Kind::Arc, {67.4473, 50, -1}, {58.7237, 50, 0}, 1, 250},
                 {Kind::Arc, {67.4473, 50, -1}, {50, 50, -1}, 1, 2000},
                 {Kind::Arc, {52.5527, 50, 1}, {60, 50, -1}, 1, 2000},
                 {Kind::Traverse, {52.5527, 50, 30}},
             },
             kTraceTolerance);
}

TEST(CutterComp, MatchesLinuxCncInverseTimeFeedsStayWithTheirMoves) {
  // tests/interp/inverse-time-with-comp/inverse.ngc o100 with #100=.4
  // (G42.1 D0.4), trace ops 12-26. Its G93 F words are written here as the
  // per-minute feeds LinuxCNC makes of them (programmed length / time).
  Blocks b(kInch);
  ASSERT_FALSE(b.run(R"(g0x0y0z0
g42.1d0.4
g1x1f30
y1f20
x-1f40
y2f40
x1f33
y3
x0
y4
g3y5j.5f10
g40g1y6f25)"));
  expect_ops(b.out.ops,
             {
                 {Kind::Traverse, {0, 0, 0}},
                 {Kind::Feed, {25.4, -5.08, 0}, {}, 0, 762},
                 {Kind::Arc, {30.48, 0, 0}, {25.4, 0, 0}, 1, 508},
                 {Kind::Feed, {30.48, 25.4, 0}, {}, 0, 508},
                 {Kind::Arc, {25.4, 30.48, 0}, {25.4, 25.4, 0}, 1, 1016},
                 {Kind::Feed, {-20.32, 30.48, 0}, {}, 0, 1016},
                 {Kind::Feed, {-20.32, 45.72, 0}, {}, 0, 1016},
                 {Kind::Feed, {25.4, 45.72, 0}, {}, 0, 838.2},
                 {Kind::Arc, {30.48, 50.8, 0}, {25.4, 50.8, 0}, 1, 838.2},
                 {Kind::Feed, {30.48, 76.2, 0}, {}, 0, 838.2},
                 {Kind::Arc, {25.4, 81.28, 0}, {25.4, 76.2, 0}, 1, 838.2},
                 {Kind::Feed, {5.08, 81.28, 0}, {}, 0, 838.2},
                 {Kind::Feed, {5.08, 97.26168, 0}, {}, 0, 838.2},
                 {Kind::Arc, {0, 132.08, 0}, {0, 114.3, 0}, 1, 254},
                 {Kind::Feed, {0, 152.4, 0}, {}, 0, 635},
             },
             kTraceTolerance);
}

TEST(CutterComp, MatchesLinuxCncCrazyPathsArcCorners) {
  // tests/interp/crazy-paths/test.ngc o2 (lines 22-32), mm, called with
  // -.5 (right, radius 0.25) and .5 (left): trace ops 33-50.
  const char* sub = R"(G0 X-100.000000 Y-50.000000
G41.1 D%
g90 g1 y-52.000000
G3 I2.240368 J-4.469983 X-95.923035 Y-61.120458
G1 X-97.923035 Y-57.120458
G2 I1.316612 J1.762536 X-94.440783 Y-55.745223
G3 I1.795380 J2.403458 X-95.540324 Y-52.554728
G40
G1 X-93.540324 Y-62.554728
)";
  std::string program;
  for (const char* d : {"-.5", ".5"}) {
    std::string s = sub;
    s.replace(s.find('%'), 1, d);
    program += s;
  }
  Blocks b;
  ASSERT_FALSE(b.run(program));
  expect_ops(b.out.ops,
             {
                 {Kind::Traverse, {-100, -50, 0}},
                 {Kind::Feed, {-100.25, -51.8482, 0}},
                 {Kind::Arc, {-95.8312, -61.353, 0}, {-97.7596, -56.47, 0}, 1},
                 {Kind::Arc, {-95.6994, -61.0087, 0}, {-95.923, -61.1205, 0}, 1},
                 {Kind::Feed, {-97.6994, -57.0087, 0}},
                 {Kind::Arc, {-97.7734, -56.9202, 0}, {-97.923, -57.1205, 0}, 1},
                 {Kind::Arc, {-94.6869, -55.7012, 0}, {-96.6064, -55.3579, 0}, -1},
                 {Kind::Arc, {-94.5904, -55.9455, 0}, {-94.4408, -55.7452, 0}, 1},
                 {Kind::Arc, {-95.7816, -52.4891, 0}, {-92.6454, -53.3418, 0}, 1},
                 {Kind::Feed, {-93.5403, -62.5547, 0}},
                 {Kind::Traverse, {-100, -50, 0}},
                 {Kind::Feed, {-99.75, -52, 0}},
                 {Kind::Arc, {-99.888, -52.2235, 0}, {-100, -52, 0}, -1},
                 {Kind::Arc, {-96.2722, -60.9811, 0}, {-97.7596, -56.47, 0}, 1},
                 {Kind::Feed, {-98.1209, -57.2838, 0}},
                 {Kind::Arc, {-94.1715, -55.6294, 0}, {-96.6064, -55.3579, 0}, -1},
                 {Kind::Arc, {-95.2991, -52.6203, 0}, {-92.6454, -53.3418, 0}, 1},
                 {Kind::Feed, {-93.5403, -62.5547, 0}},
             },
             kTraceTolerance);
}

TEST(CutterComp, MatchesLinuxCncInsideCorners) {
  // tests/interp/inside-corners/test.ngc o100 lines 10-31 with #100=.15
  // (G41.1 D0.15): concave corners between arcs of every kind. The last move
  // is still held; what has come out is trace ops 102-128.
  Blocks b(kInch);
  b.out.at = {25.4, 0, 25.4};
  ASSERT_FALSE(b.run(R"(G00 Z0.0200
G00 X0.0000 Y0.0000
G01 Z-0.1000
G41.1 D0.15
G01 X0.6767 Y0.2334
G01 X0.3359 Y0.4419
G03 X1.2281 Y1.3456 I0.2921 J0.6039
G02 X0.1253 Y0.9881 I-0.6093 J0.0000
G03 X0.7669 Y1.4548 I0.2437 J0.3394
G03 X0.6867 Y1.7527 I0.1687 J0.2052
G02 X0.3459 Y1.7626 I-0.1687 J0.0629
G01 X0.0652 Y1.5342
G01 X0.0652 Y2.4577
G02 X0.6065 Y2.4577 I0.2707 J0.0000
G02 X1.4888 Y2.4577 I0.4411 J0.0000
G02 X1.8597 Y2.4577 I0.1855 J0.0000
G02 X1.3585 Y2.0307 I-0.4325 J0.0000
G03 X2.3911 Y2.1499 I0.4303 J0.8046
G01 X2.1404 Y1.3952
G03 X1.7494 Y1.6236 I-0.2261 J0.0618
G03 X2.5014 Y1.3456 I0.3111 J-0.3144
G01 X2.7720 Y1.4846)"));
  expect_ops(b.out.ops,
             {
                 {Kind::Traverse, {25.4, 0, 0.508}},
                 {Kind::Traverse, {0, 0, 0.508}},
                 {Kind::Feed, {0, 0, -2.54}},
                 {Kind::Feed, {12.74826, 6.41096, -2.54}},
                 {Kind::Feed, {7.53872, 9.59866, -2.54}},
                 {Kind::Arc, {9.36244, 12.93876, -2.54}, {8.53186, 11.22426, -2.54}, -1},
                 {Kind::Arc, {31.0769, 26.035, -2.54}, {15.9512, 26.56332, -2.54}, 1},
                 {Kind::Arc, {1.64084, 23.98014, -2.54}, {15.71752, 34.17824, -2.54}, -1},
                 {Kind::Arc, {4.2926, 26.6446, -2.54}, {3.18262, 25.09774, -2.54}, -1},
                 {Kind::Arc, {17.6657, 36.37026, -2.54}, {9.3726, 33.7185, -2.54}, 1},
                 {Kind::Arc, {20.6883, 38.42258, -2.54}, {19.47926, 36.95192, -2.54}, -1},
                 {Kind::Arc, {19.2278, 43.8531, -2.54}, {23.76424, 42.164, -2.54}, 1},
                 {Kind::Arc, {8.255, 41.88206, -2.54}, {13.1572, 46.11624, -2.54}, -1},
                 {Kind::Feed, {2.8575, 37.4904, -2.54}},
                 {Kind::Arc, {-0.24892, 38.96868, -2.54}, {1.65608, 38.96868, -2.54}, -1},
                 {Kind::Feed, {-0.24892, 62.42558, -2.54}},
                 {Kind::Arc, {14.9479, 68.41744, -2.54}, {8.53186, 62.42558, -2.54}, -1},
                 {Kind::Arc, {38.59276, 67.7418, -2.54}, {26.60904, 62.42558, -2.54}, -1},
                 {Kind::Arc, {49.14138, 62.42558, -2.54}, {42.52722, 62.42558, -2.54}, -1},
                 {Kind::Arc, {42.20464, 50.99304, -2.54}, {36.25088, 62.42558, -2.54}, -1},
                 {Kind::Arc, {59.47664, 56.03748, -2.54}, {45.43552, 72.01662, -2.54}, 1},
                 {Kind::Arc, {62.54242, 54.00802, -2.54}, {60.73394, 54.60746, -2.54}, -1},
                 {Kind::Feed, {56.17464, 34.83864, -2.54}},
                 {Kind::Arc, {52.52974, 35.941, -2.54}, {54.36616, 35.43808, -2.54}, -1},
                 {Kind::Arc, {45.77588, 39.88562, -2.54}, {48.62322, 37.0078, -2.54}, 1},
                 {Kind::Arc, {61.63818, 34.02076, -2.54}, {52.3367, 33.25368, -2.54}, 1},
                 {Kind::Arc, {62.66434, 35.87242, -2.54}, {63.53556, 34.17824, -2.54}, -1},
             },
             kTraceTolerance);
}

}  // namespace
}  // namespace usina::gcode
