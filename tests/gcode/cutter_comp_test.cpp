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
  void traverse(const Vec3& to) override { ops.push_back({Kind::Traverse, to, {}, 0, rate, line_}); }
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
      std::size_t n = 0;
      w.emplace_back(letter, std::stod(s.substr(i), &n));
      i += n;
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
      comp.defer(loc, [rate](MotionTarget& t) { static_cast<Recorder&>(t).rate = rate; }, out);
    }
    for (const auto& [letter, value] : w) {
      if (letter != 'G') continue;
      if (auto e = g_code(static_cast<int>(std::lround(value * 10)), w, loc)) return e;
    }
    if (auto e = motion(w, loc)) return e;
    const std::optional<double> m = get(w, 'M');
    if (m && (*m == 0 || *m == 1 || *m == 2)) {
      if (auto e = comp.flush(out)) return e;
      if (*m == 2) comp.reset();
    }
    return std::nullopt;
  }

  std::optional<InterpError> g_code(int g, const Words& w, const core::SourceLoc& loc) {
    if (g == 0 || g == 10 || g == 20 || g == 30) motion_ = g / 10;
    if (g == 40) {
      const double p = get(w, 'P').value_or(0.0);
      comp.defer(loc, [p](MotionTarget& t) { t.dwell(p); }, out);
    }
    if (g == 170) plane_ = Plane::XY;
    if (g == 180) plane_ = Plane::ZX;
    if (g == 400) return comp.stop(out);
    if (g == 410 || g == 420 || g == 411 || g == 421) {
      const CompSide side = g / 10 == 41 ? CompSide::Left : CompSide::Right;
      const double d = g % 10 == 1 ? get(w, 'D').value_or(0.0) : tool_diameter;
      return comp.start(side, d * unit_ / 2, plane_, g % 10 == 1 ? 0 : orientation);
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
      e = comp.straight(to, motion_ == 0, loc, out);
    } else {
      Vec3 center = from + offset;
      if (auto r = get(w, 'R')) {
        const auto c = core::arc_center_from_radius(core::in_plane(from, plane_),
                                                    core::in_plane(to, plane_), *r * unit_,
                                                    motion_ == 3);
        center = core::from_plane(*c, from[core::axes_of(plane_).axial], plane_);
      }
      e = comp.arc(to, center, motion_ == 3 ? 1 : -1, loc, out);
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
  Kind kind = Kind::Feed;
  Vec3 to;
  Vec3 center;
  int turn = 0;
  double f = -1.0;  // feed rate (a dwell's seconds); < 0: not checked
};

void expect_ops(const std::vector<Op>& got, const std::vector<Want>& want, double tol = 1e-9) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    SCOPED_TRACE("op " + std::to_string(i + 1));
    EXPECT_EQ(got[i].kind, want[i].kind);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(got[i].to[k], want[i].to[k], tol);
      if (want[i].kind == Kind::Arc) EXPECT_NEAR(got[i].center[k], want[i].center[k], tol);
    }
    if (want[i].kind == Kind::Arc) EXPECT_EQ(got[i].turn, want[i].turn);
    if (want[i].f >= 0.0) EXPECT_NEAR(got[i].f, want[i].f, 1e-6);
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

TEST(CutterComp, StopReleasesTheHeldMoveAndTheExitMoveIsPlain) {
  Blocks b;
  ASSERT_FALSE(b.run("G0 X0 Y0\nG41.1 D2\nG1 X10\nG40\nG1 X20 Y5"));
  EXPECT_FALSE(b.comp.active());
  expect_ops(b.out.ops,
             {{Kind::Traverse, {0, 0, 0}}, {Kind::Feed, {10, 1, 0}}, {Kind::Feed, {20, 5, 0}}});
}

TEST(CutterComp, FlushReleasesTheHeldMoveAndCompensationStaysOn) {
  Blocks b;
  ASSERT_FALSE(b.run("G0 X-5 Y0\nG41.1 D2\nG1 X0\nX10\nM0\nY10\nG40"));
  EXPECT_FALSE(b.comp.active());
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
                         {Kind::Traverse, {.3 * i, 0, .95 * i}}});
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
  const auto e = comp.start(CompSide::Left, 1.0, Plane::YZ);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->code, Code::CompNotAllowed);
  EXPECT_FALSE(comp.active());
  const auto lathe = comp.start(CompSide::Left, 1.0, Plane::XY, 3);
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
  ASSERT_FALSE(b.run("G1 X5 Y.1\nG40"));
  expect_ops(b.out.ops, {{Kind::Traverse, {0, 0, 0}},
                         {Kind::Feed, {1, 0.125, 0}},
                         {Kind::Feed, {1.875, 0.125, 0}},
                         {Kind::Feed, {1.875, 0.1, 0}},
                         {Kind::Arc, {2, -0.025, 0}, {2, 0.1, 0}, -1},
                         {Kind::Feed, {5, -0.025, 0}}});
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
